// The 50-digit instantiation: the same engine code, TOMS 748 for the roots.
#include "engine/exact_engine_impl.hpp"
#include "frictionref/multiprecision.hpp"

namespace frictionref {

template class BasicExactEngine<HighPrecision>;
template struct BasicSummary<HighPrecision>;
template struct BasicSolution<HighPrecision>;
template BasicSolution<HighPrecision> solve(const BasicModel<HighPrecision>&,
                                            const HighPrecision&, const SolveOptions&);
template class BasicPhaseEvaluator<HighPrecision>;
template BasicState<HighPrecision> evaluate(const BasicModel<HighPrecision>&,
                                            const BasicPhase<HighPrecision>&,
                                            const HighPrecision&);

}  // namespace frictionref
