// Dense output of the general model: the state inside an emitted phase from
// its slip law (or the rest position of a stick). With a ground record the
// slip is carried from the phase's start to each segment of the record it
// crosses, as the engine carried it (family.hpp), and evaluated by that
// segment's law.
#pragma once

#include <algorithm>
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
    const int sign = slip_sign(phase.kind);
    Work tau = omega * Work(phase.t_begin);
    const Work tau_end = omega * Work(phase.t_end);
    RecordPiece<Work> piece = oscillator_.record().piece_at(tau);
    laws_.emplace_back(oscillator_, sign, tau, omega * Work(phase.x_begin), Work(phase.v_begin),
                       piece);
    starts_.push_back(tau);
    while (piece.end < tau_end) {
      const auto q = laws_.back().point(piece.end, false);
      tau = piece.end;
      piece = oscillator_.record().piece_at(tau);
      laws_.emplace_back(oscillator_, sign, tau, q.y, q.v, piece);
      starts_.push_back(tau);
    }
  }

  BasicState<Real> at(const Real& t) const override {
    if (laws_.empty()) return rest_state(phase_, t);
    const Work omega = oscillator_.omega();
    const Work tau = omega * Work(t);
    // The last law starting at or before tau (the first before its start).
    std::size_t j = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), tau) -
                                             starts_.begin());
    j = j == 0 ? 0 : j - 1;
    const auto q = laws_[j].point(tau, false);
    return slip_state(phase_, t, Real(q.y / omega), Real(q.v), Real(laws_[j].acceleration(q)));
  }

 private:
  BasicPhase<Real> phase_;
  Oscillator<Work> oscillator_;
  std::vector<Work> starts_;               // tau at each law's start
  std::vector<LinearSlipLaw<Work>> laws_;  // they point into oscillator_: not copyable
};

}  // namespace frictionref::detail
