// The closed form of one emitted phase, for dense output (the public
// BasicPhaseEvaluator holds one). Each family of phase laws implements it.
#pragma once

#include <cstddef>
#include <memory>

#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::detail {

template <class Real>
class PhaseFormula {
 public:
  virtual ~PhaseFormula() = default;
  // State at t in [t_begin, t_end] (the stored end state at t_end exactly).
  virtual BasicState<Real> at(const Real& t) const = 0;
  // The same at each of n times (a family may evaluate them together).
  virtual void at_many(const Real* t, std::size_t n, BasicState<Real>* out) const {
    for (std::size_t i = 0; i < n; ++i) out[i] = at(t[i]);
  }
  // x, v and a of the same states as columns (their t are the times, their
  // phase the phase's kind): the fast paths write their rows straight into
  // them, and a sampler hands them on without building states.
  virtual void columns(const Real* t, std::size_t n, Real* x, Real* v, Real* a) const;
  // The formula of another phase of the same model, sharing what depends on
  // the model alone (a sampler's next phase).
  virtual std::unique_ptr<const PhaseFormula<Real>> for_phase(
      const BasicPhase<Real>& phase) const = 0;
};

// The rules every family's dense output shares. A stick holds its rest
// position (the stored end state at t_end).
template <class Real>
BasicState<Real> rest_state(const BasicPhase<Real>& phase, const Real& t) {
  BasicState<Real> state;
  state.t = t;
  state.phase = phase.kind;
  state.x = t == phase.t_end ? phase.x_end : phase.x_begin;
  state.v = t == phase.t_end ? phase.v_end : t == phase.t_begin ? phase.v_begin : 0;
  return state;
}

// Inside a slip, the formula's x, v and a, except at the phase's own ends,
// where x and v are the stored states exactly: samples at event times then
// match the event table.
template <class Real>
BasicState<Real> slip_state(const BasicPhase<Real>& phase, const Real& t, const Real& x,
                            const Real& v, const Real& a) {
  BasicState<Real> state{t, x, v, a, phase.kind};
  if (t == phase.t_end) {
    state.x = phase.x_end;
    state.v = phase.v_end;
  } else if (t == phase.t_begin) {
    state.x = phase.x_begin;
    state.v = phase.v_begin;
  }
  return state;
}

// Row i of the columns x, v, a from a state.
template <class Real>
void put_row(const BasicState<Real>& state, std::size_t i, Real* x, Real* v, Real* a) {
  x[i] = state.x;
  v[i] = state.v;
  a[i] = state.a;
}

// The columns at n times from a state per time (state_at(t)).
template <class Real, class StateAt>
void columns_of_states(const StateAt& state_at, const Real* t, std::size_t n, Real* x, Real* v,
                       Real* a) {
  for (std::size_t i = 0; i < n; ++i) put_row(state_at(t[i]), i, x, v, a);
}

template <class Real>
void PhaseFormula<Real>::columns(const Real* t, std::size_t n, Real* x, Real* v, Real* a) const {
  columns_of_states([this](const Real& time) { return at(time); }, t, n, x, v, a);
}

// The states at n times from a formula's columns (for the families whose
// columns are their fast path), a chunk at a time.
template <class Real>
void states_from_columns(const PhaseFormula<Real>& formula, PhaseKind kind, const Real* t,
                         std::size_t n, BasicState<Real>* out) {
  constexpr std::size_t kChunk = 64;
  Real x[kChunk], v[kChunk], a[kChunk];
  for (std::size_t i = 0; i < n; i += kChunk) {
    const std::size_t m = n - i < kChunk ? n - i : kChunk;
    formula.columns(t + i, m, x, v, a);
    for (std::size_t k = 0; k < m; ++k) out[i + k] = {t[i + k], x[k], v[k], a[k], kind};
  }
}

// The formula of the model's family of laws for `phase`.
template <class Real>
std::unique_ptr<const PhaseFormula<Real>> make_phase_formula(const BasicModel<Real>& model,
                                                             const BasicPhase<Real>& phase);

}  // namespace frictionref::detail
