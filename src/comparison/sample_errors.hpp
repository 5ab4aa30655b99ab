// The error of the candidate's samples against the exact ones: the largest
// and the time-weighted RMS.
#pragma once

#include <cstddef>
#include <vector>

#include "exact_motion.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref::comparison {

struct ErrorStats {
  double max = 0;       // max |error|
  double max_time = 0;  // where (first of equal maxima)
  std::size_t max_row = 0;
  double rms = 0;  // time-weighted (trapezoidal) root mean square
};

ErrorStats error_stats(const std::vector<double>& t, const std::vector<double>& candidate,
                       const std::vector<double>& exact);

struct SampleErrors {
  ErrorStats velocity;
  ErrorStats displacement;  // all 0 without x
};

// The velocity and (with x) displacement errors; fills r.velocity_*_error*,
// r.has_displacement and r.displacement_*_error*. v_exact: exact.v(), which
// the caller reads too.
SampleErrors measure_errors(ComparisonReport& r, const TimeHistory& history,
                            const std::vector<double>& v_exact, const ExactMotion& exact);

}  // namespace frictionref::comparison
