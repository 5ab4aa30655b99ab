#include "sample_errors.hpp"

#include <cmath>

namespace frictionref::comparison {

ErrorStats error_stats(const std::vector<double>& t, const std::vector<double>& candidate,
                       const std::vector<double>& exact) {
  ErrorStats stats;
  stats.max_time = t.front();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = std::fabs(candidate[i] - exact[i]);
    if (e > stats.max) {
      stats.max = e;
      stats.max_time = t[i];
      stats.max_row = i;
    }
  }
  // The squares are taken of errors scaled by the largest one, so huge values
  // in a candidate file cannot overflow into inf * 0 = NaN; an infinite error
  // gives an infinite RMS (a FAIL, never a NaN).
  if (!(stats.max > 0) || !std::isfinite(stats.max)) {
    stats.rms = stats.max;
    return stats;
  }
  double integral = 0;
  double previous = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = (candidate[i] - exact[i]) / stats.max;
    if (i > 0) integral += (t[i] - t[i - 1]) * (previous * previous + e * e) / 2;
    previous = e;
  }
  stats.rms = stats.max * std::sqrt(integral / (t.back() - t.front()));
  return stats;
}

SampleErrors measure_errors(ComparisonReport& r, const TimeHistory& history,
                            const std::vector<double>& v_exact, const ExactMotion& exact) {
  SampleErrors errors;
  errors.velocity = error_stats(history.t, history.v, v_exact);
  r.velocity_max_error = errors.velocity.max;
  r.velocity_max_error_time = errors.velocity.max_time;
  r.velocity_rms_error = errors.velocity.rms;
  if (history.x) {
    errors.displacement = error_stats(history.t, *history.x, exact.x());
    r.has_displacement = true;
    r.displacement_max_error = errors.displacement.max;
    r.displacement_max_error_time = errors.displacement.max_time;
    r.displacement_rms_error = errors.displacement.rms;
  }
  return errors;
}

}  // namespace frictionref::comparison
