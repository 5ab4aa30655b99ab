// Dense output of the general model: the state inside an emitted phase from
// its slip law (or the rest position of a stick).
#pragma once

#include <optional>

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
    if (phase.kind != PhaseKind::stick) {
      const Work omega = oscillator_.omega();
      law_.emplace(oscillator_, slip_sign(phase.kind), omega * Work(phase.t_begin),
                   omega * Work(phase.x_begin), Work(phase.v_begin));
    }
  }

  BasicState<Real> at(const Real& t) const override {
    if (!law_) return rest_state(phase_, t);
    const Work omega = oscillator_.omega();
    const auto q = law_->point(omega * Work(t));
    return slip_state(phase_, t, Real(q.y / omega), Real(q.v), Real(law_->acceleration(q)));
  }

 private:
  BasicPhase<Real> phase_;
  Oscillator<Work> oscillator_;
  std::optional<LinearSlipLaw<Work>> law_;  // points into oscillator_: not copyable
};

}  // namespace frictionref::detail
