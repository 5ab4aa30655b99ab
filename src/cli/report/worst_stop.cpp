// The worst stop (worst_stop.hpp).
#include "worst_stop.hpp"

#include <algorithm>
#include <cmath>

namespace frictionref::cli {

double stop_window(const ComparisonReport& report) {
  return std::max(0.05 * report.scales.period, 5 * report.max_spacing);
}

std::optional<WorstStop> worst_stop(const ComparisonReport& report, const TimeHistory& history,
                                    const std::vector<double>& error) {
  const double half = stop_window(report);
  std::optional<WorstStop> worst;
  const auto consider = [&](WorstStop stop) {
    stop.window_start = std::max(report.t_first, stop.time - half);
    stop.window_end = std::min(report.t_last, stop.time + half);
    const auto begin = std::lower_bound(history.t.begin(), history.t.end(), stop.window_start);
    const auto end = std::upper_bound(begin, history.t.end(), stop.window_end);
    for (auto i = static_cast<std::size_t>(begin - history.t.begin());
         i < static_cast<std::size_t>(end - history.t.begin()); ++i)
      stop.error = std::max(stop.error, std::fabs(error[i]));
    // Strictly larger: of equal errors the first stop wins.
    if (!worst || stop.error > worst->error) worst = stop;
  };
  for (const StickInterval& phase : report.exact_phases) {
    if (!(phase.start > report.t_first)) continue;  // at rest from the start: not a stop
    WorstStop stop;
    stop.time = phase.start;
    for (const MatchedStick& m : report.matched) {
      if (m.phase_start == phase.start) {
        stop.candidate = m.candidate.start;
        stop.stick_number = m.number;
      }
    }
    consider(stop);
  }
  for (const StickInterval& extra : report.extra) {
    if (!(extra.start > report.t_first)) continue;
    WorstStop stop;
    stop.time = extra.start;
    stop.exact = false;
    stop.candidate = extra.start;
    consider(stop);
  }
  return worst;
}

}  // namespace frictionref::cli
