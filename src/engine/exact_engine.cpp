// The double instantiation of the exact engine (work type long double).
#include "engine/exact_engine_impl.hpp"

namespace frictionref {

void SolveOptions::validate() const {
  if (max_phases < 1) throw InvalidInput("max_phases", std::to_string(max_phases), "must be >= 1");
}

double time_resolution(const Model& model, double t) {
  using Work = detail::work_t<double>;
  const Work omega(model.omega);
  return static_cast<double>(detail::ScalarTraits<double>::time_resolution(omega * Work(t)) /
                             omega);
}

template class BasicExactEngine<double>;
template struct BasicSummary<double>;
template struct BasicSolution<double>;
template BasicSolution<double> solve(const BasicModel<double>&, const double&,
                                     const SolveOptions&);
template class BasicPhaseEvaluator<double>;
template BasicState<double> evaluate(const BasicModel<double>&, const BasicPhase<double>&,
                                     const double&);

}  // namespace frictionref
