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
#include "laws/linear_oscillator/slip_law.hpp"

namespace frictionref::detail {

template <class Real>
class LinearOscillatorFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;

  LinearOscillatorFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : phase_(phase), model_(model) {
    if (phase.kind == PhaseKind::stick) return;
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

  BasicState<Real> at(const Real& t) const override {
    BasicState<Real> state;
    at_many(&t, 1, &state);
    return state;
  }

  void at_many(const Real* t, std::size_t n, BasicState<Real>* out) const override {
    if constexpr (std::is_same_v<Real, double>) {
      const auto slow = [this](double ti) { return long_double_at(ti); };
      if (seed_fast_) return fast_slip_rows(*seed_fast_, phase_, t, n, out, slow);
      if (oscillator_fast_) return fast_slip_rows(*oscillator_fast_, phase_, t, n, out, slow);
    }
    for (std::size_t i = 0; i < n; ++i) out[i] = long_double_at(t[i]);
  }

  // The state from the long double laws alone (what the fast path must
  // agree with; tests compare the two).
  BasicState<Real> long_double_at(const Real& t) const {
    if (phase_.kind == PhaseKind::stick) return rest_state(phase_, t);
    const LongDoubleSlip& slip = long_double_slip();
    const std::vector<LinearSlipLaw<Work>>& laws = slip.laws;
    const Work omega = slip.oscillator.omega();
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
  // A slip's long double laws: one per segment of the record it crosses
  // (one without a record), in time order; they point into the oscillator.
  struct LongDoubleSlip {
    LongDoubleSlip(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
        : oscillator(model) {
      const Work omega = oscillator.omega();
      const Work tau_end = omega * Work(phase.t_end);
      laws.emplace_back(oscillator, slip_sign(phase.kind), omega * Work(phase.t_begin),
                        omega * Work(phase.x_begin), Work(phase.v_begin));
      while (laws.back().segment_end() < tau_end) {
        LinearSlipLaw<Work> next = laws.back().continued_at(laws.back().segment_end());
        laws.push_back(std::move(next));
      }
    }
    LongDoubleSlip(const LongDoubleSlip&) = delete;
    LongDoubleSlip& operator=(const LongDoubleSlip&) = delete;
    Oscillator<Work> oscillator;
    std::vector<LinearSlipLaw<Work>> laws;
  };

  // Built on first need: with a fast path most slips never need it (the
  // oscillator's forcing, responses and transition functions cost more
  // than a phase's rows on the fast path). Once only, also when formulas
  // are shared between threads.
  const LongDoubleSlip& long_double_slip() const {
    std::call_once(long_double_built_,
                   [this] { long_double_ = std::make_unique<LongDoubleSlip>(model_, phase_); });
    return *long_double_;
  }

  BasicPhase<Real> phase_;
  BasicModel<Real> model_;  // for the long double laws
  mutable std::once_flag long_double_built_;
  mutable std::unique_ptr<const LongDoubleSlip> long_double_;
  // For double, where the CPU allows: the seed's law, or the oscillator's.
  std::optional<DoubleDoubleSlip> seed_fast_;
  std::optional<DoubleDoubleOscillator> oscillator_fast_;
};

}  // namespace frictionref::detail
