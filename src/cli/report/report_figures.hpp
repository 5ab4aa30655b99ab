// The report's three figures, as plots for svg_plot: the exact and candidate
// velocities overlaid, the velocity error against time with its tolerance,
// and a zoom on the worst stop (worst_stop.hpp).
#pragma once

#include <string>

#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"
#include "svg_plot.hpp"

namespace frictionref::cli {

struct ReportFigures {
  Plot velocity;
  Plot error;
  Plot zoom;
  std::string zoom_caption;  // which stop, and why this one
};

ReportFigures report_figures(const ComparisonReport& report, const TimeHistory& history);

}  // namespace frictionref::cli
