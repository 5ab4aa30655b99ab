// The SVG plot writer (svg_plot.hpp).
#include "svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

#include "axis_ticks.hpp"
#include "markup_escape.hpp"

namespace frictionref::cli {
namespace {

// Room around the plot area for the title, tick labels and axis labels [px].
constexpr double left = 84, right = 20, top = 34, bottom = 52;
constexpr const char* font = "font-family=\"sans-serif\" font-size=\"12\"";

struct Frame {
  Axis x, y;
  double x0, y0, w, h;  // the plot area [px]
  double px(double value) const { return x0 + (value - x.min) / (x.max - x.min) * w; }
  double py(double value) const { return y0 + h - (value - y.min) / (y.max - y.min) * h; }
};

// The rows of `line` inside [x_min, x_max], with one neighbour on each side.
std::vector<std::size_t> shown_rows(const PlotLine& line, double x_min, double x_max) {
  std::vector<std::size_t> rows;
  const std::size_t n = std::min(line.x.size(), line.y.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(line.x[i]) || !std::isfinite(line.y[i])) continue;
    const bool inside = line.x[i] >= x_min && line.x[i] <= x_max;
    const bool next_inside = i + 1 < n && line.x[i + 1] >= x_min && line.x[i + 1] <= x_max;
    const bool previous_inside = i > 0 && line.x[i - 1] >= x_min && line.x[i - 1] <= x_max;
    if (inside || next_inside || previous_inside) rows.push_back(i);
  }
  return rows;
}

std::string stroke(const std::string& color, double width, bool dashed) {
  return fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{}", escape_markup(color),
                     width, dashed ? " stroke-dasharray=\"6 4\"" : "");
}

}  // namespace

