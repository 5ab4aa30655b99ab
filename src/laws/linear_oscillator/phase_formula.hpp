// Dense output of the general model: the state inside an emitted phase from
// its slip law (or the rest position of a stick). With a ground record the
// slip is carried from the phase's start to each segment of the record it
// crosses, as the engine carried it (family.hpp), and evaluated by that
// segment's law.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
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
  }

  BasicState<Real> at(const Real& t) const override {
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

 private:
  BasicPhase<Real> phase_;
  Oscillator<Work> oscillator_;
  std::vector<LinearSlipLaw<Work>> laws_;  // in time order; they point into oscillator_
};

}  // namespace frictionref::detail
