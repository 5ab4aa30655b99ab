// Which stop the report zooms on: of all the places where the mass comes to
// rest (the start of every exact stick phase after the record's first time,
// and of every stick only the candidate shows), the one with the largest
// velocity error |v - v_exact| among the candidate's samples around it
// (of equal errors the first: exact stops in time order, then extra sticks).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref::cli {

struct WorstStop {
  double time = 0;                  // where the mass stops: exact phase start, or the
                                    // candidate's stick start for an extra stick [time]
  bool exact = true;                // false: a stop only the candidate makes (extra)
  std::optional<double> candidate;  // the candidate's matched stick start, if any [time]
  std::size_t stick_number = 0;     // MatchedStick::number if matched, else 0
  double error = 0;                 // max |v - v_exact| in the window [length/time]
  double window_start = 0;          // the samples looked at, and the zoom shown [time]
  double window_end = 0;
};

// The half-width of the window around each stop: 5 % of a forcing period, or
// 5 candidate steps if that is wider.
double stop_window(const ComparisonReport& report);

// nullopt if the record holds no stop. `error` is v - v_exact at the
// candidate's times.
std::optional<WorstStop> worst_stop(const ComparisonReport& report, const TimeHistory& history,
                                    const std::vector<double>& error);

}  // namespace frictionref::cli
