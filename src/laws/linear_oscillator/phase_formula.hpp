// Dense output of the general model: the state inside an emitted phase from
// its slip law (or the rest position of a stick). With a ground record the
// slip is carried from the phase's start to each segment of the record it
// crosses, as the engine carried it (family.hpp), and evaluated by that
// segment's law. A model without spring, damper, harmonics or record (static
// friction above R, a force offset) slips by the seed's law with a constant
// force: for double its rows take the seed's fast path first
// (fast_slip_rows.hpp, docs/theory.md 10), the long double law where it
// cannot decide.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/harmonic_coulomb/double_double_slip.hpp"
#include "laws/harmonic_coulomb/fast_slip_rows.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"

namespace frictionref::detail {

template <class Real>
class LinearOscillatorFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;

  LinearOscillatorFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : phase_(phase), oscillator_(model) {
    if (phase.kind == PhaseKind::stick) return;
    const Work omega = oscillator_.omega();
    const Work tau_end = omega * Work(phase.t_end);
    laws_.emplace_back(oscillator_, slip_sign(phase.kind), omega * Work(phase.t_begin),
                       omega * Work(phase.x_begin), Work(phase.v_begin));
    while (laws_.back().segment_end() < tau_end) {
      LinearSlipLaw<Work> next = laws_.back().continued_at(laws_.back().segment_end());
      laws_.push_back(std::move(next));
    }
    if constexpr (std::is_same_v<Real, double>) {
      const bool seed_law = model.stiffness == 0 && model.damping == 0 && model.harmonics.empty() &&
                            !model.ground_motion;
      if (seed_law && double_double_lanes_available()) {
        fast_.emplace(SeedSlipStart{model.omega, model.amplitude, model.mass, model.friction,
                                    slip_sign(phase.kind), phase.t_begin, phase.x_begin,
                                    phase.v_begin, model.force_offset});
        if (!fast_->usable()) fast_.reset();
      }
    }
  }

  BasicState<Real> at(const Real& t) const override {
    BasicState<Real> state;
    at_many(&t, 1, &state);
    return state;
  }

  void at_many(const Real* t, std::size_t n, BasicState<Real>* out) const override {
    if (!fast_) {
      for (std::size_t i = 0; i < n; ++i) out[i] = long_double_at(t[i]);
      return;
    }
    if constexpr (std::is_same_v<Real, double>)
      fast_slip_rows(*fast_, phase_, t, n, out, [this](double ti) { return long_double_at(ti); });
  }

  // The state from the long double laws alone (what the fast path must
  // agree with; tests compare the two).
  BasicState<Real> long_double_at(const Real& t) const {
    if (laws_.empty()) return rest_state(phase_, t);
    const Work omega = oscillator_.omega();
    const Work tau = omega * Work(t);
    // The last law starting at or before tau (the first before its start).
    const auto after = std::upper_bound(
        laws_.begin(), laws_.end(), tau,
        [](const Work& value, const LinearSlipLaw<Work>& law) { return value < law.tau_begin(); });
    const std::size_t j =
        after == laws_.begin() ? 0 : static_cast<std::size_t>(after - laws_.begin()) - 1;
    const auto q = laws_[j].point(tau, false);
    return slip_state(phase_, t, Real(q.y / omega), Real(q.v), Real(laws_[j].acceleration(q)));
  }

  // The fast path's answer alone, where it decides (tests).
  bool fast_at(const Real& t, BasicState<Real>& state) const {
    if constexpr (std::is_same_v<Real, double>) {
      return fast_ && fast_slip_row(*fast_, phase_, t, state);
    } else {
      (void)t;
      (void)state;
      return false;
    }
  }

 private:
  BasicPhase<Real> phase_;
  Oscillator<Work> oscillator_;
  std::vector<LinearSlipLaw<Work>> laws_;  // in time order; they point into oscillator_
  std::optional<DoubleDoubleSlip> fast_;   // the seed's law, for double, where the CPU allows
};

}  // namespace frictionref::detail
