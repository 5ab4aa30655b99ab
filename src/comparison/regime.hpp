// The regime both sides show over the last window of the record, and the
// model's steady state.
#pragma once

#include <vector>

#include "frictionref/comparison.hpp"

namespace frictionref::comparison {

// Fills r.regime_window_start, r.exact_regime(_method) (classify(): a closed
// form where one applies, else the exact engine period after period), and
// the regimes shown by the exact and the candidate velocity in the window
// (needs r.exact_sticks and r.candidate_sticks).
void read_regime(ComparisonReport& r, const std::vector<double>& t,
                 const std::vector<double>& v_exact, const std::vector<double>& v);

}  // namespace frictionref::comparison
