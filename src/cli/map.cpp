// `frictionref map`: the steady state found by simulation over a grid of two
// model parameters (library: frictionref/parameter_map.hpp), as CSV, with a
// heat map of the stops per period and Den Hartog's non-stop boundary where
// it applies. All cores; a progress line on a terminal.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "count_options.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/den_hartog.hpp"
#include "frictionref/parameter_map.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "progress_line.hpp"
#include "shard_option.hpp"

namespace frictionref::cli {
namespace {

constexpr double max_points = 1e7;
constexpr double max_total_periods = 1e10;  // points * periods: a typo must not run for weeks

struct MapCliOptions {
  ModelOptions model;
  std::string x, y;
  std::string periods = "200";
  std::string threads;
  std::string shard;
  OutputFileOption output;
  std::string plot;
};

std::string spec_text(const MapAxis& axis) {
  return fmt::format("{}:{}:{}:{}", to_string(axis.parameter), axis.from, axis.to, axis.points);
}

void write_table(std::FILE* out, const Model& base, const MapAxis& x, const MapAxis& y,
                 const MapOptions& options, const std::optional<Shard>& shard,
                 const std::vector<MapPoint>& points, const std::string& command) {
  write_metadata(
      out, base, command,
      shard_lines(fmt::format("map: x={} y={} periods={} max_multiplicity={} "
                              "tolerance={} method=simulation",
                              spec_text(x), spec_text(y), options.classify.max_periods,
                              options.classify.max_multiplicity, options.classify.tolerance),
                  shard, x.points * y.points));
  fmt::print(out,
             "{},{},regime,stops_per_period,reversals_per_period,multiplicity,stuck_fraction,"
             "transient_periods\n",
             column_name(x.parameter), column_name(y.parameter));
  for (const MapPoint& p : points)
    fmt::print(out, "{},{},{},{},{},{},{},{}\n", p.x, p.y, to_string(p.regime), p.stops_per_period,
               p.reversals_per_period, p.multiplicity, p.stuck_fraction, p.transient_periods);
}

// Den Hartog's boundary applies to a spring + Coulomb model without damper,
// offset or extra harmonics, on a lambda x frequency-ratio map.
bool boundary_applies(const Model& base, const MapAxis& x, const MapAxis& y) {
  const bool axes =
      (x.parameter == MapParameter::lambda && y.parameter == MapParameter::frequency_ratio) ||
      (x.parameter == MapParameter::frequency_ratio && y.parameter == MapParameter::lambda);
  return axes && base.stiffness > 0 && base.damping == 0 && base.force_offset == 0 &&
         base.harmonics.empty() && base.amplitude > 0;
}

Figure map_figure(const Model& base, const MapAxis& x, const MapAxis& y, const MapOptions& options,
                  const std::vector<MapPoint>& points) {
  Panel panel;
  panel.x_label = std::string(to_string(x.parameter)) + " [1]";
  panel.y_label = std::string(to_string(y.parameter)) + " [1]";
  panel.heat_map.x = x.values();
  panel.heat_map.y = y.values();
  for (const MapPoint& p : points) panel.heat_map.z.push_back(p.stops_per_period);
  panel.heat_map.z_label = "stops per forcing period";
  panel.title = fmt::format("stops per period in the steady state (simulation, up to {} periods)",
                            options.classify.max_periods);
  if (boundary_applies(base, x, y)) {
    // Rs / R of the base model (1 unless a static friction was set).
    const double ratio =
        base.static_friction && base.friction > 0 ? *base.static_friction / base.friction : 1.0;
    Series boundary{"Den Hartog's non-stop boundary", {}, {}, Series::Role::reference};
    const MapAxis& beta_axis = x.parameter == MapParameter::frequency_ratio ? x : y;
    const std::size_t n = std::max<std::size_t>(400, beta_axis.points);
    for (std::size_t i = 0; i < n; ++i) {
      const double beta = beta_axis.from + (beta_axis.to - beta_axis.from) *
                                               static_cast<double>(i) / static_cast<double>(n - 1);
      if (!(beta > 0)) continue;
      const double lambda = den_hartog_boundary(beta, ratio);
      if (x.parameter == MapParameter::lambda) {
        boundary.x.push_back(lambda);
        boundary.y.push_back(beta);
      } else {
        boundary.x.push_back(beta);
        boundary.y.push_back(lambda);
      }
    }
    panel.series.push_back(boundary);
  }
  Figure figure;
  figure.title = "map: " + model_fields(base, number);
  figure.panels = {panel};
  figure.panel_height = 640;
  return figure;
}

void run_map(const MapCliOptions& typed, const Invocation& invocation) {
  const Model base = typed.model.model();
  refuse_ground_motion(base, "map",
                       "it maps steady states, which a record (a transient) does not have "
                       "(newmark runs records x yield accelerations)");
  const auto axis = [](const std::string& spec, const char* option) {
    try {
      return MapAxis::parse(spec, option);
    } catch (const InvalidInput& error) {
      throw bad_input(fmt::format("{} = {}: {}", option, spec, error.rule()));
    }
  };
  const MapAxis x = axis(typed.x, "--x");
  const MapAxis y = axis(typed.y, "--y");
  if (x.parameter == y.parameter)
    throw bad_input(fmt::format("--y = {}: must vary another parameter than --x", typed.y));
  const double total_points = static_cast<double>(x.points) * static_cast<double>(y.points);
  if (total_points > max_points)
    throw bad_input(fmt::format("--y = {}: with --x the map has {:.3g} points, more than 10^7",
                                typed.y, total_points));
  MapOptions options;
  options.classify.max_periods = whole_number({"--periods", typed.periods}, 1e6, "10^6");
  if (options.classify.max_periods < 2)
    throw bad_input(fmt::format("--periods = {}: must be >= 2", typed.periods));
  if (total_points * static_cast<double>(options.classify.max_periods) > max_total_periods)
    throw bad_input(fmt::format(
        "--periods = {}: the map could simulate {:.3g} forcing periods, "
        "more than 10^10",
        typed.periods, total_points * static_cast<double>(options.classify.max_periods)));
  options.threads = thread_count(typed.threads);
  std::optional<Shard> shard;
  if (!typed.shard.empty()) options.shard = *(shard = parse_shard(typed.shard, typed.plot));
  if (!typed.plot.empty()) require_figure_path(typed.plot, "--plot");

  // An axis that cannot apply to this model (frequency-ratio without a
  // spring), or a corner of the grid that makes an invalid model, is named
  // against its axis.
  const auto naming_axes = [&](auto&& f) {
    try {
      return f();
    } catch (const InvalidInput& error) {
      const std::string p = error.parameter();
      const bool on_y = p == "y" || p == std::string(to_string(y.parameter));
      const bool on_x = p == "x" || p == std::string(to_string(x.parameter));
      if (on_x || on_y)
        throw bad_input(fmt::format("{} = {}: {}", on_x ? "--x" : "--y", on_x ? typed.x : typed.y,
                                    error.rule()));
      throw bad_input(
          fmt::format("the map's grid reaches an invalid model at a corner: {} = {}: "
                      "{} (check --x and --y against the model options)",
                      p, error.value(), error.rule()));
    }
  };
  AtomicOutput out(typed.output.path(), "-o");  // a bad -o fails now, not after the run
  std::vector<MapPoint> points;
  {
    ProgressLine progress("map", "points");
    points = naming_axes([&] {
      return parameter_map(base, x, y, options, [&progress](std::size_t done, std::size_t all) {
        progress.update(done, all);
      });
    });
  }
  write_table(out.stream(), base, x, y, options, shard, points, invocation.command_line);
  if (!typed.plot.empty())
    write_figure(map_figure(base, x, y, options, points), typed.plot, "--plot");
  out.commit();
}

}  // namespace

Command add_map_command(CLI::App& app) {
  auto options = std::make_shared<MapCliOptions>();
  CLI::App* command = app.add_subcommand(
      "map", "Steady state over a grid of two model parameters: stops per period and more");
  options->model.add_to(*command, /*friction_required=*/false);
  command->add_option("--x", options->x, "first axis: NAME:FROM:TO:POINTS, e.g. lambda:0:1.2:241")
      ->required()
      ->type_name("SPEC");
  command
      ->add_option("--y", options->y,
                   "second axis: NAME:FROM:TO:POINTS, e.g. frequency-ratio:0.1:3:146")
      ->required()
      ->type_name("SPEC");
  numeric(command->add_option("--periods", options->periods,
                              "forcing periods simulated per point at most; 2 to 10^6"))
      ->type_name("P")
      ->capture_default_str();
  add_threads_option(*command, options->threads);
  add_shard_option(*command, options->shard, "points");
  options->output.add_to(*command);
  command
      ->add_option("--plot", options->plot,
                   "also draw the stops per period as a heat map into FILE (.svg or .png; "
                   "needs gnuplot), with Den Hartog's non-stop boundary where it applies")
      ->type_name("FILE");
  command->footer(
      "For each point of the grid, the model options with the two axis values set, simulated\n"
      "with the exact engine from (x0, v0, t0) period after period of the forcing until the\n"
      "motion repeats (at most --periods periods), and the repeating stretch measured: stops\n"
      "per period (sticks of non-zero duration, not direct reversals), reversals per period,\n"
      "the period multiplicity (0: no repetition found) and the stuck fraction.\n"
      "Axis names: lambda (R = lambda B; a set static friction keeps its ratio Rs/R),\n"
      "static-ratio (Rs = value R), frequency-ratio (w = value sqrt(k/m), needs --stiffness),\n"
      "damping-ratio (c = value 2 sqrt(k m), needs --stiffness), and the fields mass,\n"
      "amplitude, omega, friction, static-friction, stiffness, damping, force-offset, x0, v0.\n"
      "--friction/--lambda are optional here (default R = 0).\n"
      "Output: '# ...' metadata lines, then <x>,<y>,regime,stops_per_period,\n"
      "reversals_per_period,multiplicity,stuck_fraction,transient_periods (x outer).\n"
      "A progress line is shown on a terminal (stderr) when the run takes over a second.\n"
      "--shard I/N computes only the I-th of N contiguous blocks of the points (x outer), with\n"
      "a '# shard:' line; 'frictionref merge' joins the N files into the whole map's table.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref map --x lambda:0:1.2:241 --y frequency-ratio:0.1:3:146 --stiffness 1 "
      "--periods 200 -o map.csv --plot map.png\n"
      "  frictionref map --x lambda:0:1.2:241 --y frequency-ratio:0.1:3:146 --stiffness 1 "
      "--shard 3/8 -o map-3.csv   (then: frictionref merge map-*.csv -o map.csv)\n"
      "  frictionref map --x lambda:0.1:0.9:41 --y damping-ratio:0:0.5:21 --stiffness 1 -o m.csv");
  return {command, [options](const Invocation& invocation) {
            run_map(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
