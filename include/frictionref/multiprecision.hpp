// The exact engine instantiated with a 50-digit Boost.Multiprecision type.
// It computes in that type throughout and finds slip ends with Boost.Math's
// TOMS 748 instead of GSL: a standing cross-check of the double engine.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "frictionref/exact_engine.hpp"

namespace frictionref {

using HighPrecision = boost::multiprecision::cpp_bin_float_50;

extern template class BasicExactEngine<HighPrecision>;
extern template struct BasicSummary<HighPrecision>;
extern template struct BasicSolution<HighPrecision>;
extern template BasicSolution<HighPrecision> solve(const BasicModel<HighPrecision>&,
                                                   const HighPrecision&, const SolveOptions&);
extern template class BasicPhaseEvaluator<HighPrecision>;
extern template BasicState<HighPrecision> evaluate(const BasicModel<HighPrecision>&,
                                                   const BasicPhase<HighPrecision>&,
                                                   const HighPrecision&);

}  // namespace frictionref
