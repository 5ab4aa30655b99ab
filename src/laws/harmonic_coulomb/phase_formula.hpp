// Dense output of the seed's model: the state inside an emitted phase from
// its law (one sin_cos per evaluation).
#pragma once

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/harmonic_coulomb/phase_law.hpp"

namespace frictionref::detail {

template <class Real>
class HarmonicCoulombFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;

  HarmonicCoulombFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : phase_(phase),
        omega_(model.omega),
        law_(model, phase.kind, omega_ * Work(phase.t_begin), Work(phase.x_begin),
             Work(phase.v_begin)) {}

  BasicState<Real> at(const Real& t) const override {
    if (phase_.kind == PhaseKind::stick) return rest_state(phase_, t);
    const auto point = law_.point(omega_ * Work(t));
    // v = s (s v).
    return slip_state(phase_, t, Real(law_.position(point)), Real(Work(law_.sign()) * point.speed),
                      Real(law_.acceleration_at(point.at)));
  }

 private:
  BasicPhase<Real> phase_;
  Work omega_;
  PhaseLaw<Work> law_;
};

}  // namespace frictionref::detail
