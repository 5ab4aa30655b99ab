// Dense output of the general model: the state inside an emitted phase from
// its slip law (or the rest position of a stick). With a ground record the
// slip is carried from the phase's start to each segment of the record it
// crosses, as the engine carried it (family.hpp), and evaluated by that
// segment's law. For double, without a record, a slip's rows take a fast
// path first (fast_slip_rows.hpp, docs/theory.md 10), the long double law
// where it cannot decide: the seed's (a constant force F0 - s R added) for a
// model without spring, damper or harmonics; double_double_oscillator.hpp's
// (theory.md 10.6) for the others (up to eight harmonics, not critically
// damped).
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/fast_slip_rows.hpp"
#include "laws/harmonic_coulomb/double_double_slip.hpp"
#include "laws/linear_oscillator/double_double_oscillator.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/shared_oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"

namespace frictionref::detail {

template <class Real>
class LinearOscillatorFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;

  LinearOscillatorFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : LinearOscillatorFormula(std::make_shared<const SharedOscillator<Real>>(model), phase) {}

  LinearOscillatorFormula(std::shared_ptr<const SharedOscillator<Real>> shared,
                          const BasicPhase<Real>& phase)
      : phase_(phase), shared_(std::move(shared)) {
    if (phase.kind == PhaseKind::stick) return;
    const BasicModel<Real>& model = shared_->model();
    if constexpr (std::is_same_v<Real, double>) {
      if (model.ground_motion || !double_double_lanes_available()) return;
      const int sign = slip_sign(phase.kind);
      if (model.stiffness == 0 && model.damping == 0 && model.harmonics.empty()) {
        seed_fast_.emplace(SeedSlipStart{model.omega, model.amplitude, model.mass, model.friction,
                                         sign, phase.t_begin, phase.x_begin, phase.v_begin,
                                         model.force_offset});
        if (!seed_fast_->usable()) seed_fast_.reset();
      } else if (model.harmonics.size() <= OscillatorSlipStart::kMaxHarmonics) {
        OscillatorSlipStart start{};
        start.omega = model.omega;
        start.amplitude = model.amplitude;
        start.mass = model.mass;
        start.friction = model.friction;
        start.stiffness = model.stiffness;
        start.damping = model.damping;
        start.force_offset = model.force_offset;
        start.harmonics = static_cast<int>(model.harmonics.size());
        for (std::size_t j = 0; j < model.harmonics.size(); ++j) {
          start.harmonic_amplitude[j] = model.harmonics[j].amplitude;
          start.harmonic_omega[j] = model.harmonics[j].omega;
          start.harmonic_phase[j] = model.harmonics[j].phase;
        }
        start.sign = sign;
        start.t_begin = phase.t_begin;
        start.x_begin = phase.x_begin;
        start.v_begin = phase.v_begin;
        oscillator_fast_.emplace(start);
        if (!oscillator_fast_->usable()) oscillator_fast_.reset();
      }
    }
  }

  std::unique_ptr<const PhaseFormula<Real>> for_phase(
      const BasicPhase<Real>& phase) const override {
    return std::make_unique<LinearOscillatorFormula>(shared_, phase);
  }

  BasicState<Real> at(const Real& t) const override {
    BasicState<Real> state{t, 0, 0, 0, phase_.kind};
    columns(&t, 1, &state.x, &state.v, &state.a);
    return state;
  }

  void at_many(const Real* t, std::size_t n, BasicState<Real>* out) const override {
    states_from_columns(*this, phase_.kind, t, n, out);
  }

  void columns(const Real* t, std::size_t n, Real* x, Real* v, Real* a) const override {
    if constexpr (std::is_same_v<Real, double>) {
      const auto slow = [this](double ti) { return long_double_at(ti); };
      if (seed_fast_) return fast_slip_rows(*seed_fast_, phase_, t, n, x, v, a, slow);
      if (oscillator_fast_) return fast_slip_rows(*oscillator_fast_, phase_, t, n, x, v, a, slow);
    }
    columns_of_states([this](const Real& time) { return long_double_at(time); }, t, n, x, v, a);
  }

  // The state from the long double laws alone (what the fast path must
  // agree with; tests compare the two).
  BasicState<Real> long_double_at(const Real& t) const {
    if (phase_.kind == PhaseKind::stick) return rest_state(phase_, t);
    const std::vector<LinearSlipLaw<Work>>& laws = slip_laws();
    const Work omega = shared_->oscillator().omega();
    const Work tau = omega * Work(t);
    // The last law starting at or before tau (the first before its start).
    const auto after = std::upper_bound(
        laws.begin(), laws.end(), tau,
        [](const Work& value, const LinearSlipLaw<Work>& law) { return value < law.tau_begin(); });
    const std::size_t j =
        after == laws.begin() ? 0 : static_cast<std::size_t>(after - laws.begin()) - 1;
    const auto q = laws[j].point(tau, false);
    return slip_state(phase_, t, Real(q.y / omega), Real(q.v), Real(laws[j].acceleration(q)));
  }

  // The fast path's answer alone, where it decides (tests).
  bool fast_at(const Real& t, BasicState<Real>& state) const {
    if constexpr (std::is_same_v<Real, double>) {
      if (seed_fast_) return fast_slip_row(*seed_fast_, phase_, t, state);
      return oscillator_fast_ && fast_slip_row(*oscillator_fast_, phase_, t, state);
    } else {
      (void)t;
      (void)state;
      return false;
    }
  }

 private:
  // The slip's long double laws, one per segment of the record it crosses
  // (one without a record), in time order, built on first need (once, also
  // when formulas are used from several threads); they point into the
  // shared oscillator.
  const std::vector<LinearSlipLaw<Work>>& slip_laws() const {
    std::call_once(laws_built_, [this] {
      const Oscillator<Work>& oscillator = shared_->oscillator();
      const Work omega = oscillator.omega();
      const Work tau_end = omega * Work(phase_.t_end);
      laws_.emplace_back(oscillator, slip_sign(phase_.kind), omega * Work(phase_.t_begin),
                         omega * Work(phase_.x_begin), Work(phase_.v_begin));
      while (laws_.back().segment_end() < tau_end) {
        LinearSlipLaw<Work> next = laws_.back().continued_at(laws_.back().segment_end());
        laws_.push_back(std::move(next));
      }
    });
    return laws_;
  }

  BasicPhase<Real> phase_;
  std::shared_ptr<const SharedOscillator<Real>> shared_;  // the model and its oscillator
  mutable std::once_flag laws_built_;
  mutable std::vector<LinearSlipLaw<Work>> laws_;
  // For double, where the CPU allows: the seed's law, or the oscillator's.
  std::optional<DoubleDoubleSlip> seed_fast_;
  std::optional<DoubleDoubleOscillator> oscillator_fast_;
};

}  // namespace frictionref::detail
