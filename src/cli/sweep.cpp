// `frictionref sweep`: the regime found by simulation against the regime
// from the threshold lambda*, with the stuck fraction, slide and stops per
// period, for a grid of lambdas (library: frictionref/sweep.hpp). All cores
// by default; a progress line on a terminal for long runs.
#include "frictionref/sweep.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "progress_line.hpp"

namespace frictionref::cli {
namespace {

constexpr double max_lambda = 1e6;  // every lambda >= 1 stops; larger adds nothing
constexpr double max_speed = 1e6;   // |v0| [B/(m w)]
constexpr double max_points = 1e7;  // about 40 bytes of results per point
constexpr double max_threads = 256;
constexpr double max_total_periods = 1e9;    // points * periods: a typo must not run for days
constexpr std::size_t max_plotted = 20'000;  // evenly spaced rows, plus every change

struct SweepCliOptions {
  std::string lambda_from;
  std::string lambda_to;
  std::string points;
  std::string v0 = "0";
  std::string periods = "100";
  std::string threads;  // empty: all cores
  OutputFileOption output;
  std::string plot;
};

double finite_lambda(const TypedNumber& typed) {
  const double value = parse_number(typed);
  if (!std::isfinite(value))
    throw bad_input(fmt::format("{} = {}: must be a finite number", typed.option, typed.text));
  if (!(value >= 0))
    throw bad_input(fmt::format("{} = {}: must be >= 0", typed.option, typed.text));
  if (!(value <= max_lambda))
    throw bad_input(
        fmt::format("{} = {}: must be <= 1e6 (every lambda >= 1 stops)", typed.option, typed.text));
  return value;
}

// The typed decimal in long double (strtold), for the grid's interior
// points; the double `value` (strtod) itself in the rare case where the long
// double would round to another double than strtod's correctly rounded one,
// so the grid's ends are always exactly the numbers as read.
long double precise(const std::string& text, double value) {
  const long double wide = std::strtold(text.c_str(), nullptr);
  return static_cast<double>(wide) == value ? wide : static_cast<long double>(value);
}

// A whole number in [1, max]; "1e5" is fine.
std::uint64_t whole_number(const TypedNumber& typed, double max, const char* max_text) {
  const double value = parse_number(typed);
  if (!(value >= 1) || value != std::floor(value))
    throw bad_input(fmt::format("{} = {}: must be a whole number >= 1", typed.option, typed.text));
  if (!(value <= max))
    throw bad_input(fmt::format("{} = {}: must be <= {}", typed.option, typed.text, max_text));
  return static_cast<std::uint64_t>(value);
}

void write_table(std::FILE* out, const std::vector<SweepPoint>& points, const SweepOptions& options,
                 const std::string& command) {
  const SweepWindow window = sweep_window(options.periods);
  std::size_t differ = 0;
  for (const SweepPoint& p : points) differ += !p.regimes_agree();
  fmt::print(out, "# frictionref {}\n", version);
  fmt::print(out,
             "# model: mass=1 amplitude=1 omega=1 friction=lambda lambda=lambda x0=0 v0={} t0=0\n",
             options.v0);
  fmt::print(out, "# command: {}\n", command);
  fmt::print(out,
             "# sweep: lambda_from={} lambda_to={} points={} periods={} measured_from={} "
             "measured_to={} threshold={}\n",
             points.front().lambda, points.back().lambda, points.size(), options.periods,
             window.begin, window.end, regime_threshold());
  fmt::print(out,
             "# regimes: simulated and threshold differ at {} of {} lambdas (expected only for 0 < "
             "lambda - lambda* <= {:.3g}, dead bands shorter than the engine's time resolution)\n",
             differ, points.size(), sweep_unresolved_distance(options.periods));
  std::fputs(
      "lambda,regime_simulated,regime_threshold,stuck_fraction,slide_per_period,"
      "stops_per_period,reversals_per_period\n",
      out);
  for (const SweepPoint& p : points) {
    fmt::print(out, "{},{},{},{},{},{},{}\n", p.lambda, to_string(p.regime_simulated),
               to_string(p.regime_threshold), p.stuck_fraction, p.slide_per_period,
               p.stops_per_period, p.reversals_per_period);
  }
}

// Stuck fraction and stops per period against lambda, the closed-form steady
// state as the reference line, lambda* dashed. Long sweeps are thinned to
// about max_plotted evenly spaced points plus every point where a count or
// the regime changes, so jumps stay sharp.
Figure sweep_figure(const std::vector<SweepPoint>& points, const SweepOptions& options) {
  const std::size_t n = points.size();
  const std::size_t stride = (n + max_plotted - 1) / max_plotted;
  const auto differs = [&](std::size_t i, std::size_t j) {
    return points[i].stops_per_period != points[j].stops_per_period ||
           points[i].reversals_per_period != points[j].reversals_per_period ||
           points[i].regime_simulated != points[j].regime_simulated;
  };
  // No legend (it would hide the data at the top right, where the stops
  // regime sits): the panel titles say which series is which.
  Series stuck_exact{"", {}, {}, Series::Role::reference};
  Series stuck{"", {}, {}, Series::Role::candidate, true};
  Series stops_exact = stuck_exact;
  Series stops = stuck;
  Series reversals = stuck;
  for (std::size_t i = 0; i < n; ++i) {
    const bool keep = i % stride == 0 || i + 1 == n || (i > 0 && differs(i, i - 1)) ||
                      (i + 1 < n && differs(i, i + 1));
    if (!keep) continue;
    const SweepPoint& p = points[i];
    Model model;
    model.friction = p.lambda;
    const SteadyState steady = steady_state(model);
    stuck_exact.x.push_back(p.lambda);
    stuck_exact.y.push_back(steady.stuck_fraction);
    stuck.x.push_back(p.lambda);
    stuck.y.push_back(p.stuck_fraction);
    stops_exact.x.push_back(p.lambda);
    stops_exact.y.push_back(steady.stops_per_period);
    stops.x.push_back(p.lambda);
    stops.y.push_back(p.stops_per_period);
    reversals.x.push_back(p.lambda);
    reversals.y.push_back(p.reversals_per_period);
  }
  Panel stuck_panel = make_panel(
      fmt::format("fraction of the period at rest: simulated (red points, last of {} periods), "
                  "closed-form steady state (black line)",
                  options.periods),
      "lambda = R / B [1]", "stuck fraction [1]", {stuck_exact, stuck});
  Panel stops_panel = make_panel(
      "per forcing period: stops into rest (red points; closed form: black line), reversals "
      "without rest (blue points)",
      "lambda = R / B [1]", "stops, reversals per period [1]", {stops_exact, stops, reversals});
  const double threshold = regime_threshold();
  const bool marked = !points.empty() && points.front().lambda <= threshold &&
                      threshold <= points.back().lambda &&
                      points.front().lambda < points.back().lambda;
  if (marked) stuck_panel.vertical_lines = stops_panel.vertical_lines = {threshold};
  Figure figure;
  figure.title = fmt::format(
      "sweep: m=B=w=1, v0={}, measured over the last of {} periods; "
      "lambda* = {}{}",
      options.v0, options.periods, threshold, marked ? " (dashed)" : "");
  figure.panels = {stuck_panel, stops_panel};
  return figure;
}

void run_sweep(const SweepCliOptions& typed, const Invocation& invocation) {
  const double from = finite_lambda({"--lambda-from", typed.lambda_from});
  const double to = finite_lambda({"--lambda-to", typed.lambda_to});
  if (!(to >= from))
    throw bad_input(fmt::format("--lambda-to = {}: must be >= --lambda-from = {}", typed.lambda_to,
                                typed.lambda_from));
  const std::uint64_t points = whole_number({"--points", typed.points}, max_points, "10^7");
  if (points == 1 && to != from)
    throw bad_input(fmt::format("--points = {}: a single lambda needs --lambda-to = --lambda-from",
                                typed.points));
  if (points > 1 && to == from)
    throw bad_input(
        fmt::format("--points = {}: must be 1 when --lambda-from = --lambda-to", typed.points));
  SweepOptions options;
  options.periods = whole_number({"--periods", typed.periods},
                                 static_cast<double>(SweepOptions::max_periods), "10^6");
  const double total = static_cast<double>(points) * static_cast<double>(options.periods);
  if (total > max_total_periods)
    throw bad_input(
        fmt::format("--periods = {}: with --points = {} the sweep would simulate {:.3g} "
                    "forcing periods, more than 10^9",
                    typed.periods, typed.points, total));
  if (!typed.threads.empty())
    options.threads =
        static_cast<unsigned>(whole_number({"--threads", typed.threads}, max_threads, "256"));
  options.v0 = parse_number({"--v0", typed.v0});
  if (!std::isfinite(options.v0))
    throw bad_input(fmt::format("--v0 = {}: must be a finite number", typed.v0));
  if (!(std::fabs(options.v0) <= max_speed))
    throw bad_input(fmt::format("--v0 = {}: must satisfy |v0| <= 1e6 (in B/(m w))", typed.v0));
  if (!typed.plot.empty()) require_figure_path(typed.plot, "--plot");

  const TypedInputs inputs{{"lambda_from", {"--lambda-from", typed.lambda_from}},
                           {"lambda_to", {"--lambda-to", typed.lambda_to}},
                           {"lambda", {"--lambda-to", typed.lambda_to}},
                           {"points", {"--points", typed.points}},
                           {"periods", {"--periods", typed.periods}},
                           {"v0", {"--v0", typed.v0}}};
  const std::vector<double> lambdas = naming_options(inputs, [&] {
    return sweep_grid(precise(typed.lambda_from, from), precise(typed.lambda_to, to), points);
  });

  AtomicOutput out(typed.output.path(), "-o");  // a bad -o fails now, not after the run
  std::vector<SweepPoint> results;
  {
    ProgressLine progress("sweep", "lambdas");
    results = naming_options(inputs, [&] {
      return sweep(lambdas, options,
                   [&progress](std::size_t done, std::size_t all) { progress.update(done, all); });
    });
  }
  for (const SweepPoint& p : results) {
    if (p.termination != Termination::reached_end)
      throw internal_error(fmt::format("the engine stopped early ({}) at lambda = {}",
                                       to_string(p.termination), p.lambda));
  }
  write_table(out.stream(), results, options, invocation.command_line);
  if (!typed.plot.empty()) write_figure(sweep_figure(results, options), typed.plot, "--plot");
  out.commit();
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto options = std::make_shared<SweepCliOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Simulated regime against the threshold's, stuck fraction and stops per period, "
      "for a grid of lambdas");
  numeric(command->add_option("--lambda-from", options->lambda_from,
                              "first lambda = R / B [1]; finite, >= 0"))
      ->required()
      ->type_name("A");
  numeric(command->add_option("--lambda-to", options->lambda_to,
                              "last lambda [1]; >= --lambda-from, <= 1e6"))
      ->required()
      ->type_name("B");
  numeric(command->add_option(
              "--points", options->points,
              "number of lambdas, evenly spaced from A to B; 1 to 10^7 (1 needs A = B)"))
      ->required()
      ->type_name("N");
  numeric(command->add_option("--v0", options->v0,
                              "initial velocity of every run [B/(m w)]; |v0| <= 1e6"))
      ->type_name("V")
      ->capture_default_str();
  numeric(command->add_option("--periods", options->periods,
                              "forcing periods simulated per lambda, the last one measured; "
                              "1 to 10^6, points x periods <= 10^9"))
      ->type_name("P")
      ->capture_default_str();
  numeric(command->add_option("--threads", options->threads,
                              "worker threads; 1 to 256 (default: all cores)"))
      ->type_name("N");
  options->output.add_to(*command);
  command
      ->add_option("--plot", options->plot,
                   "also draw stuck fraction and stops per period against lambda, lambda* "
                   "dashed, into FILE (.svg or .png; needs gnuplot)")
      ->type_name("FILE");
  command->footer(
      "For each lambda, runs the exact engine with m = B = w = 1, R = lambda, x0 = t0 = 0 and\n"
      "v0 from t = 0 to 2 pi P + pi/2 and measures the last period (from force maximum to force\n"
      "maximum): the regime the simulation shows (stops: at rest for good; dead-bands: at rest\n"
      "part of the period; continuous: never at rest), the regime from the threshold\n"
      "lambda* = 2 / sqrt(4 + pi^2) = 0.5370293, the fraction of the period at rest, the\n"
      "distance slid, the stops (v = 0 and rest) and the reversals (v = 0, no rest).\n"
      "The two regimes agree except just above lambda*, within 2.7e-15 P, where the dead band\n"
      "is shorter than the engine's time resolution (docs/cli.md).\n"
      "Output: '# ...' metadata lines, then lambda,regime_simulated,regime_threshold,\n"
      "stuck_fraction,slide_per_period [B/(m w^2)],stops_per_period,reversals_per_period.\n"
      "A progress line is shown on a terminal (stderr) when the run takes over a second.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 3 internal error.\n"
      "Examples:\n"
      "  frictionref sweep --lambda-from 0 --lambda-to 1.2 --points 1201 -o sweep.csv --plot "
      "sweep.svg\n"
      "  frictionref sweep --lambda-from 0.5 --lambda-to 0.6 --points 101 --periods 1000 --v0 1");
  return {command, [options](const Invocation& invocation) {
            run_sweep(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
