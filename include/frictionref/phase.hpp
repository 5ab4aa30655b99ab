// One stick or slip phase of the exact solution, and dense evaluation inside it.
#pragma once

#include <cstddef>
#include <memory>

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

namespace detail {
template <class Real>
class PhaseFormula;  // the closed form of a phase of one family of laws (src/engine)
}  // namespace detail

// The closed form of one phase, built once from the model and the phase's
// start (samplers evaluate it at many times: one sin_cos per sample for the
// seed's model).
template <class Real>
class BasicPhaseEvaluator {
 public:
  BasicPhaseEvaluator(const BasicModel<Real>& model, const BasicPhase<Real>& phase);
  ~BasicPhaseEvaluator();
  BasicPhaseEvaluator(BasicPhaseEvaluator&&) noexcept;
  BasicPhaseEvaluator& operator=(BasicPhaseEvaluator&&) noexcept;

  // State at time t inside the phase (t_begin <= t <= t_end), in closed form.
  // At t_end it returns the phase's stored end state exactly, and at t_begin
  // its start state.
  BasicState<Real> operator()(const Real& t) const;
  // The states at times[0..count) (each as above), written to states[0..count).
  // The same values as one call per time, faster for the seed's model in
  // double (docs/theory.md 10 evaluates four times at once).
  void operator()(const Real* times, std::size_t count, BasicState<Real>* states) const;
  // The same states as columns: x[i], v[i] and a[i] of the state at times[i]
  // (its t is times[i], its phase this phase's kind). The fast paths write
  // these arrays directly, so this is the cheapest way to many rows.
  void operator()(const Real* times, std::size_t count, Real* x, Real* v, Real* a) const;

  // The evaluator of another phase of the same model: the same states as
  // BasicPhaseEvaluator(model, phase), sharing what depends on the model
  // alone (the general model's long double oscillator, built on first
  // need), so cheaper where a sampler visits a model's phases in turn.
  BasicPhaseEvaluator for_phase(const BasicPhase<Real>& phase) const;

 private:
  explicit BasicPhaseEvaluator(std::unique_ptr<const detail::PhaseFormula<Real>> formula);
  std::unique_ptr<const detail::PhaseFormula<Real>> formula_;
};

// State at time t inside `phase` (t_begin <= t <= t_end), in closed form
// (builds the phase's evaluator for this one call).
template <class Real>
BasicState<Real> evaluate(const BasicModel<Real>& model, const BasicPhase<Real>& phase,
                          const Real& t);

using Phase = BasicPhase<double>;
using State = BasicState<double>;
using PhaseEvaluator = BasicPhaseEvaluator<double>;

extern template class BasicPhaseEvaluator<double>;
extern template BasicState<double> evaluate(const BasicModel<double>&, const BasicPhase<double>&,
                                            const double&);

}  // namespace frictionref
