// Definitions of the public engine templates (exact_engine.hpp, phase.hpp) on
// top of the event loop and the families of phase laws; instantiated for
// double in exact_engine.cpp and for HighPrecision in
// exact_engine_multiprecision.cpp.
#pragma once

#include <algorithm>
#include <sstream>

#include "engine/engine_core.hpp"
#include "engine/event_loop.hpp"
#include "engine/phase_formula.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/exact_engine.hpp"
#include "laws/harmonic_coulomb/family.hpp"
#include "laws/harmonic_coulomb/phase_formula.hpp"
#include "laws/linear_oscillator/family.hpp"
#include "laws/linear_oscillator/phase_formula.hpp"
#include "laws/rigid_block_record/family.hpp"
#include "laws/rigid_block_record/phase_formula.hpp"

namespace frictionref {
namespace detail {

template <class Real>
std::unique_ptr<EngineCore<Real>> make_engine_core(const BasicModel<Real>& model, const Real& t_end,
                                                   const SolveOptions& options) {
  if (model.is_harmonic_coulomb())
    return std::make_unique<EventLoop<Real, HarmonicCoulombFamily<Real>>>(model, t_end, options);
  if (is_rigid_block_record(model))
    return std::make_unique<EventLoop<Real, RigidBlockRecordFamily<Real>>>(model, t_end, options);
  return std::make_unique<EventLoop<Real, LinearOscillatorFamily<Real>>>(model, t_end, options);
}

template <class Real>
std::unique_ptr<const PhaseFormula<Real>> make_phase_formula(const BasicModel<Real>& model,
                                                             const BasicPhase<Real>& phase) {
  if (model.is_harmonic_coulomb())
    return std::make_unique<HarmonicCoulombFormula<Real>>(model, phase);
  if (is_rigid_block_record(model))
    return std::make_unique<RigidBlockRecordFormula<Real>>(model, phase);
  return std::make_unique<LinearOscillatorFormula<Real>>(model, phase);
}

}  // namespace detail

template <class Real>
std::string BasicSummary<Real>::brief_report() const {
  std::ostringstream text;
  text.precision(std::numeric_limits<Real>::max_digits10);
  text << "termination=" << to_string(termination) << " phases=" << phases
       << " stick=" << count(PhaseKind::stick) << " slip+=" << count(PhaseKind::slip_forward)
       << " slip-=" << count(PhaseKind::slip_backward) << " stops=" << stops
       << " reversals=" << reversals << " breakaways=" << breakaways
       << " merged_sticks=" << merged_sticks << " touches=" << touches
       << " sign_tests=" << sign_tests << " root_function_calls=" << root_function_calls
       << " predicted_stops=" << predicted_stops << " replayed_phases=" << replayed_phases
       << " t=" << final_state.t << " x=" << final_state.x
       << " v=" << final_state.v;
  return text.str();
}

template <class Real>
BasicExactEngine<Real>::BasicExactEngine(const BasicModel<Real>& model, const Real& t_end,
                                         const SolveOptions& options)
    : core_(detail::make_engine_core(model, t_end, options)) {}

template <class Real>
BasicExactEngine<Real>::~BasicExactEngine() = default;
template <class Real>
BasicExactEngine<Real>::BasicExactEngine(BasicExactEngine&&) noexcept = default;
template <class Real>
BasicExactEngine<Real>& BasicExactEngine<Real>::operator=(BasicExactEngine&&) noexcept = default;

template <class Real>
bool BasicExactEngine<Real>::next(BasicPhase<Real>& phase) {
  return core_->next(phase);
}
template <class Real>
const BasicModel<Real>& BasicExactEngine<Real>::model() const {
  return core_->model();
}
template <class Real>
const Real& BasicExactEngine<Real>::t_end() const {
  return core_->t_end();
}
template <class Real>
const BasicSummary<Real>& BasicExactEngine<Real>::summary() const {
  return core_->summary();
}

template <class Real>
const BasicPhase<Real>& BasicSolution<Real>::phase_at(const Real& t) const {
  if (phases.empty() || !(t >= phases.front().t_begin) || !(t <= phases.back().t_end))
    throw InvalidInput("t", detail::to_text(t), "must lie within [t0, t_end] of the solution");
  // First phase whose t_end > t; the last phase also owns its t_end.
  auto it = std::upper_bound(
      phases.begin(), phases.end(), t,
      [](const Real& value, const BasicPhase<Real>& p) { return value < p.t_end; });
  if (it == phases.end()) --it;
  return *it;
}

template <class Real>
BasicState<Real> BasicSolution<Real>::state_at(const Real& t) const {
  return evaluate(model, phase_at(t), t);
}

template <class Real>
BasicSolution<Real> solve(const BasicModel<Real>& model, const Real& t_end,
                          const SolveOptions& options) {
  BasicExactEngine<Real> engine(model, t_end, options);
  BasicSolution<Real> solution;
  solution.model = model;
  BasicPhase<Real> phase;
  while (engine.next(phase)) solution.phases.push_back(phase);
  solution.summary = engine.summary();
  return solution;
}

template <class Real>
BasicPhaseEvaluator<Real>::BasicPhaseEvaluator(const BasicModel<Real>& model,
                                               const BasicPhase<Real>& phase)
    : formula_(detail::make_phase_formula(model, phase)) {}
template <class Real>
BasicPhaseEvaluator<Real>::BasicPhaseEvaluator(
    std::unique_ptr<const detail::PhaseFormula<Real>> formula)
    : formula_(std::move(formula)) {}
template <class Real>
BasicPhaseEvaluator<Real> BasicPhaseEvaluator<Real>::for_phase(
    const BasicPhase<Real>& phase) const {
  return BasicPhaseEvaluator(formula_->for_phase(phase));
}
template <class Real>
BasicPhaseEvaluator<Real>::~BasicPhaseEvaluator() = default;
template <class Real>
BasicPhaseEvaluator<Real>::BasicPhaseEvaluator(BasicPhaseEvaluator&&) noexcept = default;
template <class Real>
BasicPhaseEvaluator<Real>& BasicPhaseEvaluator<Real>::operator=(BasicPhaseEvaluator&&) noexcept =
    default;

template <class Real>
BasicState<Real> BasicPhaseEvaluator<Real>::operator()(const Real& t) const {
  return formula_->at(t);
}

template <class Real>
void BasicPhaseEvaluator<Real>::operator()(const Real* times, std::size_t count,
                                           BasicState<Real>* states) const {
  formula_->at_many(times, count, states);
}

template <class Real>
void BasicPhaseEvaluator<Real>::operator()(const Real* times, std::size_t count, Real* x, Real* v,
                                           Real* a) const {
  formula_->columns(times, count, x, v, a);
}

template <class Real>
BasicState<Real> evaluate(const BasicModel<Real>& model, const BasicPhase<Real>& phase,
                          const Real& t) {
  return detail::make_phase_formula(model, phase)->at(t);
}

}  // namespace frictionref
