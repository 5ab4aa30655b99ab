// One stick or slip phase of the exact solution, and dense evaluation inside it.
#pragma once

#include "frictionref/closed_form.hpp"
#include "frictionref/model.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

// A maximal time interval with one kind of motion. Consecutive phases share
// their boundary time and state; no phase has zero length (a stick shorter
// than the resolution of t, as at a grazing stop, is not emitted).
template <class Real>
struct BasicPhase {
  PhaseKind kind = PhaseKind::stick;
  Real t_begin = 0;  // user time
  Real t_end = 0;    // user time; > t_begin
  Real x_begin = 0;
  Real x_end = 0;
  Real v_begin = 0;  // 0 at a breakaway or reversal; v0 for the first phase
  Real v_end = 0;    // 0 where the phase ends in a stop; else the state at the horizon

  Real duration() const { return t_end - t_begin; }
};

// The state at one time: position, velocity, acceleration and phase kind.
template <class Real>
struct BasicState {
  Real t = 0;
  Real x = 0;
  Real v = 0;
  Real a = 0;  // acceleration of the phase `phase` (right limit at a phase start)
  PhaseKind phase = PhaseKind::stick;
};

using Phase = BasicPhase<double>;
using State = BasicState<double>;

// The law of `phase` (built once per phase by samplers; evaluate() below
// builds it for each call).
template <class Real>
PhaseLaw<work_t<Real>> phase_law(const BasicModel<Real>& model, const BasicPhase<Real>& phase) {
  using Work = work_t<Real>;
  const Work omega(model.omega);
  return PhaseLaw<Work>(model, phase.kind, omega * Work(phase.t_begin), Work(phase.x_begin),
                        Work(phase.v_begin));
}

// State at time t inside `phase` (t_begin <= t <= t_end) from its law, in
// closed form: one sin_cos. At t_end it returns the phase's stored end state
// exactly, and at t_begin its start state.
template <class Real>
BasicState<Real> evaluate(const BasicModel<Real>& model, const PhaseLaw<work_t<Real>>& law,
                          const BasicPhase<Real>& phase, const Real& t) {
  using Work = work_t<Real>;
  BasicState<Real> state;
  state.t = t;
  state.phase = phase.kind;
  if (phase.kind == PhaseKind::stick) {
    state.x = t == phase.t_end ? phase.x_end : phase.x_begin;
    state.v = t == phase.t_end ? phase.v_end : t == phase.t_begin ? phase.v_begin : 0;
    state.a = 0;
    return state;
  }
  const auto point = law.point(Work(model.omega) * Work(t));
  state.a = Real(law.acceleration_at(point.at));
  if (t == phase.t_end) {
    state.x = phase.x_end;
    state.v = phase.v_end;
  } else if (t == phase.t_begin) {
    state.x = phase.x_begin;
    state.v = phase.v_begin;
  } else {
    state.x = Real(law.position(point));
    state.v = Real(Work(law.sign()) * point.speed);  // s (s v) = v
  }
  return state;
}

// State at time t inside `phase` (t_begin <= t <= t_end), in closed form.
// At t_end it returns the phase's stored end state exactly.
template <class Real>
BasicState<Real> evaluate(const BasicModel<Real>& model, const BasicPhase<Real>& phase,
                          const Real& t) {
  return evaluate(model, phase_law(model, phase), phase, t);
}

}  // namespace frictionref
