// Axis ranges and tick marks for the report's figures: ticks at 1, 2 or 5
// times a power of ten, labelled with just enough digits to tell them apart.
#pragma once

#include <string>
#include <vector>

namespace frictionref::cli {

struct Axis {
  double min = 0, max = 1;          // the range drawn
  std::vector<double> ticks;        // inside [min, max], increasing
  std::vector<std::string> labels;  // one per tick
};

// An axis over the data range [lo, hi] (finite, lo <= hi) with about
// `target` ticks. `padding` widens the range by that fraction of its span at
// each end (0 for time axes, which end where the data end). An empty or
// too-narrow range is widened around its middle so that it can be drawn.
Axis make_axis(double lo, double hi, int target, double padding);

}  // namespace frictionref::cli
