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
    BasicState<Real> state;
    state.t = t;
    state.phase = phase_.kind;
    if (phase_.kind == PhaseKind::stick) {
      state.x = t == phase_.t_end ? phase_.x_end : phase_.x_begin;
      state.v = t == phase_.t_end ? phase_.v_end : t == phase_.t_begin ? phase_.v_begin : 0;
      state.a = 0;
      return state;
    }
    const auto point = law_.point(omega_ * Work(t));
    state.a = Real(law_.acceleration_at(point.at));
    if (t == phase_.t_end) {
      state.x = phase_.x_end;
      state.v = phase_.v_end;
    } else if (t == phase_.t_begin) {
      state.x = phase_.x_begin;
      state.v = phase_.v_begin;
    } else {
      state.x = Real(law_.position(point));
      state.v = Real(Work(law_.sign()) * point.speed);  // s (s v) = v
    }
    return state;
  }

 private:
  BasicPhase<Real> phase_;
  Work omega_;
  PhaseLaw<Work> law_;
};

}  // namespace frictionref::detail
