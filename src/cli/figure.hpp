// Figures through gnuplot (the only plotting the project does): one or more
// stacked panels of x-y series, written atomically as SVG or PNG chosen by
// the file extension. gnuplot runs as a child process on a temporary data
// file and script; nothing is drawn by hand.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace frictionref::cli {

struct Series {
  std::string title;         // legend entry ("" for none)
  std::vector<double> x, y;  // same length
  // How it is drawn. The exact solution is "reference": a thick black line;
  // other series cycle through thinner coloured lines (or points).
  // "level": a dashed grey line, for a threshold (the yield level).
  enum class Role { reference, candidate, marker, level } role = Role::candidate;
  bool points = false;       // points instead of a line
  bool markers = false;      // a line with a marker at every point (sparse data)
};

// Values on a regular grid, drawn as coloured pixels under the series (a
// parameter map): z[i * y.size() + j] belongs to (x[i], y[j]).
struct HeatMap {
  std::vector<double> x, y, z;
  std::string z_label;  // the colour bar's label, with units
};

struct Panel {
  std::string title;
  std::string x_label;  // with units, e.g. "t [time]"
  std::string y_label;
  std::vector<Series> series;
  bool log_x = false, log_y = false;
  std::vector<double> vertical_lines;  // drawn dashed, e.g. lambda* on a sweep
  HeatMap heat_map;                    // drawn first when it has values
};

inline Panel make_panel(std::string title, std::string x_label, std::string y_label,
                        std::vector<Series> series) {
  Panel panel;
  panel.title = std::move(title);
  panel.x_label = std::move(x_label);
  panel.y_label = std::move(y_label);
  panel.series = std::move(series);
  return panel;
}

struct Figure {
  std::string title;  // over all panels
  std::vector<Panel> panels;
  int width = 900;    // pixels; height grows with the panels
  int panel_height = 360;
};

// True if a gnuplot executable is on PATH.
bool gnuplot_available();

// Throws bad input (cli_error.hpp) naming `option` unless `path` ends in .svg
// or .png, and unless gnuplot can be run. Call before computing anything, so
// a missing gnuplot leaves no other output behind either.
void require_figure_path(const std::string& path, const std::string& option);

// Writes the figure to `path` (via "<path>.tmp.XXXXXX" and a rename). Throws
// bad input naming `option` if gnuplot fails or the file cannot be written.
void write_figure(const Figure& figure, const std::string& path, const std::string& option);

}  // namespace frictionref::cli