std::string svg_plot(const Plot& plot) {
  // The x range: given, or the lines' own.
  double x_min = plot.x_min, x_max = plot.x_max;
  if (!std::isfinite(x_min) || !std::isfinite(x_max)) {
    x_min = std::numeric_limits<double>::infinity();
    x_max = -x_min;
    for (const PlotLine& line : plot.lines)
      for (const double x : line.x)
        if (std::isfinite(x)) x_min = std::min(x_min, x), x_max = std::max(x_max, x);
    if (!(x_min <= x_max)) x_min = 0, x_max = 1;
  }
  // The y range over what is shown.
  std::vector<std::vector<std::size_t>> rows;
  double y_min = std::numeric_limits<double>::infinity(), y_max = -y_min;
  for (const PlotLine& line : plot.lines) {
    rows.push_back(shown_rows(line, x_min, x_max));
    for (const std::size_t i : rows.back())
      if (line.x[i] >= x_min && line.x[i] <= x_max)
        y_min = std::min(y_min, line.y[i]), y_max = std::max(y_max, line.y[i]);
  }
  for (const PlotRule& rule : plot.horizontal)
    if (std::isfinite(rule.value))
      y_min = std::min(y_min, rule.value), y_max = std::max(y_max, rule.value);
  if (!(y_min <= y_max)) y_min = -1, y_max = 1;

  Frame f;
  f.x = make_axis(x_min, x_max, 8, 0);
  f.y = make_axis(y_min, y_max, 6, 0.06);
  f.x0 = left;
  f.y0 = top;
  f.w = plot.width - left - right;
  f.h = plot.height - top - bottom;
  const std::string& id = plot.id;

  std::string svg = fmt::format(
      "<svg id=\"{0}\" class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" width=\"{1}\" "
      "height=\"{2}\" viewBox=\"0 0 {1} {2}\" role=\"img\" aria-labelledby=\"{0}-title\">\n"
      "<title id=\"{0}-title\">{3}</title>\n"
      "<rect x=\"0\" y=\"0\" width=\"{1}\" height=\"{2}\" fill=\"#ffffff\"/>\n"
      "<defs><clipPath id=\"{0}-area\"><rect x=\"{4:.2f}\" y=\"{5:.2f}\" width=\"{6:.2f}\" "
      "height=\"{7:.2f}\"/></clipPath></defs>\n",
      escape_markup(id), plot.width, plot.height, escape_markup(plot.title), f.x0, f.y0, f.w, f.h);
  svg += fmt::format(
      "<text x=\"{:.2f}\" y=\"20\" text-anchor=\"middle\" {} font-weight=\"bold\">"
      "{}</text>\n",
      plot.width / 2.0, font, escape_markup(plot.title));

  // Grid, ticks and tick labels.
  svg += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
  for (const double t : f.x.ticks)
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\"/>\n",
                       f.px(t), f.y0, f.y0 + f.h);
  for (const double t : f.y.ticks)
    svg += fmt::format("<line x1=\"{1:.2f}\" y1=\"{0:.2f}\" x2=\"{2:.2f}\" y2=\"{0:.2f}\"/>\n",
                       f.py(t), f.x0, f.x0 + f.w);
  svg += "</g>\n";
  svg += fmt::format("<g {} fill=\"#222222\">\n", font);
  for (std::size_t i = 0; i < f.x.ticks.size(); ++i) {
    const double x = f.px(f.x.ticks[i]);
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"#222222\"/>"
        "<text x=\"{0:.2f}\" y=\"{3:.2f}\" text-anchor=\"middle\">{4}</text>\n",
        x, f.y0 + f.h, f.y0 + f.h + 5, f.y0 + f.h + 19, escape_markup(f.x.labels[i]));
  }
  for (std::size_t i = 0; i < f.y.ticks.size(); ++i) {
    const double y = f.py(f.y.ticks[i]);
    svg += fmt::format(
        "<line x1=\"{1:.2f}\" y1=\"{0:.2f}\" x2=\"{2:.2f}\" y2=\"{0:.2f}\" stroke=\"#222222\"/>"
        "<text x=\"{3:.2f}\" y=\"{4:.2f}\" text-anchor=\"end\">{5}</text>\n",
        y, f.x0 - 5, f.x0, f.x0 - 8, y + 4, escape_markup(f.y.labels[i]));
  }
  // Axis labels.
  svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>\n",
                     f.x0 + f.w / 2, plot.height - 12.0, escape_markup(plot.x_label));
  svg += fmt::format(
      "<text x=\"0\" y=\"0\" text-anchor=\"middle\" transform=\"translate(18 {:.2f}) "
      "rotate(-90)\">{}</text>\n",
      f.y0 + f.h / 2, escape_markup(plot.y_label));
  svg += "</g>\n";

  // Data and rules, clipped to the plot area.
  svg += fmt::format("<g clip-path=\"url(#{}-area)\">\n", escape_markup(id));
  for (const PlotRule& rule : plot.vertical) {
    if (!std::isfinite(rule.value)) continue;
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" {3}/>\n",
                       f.px(rule.value), f.y0, f.y0 + f.h, stroke(rule.color, 1.2, true));
  }
  for (const PlotRule& rule : plot.horizontal) {
    if (!std::isfinite(rule.value)) continue;
    svg += fmt::format("<line x1=\"{1:.2f}\" y1=\"{0:.2f}\" x2=\"{2:.2f}\" y2=\"{0:.2f}\" {3}/>\n",
                       f.py(rule.value), f.x0, f.x0 + f.w, stroke(rule.color, 1.2, true));
  }
  for (std::size_t k = 0; k < plot.lines.size(); ++k) {
    const PlotLine& line = plot.lines[k];
    if (rows[k].empty()) continue;
    std::string points;
    for (const std::size_t i : rows[k])
      points += fmt::format("{}{:.2f},{:.2f}", points.empty() ? "" : " ", f.px(line.x[i]),
                            f.py(line.y[i]));
    svg += fmt::format("<polyline class=\"line-{}\" {} stroke-linejoin=\"round\" points=\"{}\"/>\n",
                       k, stroke(line.color, line.width, line.dashed), points);
    if (line.dots) {
      svg += fmt::format("<g fill=\"{}\">", escape_markup(line.color));
      for (const std::size_t i : rows[k])
        svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2.2\"/>", f.px(line.x[i]),
                           f.py(line.y[i]));
      svg += "</g>\n";
    }
  }
  svg += "</g>\n";
  svg += fmt::format(
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" "
      "stroke=\"#222222\"/>\n",
      f.x0, f.y0, f.w, f.h);

  // Legend: in a corner of the plot area, one row per labelled entry.
  struct Entry {
    std::string label, color;
    double width;
    bool dashed, dots;
  };
  std::vector<Entry> entries;
  for (const PlotLine& line : plot.lines)
    if (!line.label.empty())
      entries.push_back({line.label, line.color, line.width, line.dashed, line.dots});
  for (const auto* rules : {&plot.vertical, &plot.horizontal})
    for (const PlotRule& rule : *rules)
      if (!rule.label.empty()) entries.push_back({rule.label, rule.color, 1.2, true, false});
  if (!entries.empty()) {
    std::size_t longest = 0;
    for (const Entry& e : entries) longest = std::max(longest, e.label.size());
    const double box_w = 46 + 6.8 * static_cast<double>(longest);
    const double box_h = 8 + 18 * static_cast<double>(entries.size());
    // The corner that hides the fewest points (top right on a tie).
    double bx = 0, by = 0;
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    for (const auto& [right_side, top_side] :
         {std::pair{true, true}, {false, true}, {true, false}, {false, false}}) {
      const double x = right_side ? f.x0 + f.w - box_w - 8 : f.x0 + 8;
      const double y = top_side ? f.y0 + 8 : f.y0 + f.h - box_h - 8;
      std::size_t hidden = 0;
      for (std::size_t k = 0; k < plot.lines.size(); ++k) {
        for (const std::size_t i : rows[k]) {
          const double px = f.px(plot.lines[k].x[i]), py = f.py(plot.lines[k].y[i]);
          if (px >= x && px <= x + box_w && py >= y && py <= y + box_h) ++hidden;
        }
      }
      if (hidden < fewest) fewest = hidden, bx = x, by = y;
    }
    svg += fmt::format(
        "<g class=\"legend\" {}><rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" "
        "height=\"{:.2f}\" fill=\"#ffffff\" fill-opacity=\"0.88\" stroke=\"#999999\"/>\n",
        font, bx, by, box_w, box_h);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const Entry& e = entries[i];
      const double y = by + 16 + 18 * static_cast<double>(i);
      svg += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" {}/>",
                         bx + 8, y - 4, bx + 36, y - 4, stroke(e.color, e.width, e.dashed));
      if (e.dots)
        svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2.2\" fill=\"{}\"/>", bx + 22,
                           y - 4, escape_markup(e.color));
      svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" fill=\"#222222\">{}</text>\n", bx + 42, y,
                         escape_markup(e.label));
    }
    svg += "</g>\n";
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace frictionref::cli
