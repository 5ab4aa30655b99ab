// The report's figures (report_figures.hpp).
#include "report_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../compare_run.hpp"
#include "../csv_format.hpp"
#include "frictionref/sampling.hpp"
#include "worst_stop.hpp"

namespace frictionref::cli {
namespace {

// A 900 px plot shows at most ~3 points per pixel column; decimation keeps
// each bucket's extremes, so nothing visible is lost.
constexpr std::size_t max_points = 3000;
// Dots on the candidate's samples while they stay apart.
constexpr std::size_t max_dots = 300;

constexpr const char* exact_color = "#000000";
constexpr const char* candidate_color = "#d95f02";
constexpr const char* tolerance_color = "#1b9e77";
constexpr const char* marker_color = "#7570b3";

PlotLine line(std::string label, const Curve& curve, const char* color, double width) {
  PlotLine l;
  l.label = std::move(label);
  l.x = curve.x;
  l.y = curve.y;
  l.color = color;
  l.width = width;
  return l;
}

// The exact velocity on a fine grid over [start, end], with every phase
// boundary inside it (the kinks of a stop are drawn where they are).
Curve exact_zoom(const ComparisonReport& report, double start, double end) {
  std::vector<double> times;
  constexpr int steps = 600;
  for (int i = 0; i <= steps; ++i) times.push_back(start + (end - start) * i / steps);
  for (const StickInterval& phase : report.exact_phases)
    for (const double t : {phase.start, phase.end})
      if (t > start && t < end) times.push_back(t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  Curve curve;
  for (const State& state : sample_at(report.model, times)) {
    curve.x.push_back(state.t);
    curve.y.push_back(state.v);
  }
  return curve;
}

}  // namespace

ReportFigures report_figures(const ComparisonReport& report, const TimeHistory& history) {
  ReportFigures figures;
  const std::vector<State> at_candidate = sample_at(report.model, history.t);
  const std::vector<double> error = velocity_error(history, at_candidate);

  Plot& velocity = figures.velocity;
  velocity.id = "figure-velocity";
  velocity.title = "Velocity: exact solution and candidate";
  velocity.x_label = "t [time]";
  velocity.y_label = "v [length/time]";
  Curve exact = exact_velocity_curve(report, history, at_candidate);
  if (exact.x.size() > 2 * max_points) exact = decimated(exact.x, exact.y, max_points);
  velocity.lines.push_back(line("exact", exact, exact_color, 2.2));
  velocity.lines.push_back(
      line("candidate", decimated(history.t, history.v, max_points), candidate_color, 1.3));

  Plot& difference = figures.error;
  difference.id = "figure-error";
  difference.title = fmt::format("Velocity error v - v_exact (max {:.6g} at t = {:.6g})",
                                 report.velocity_max_error, report.velocity_max_error_time);
  difference.x_label = "t [time]";
  difference.y_label = "v - v_exact [length/time]";
  difference.lines.push_back(
      line("candidate - exact", decimated(history.t, error, max_points), candidate_color, 1.3));
  const double tolerance = report.options.velocity_max_tolerance * report.scales.velocity;
  difference.horizontal = {
      {tolerance, fmt::format("velocity_max tolerance +-{:.6g}", tolerance), tolerance_color},
      {-tolerance, "", tolerance_color}};
  difference.vertical = {{report.velocity_max_error_time, "largest error", marker_color}};

  Plot& zoom = figures.zoom;
  zoom.id = "figure-zoom";
  zoom.x_label = "t [time]";
  zoom.y_label = "v [length/time]";
  const std::optional<WorstStop> worst = worst_stop(report, history, error);
  if (worst) {
    // The window the stop was judged on, widened to show the candidate's stop too.
    const double half = stop_window(report);
    zoom.x_min = worst->window_start;
    zoom.x_max = worst->window_end;
    if (worst->candidate) {
      zoom.x_min = std::max(report.t_first, std::min(zoom.x_min, *worst->candidate - half));
      zoom.x_max = std::min(report.t_last, std::max(zoom.x_max, *worst->candidate + half));
    }
    zoom.title = fmt::format("Zoom on the worst stop, t = {:.6g} (max |v - v_exact| = {:.6g})",
                             worst->time, worst->error);
    if (worst->exact) {
      zoom.vertical.push_back({worst->time, "exact stop", exact_color});
      figures.zoom_caption = fmt::format("The exact motion stops at t = {}", number(worst->time));
      if (worst->candidate) {
        zoom.vertical.push_back({*worst->candidate, "candidate stop", candidate_color});
        figures.zoom_caption +=
            fmt::format("; the candidate stops at t = {} (matched stick {}, stop time error {}).",
                        number(*worst->candidate), worst->stick_number,
                        number(*worst->candidate - worst->time));
      } else {
        figures.zoom_caption += "; no candidate stick is matched to this stop.";
      }
    } else {
      zoom.vertical.push_back({worst->time, "candidate stop", candidate_color});
      figures.zoom_caption = fmt::format(
          "The candidate stops at t = {} where the exact motion does not (an extra stick).",
          number(worst->time));
    }
    figures.zoom_caption += fmt::format(
        " Of all stops in the record, the candidate's velocity error within +-{} of this one "
        "is the largest: {}.",
        number(stop_window(report)), number(worst->error));
  } else {
    const double half = stop_window(report);
    zoom.x_min = std::max(report.t_first, report.velocity_max_error_time - half);
    zoom.x_max = std::min(report.t_last, report.velocity_max_error_time + half);
    zoom.title =
        fmt::format("Zoom on the largest velocity error, t = {:.6g} (no stop in the record)",
                    report.velocity_max_error_time);
    zoom.vertical.push_back({report.velocity_max_error_time, "largest error", marker_color});
    figures.zoom_caption = fmt::format(
        "The mass does not stop within the record, so this zoom shows the largest velocity "
        "error instead, at t = {}.",
        number(report.velocity_max_error_time));
  }
  zoom.lines.push_back(line("exact", exact_zoom(report, zoom.x_min, zoom.x_max), exact_color, 2.2));
  // The candidate's samples in the window (and one on each side), as they are.
  const auto begin = std::lower_bound(history.t.begin(), history.t.end(), zoom.x_min);
  const auto end = std::upper_bound(begin, history.t.end(), zoom.x_max);
  const std::size_t first = static_cast<std::size_t>(begin - history.t.begin());
  const std::size_t last = static_cast<std::size_t>(end - history.t.begin());
  const std::size_t from = first > 0 ? first - 1 : 0;
  const std::size_t to = std::min(history.t.size(), last + 1);
  Curve samples;
  samples.x.assign(history.t.begin() + from, history.t.begin() + to);
  samples.y.assign(history.v.begin() + from, history.v.begin() + to);
  if (samples.x.size() > 2 * max_points) samples = decimated(samples.x, samples.y, max_points);
  PlotLine candidate = line("candidate", samples, candidate_color, 1.3);
  candidate.dots = last - first <= max_dots;
  zoom.lines.push_back(std::move(candidate));
  zoom.horizontal = {
      {report.stick_velocity, fmt::format("stick threshold +-{:.6g}", report.stick_velocity),
       tolerance_color},
      {-report.stick_velocity, "", tolerance_color}};
  return figures;
}

}  // namespace frictionref::cli
