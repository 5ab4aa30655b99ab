// Line plots as inline SVG, written by hand for the HTML report: axes with
// ticks and labels, grid, legend, dashed reference lines; no script, no
// fonts or styles from outside (generic font families only). Text is escaped
// (markup_escape.hpp); coordinates are finite by construction.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace frictionref::cli {

struct PlotLine {
  std::string label;  // legend entry ("" for none)
  std::vector<double> x, y;
  std::string color = "#000000";  // a CSS colour (#rrggbb)
  double width = 1.5;             // stroke width [px]
  bool dashed = false;
  bool dots = false;  // also a dot at every point (sparse samples in a zoom)
};

// A dashed line across the plot at x = value (vertical) or y = value (horizontal).
struct PlotRule {
  double value = 0;
  std::string label;  // legend entry ("" for none)
  std::string color = "#555555";
};

struct Plot {
  std::string id;  // unique in the page: the svg's id and the prefix of its inner ids
  std::string title;
  std::string x_label, y_label;  // with units: "t [time]"
  std::vector<PlotLine> lines;   // drawn in order (later on top)
  std::vector<PlotRule> vertical, horizontal;
  double x_min = NAN, x_max = NAN;  // the x range shown; NaN: the lines' range
  int width = 900, height = 360;    // [px]
};

// <svg ...>...</svg> for the plot. Points outside the x range are left out
// (but for one on each side, so lines reach the edges); the y range covers
// the points shown and the horizontal rules, with a margin.
std::string svg_plot(const Plot& plot);

}  // namespace frictionref::cli
