// The checks of a comparison, each a verdict on one property with a message
// that says what was measured and where (docs/cross-checking.md).
#pragma once

#include <cstddef>

#include "exact_motion.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"
#include "sample_errors.hpp"

namespace frictionref::comparison {

// Appends r.checks in CheckKind order (displacement_max only with x), from the
// measured errors, sticks, creep (creep_phase: measure_creep's answer) and
// regime already in r.
void run_checks(ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact,
                const SampleErrors& errors, std::size_t creep_phase);

}  // namespace frictionref::comparison
