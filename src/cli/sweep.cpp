// `frictionref sweep`: the regime found by simulation against the regime a
// closed form gives (the threshold lambda* for the seed's model, Den Hartog's
// non-stop solution for a spring without damper, none otherwise), with the
// stuck fraction, slide and stops per period, for a grid of lambdas and any
// model (library: frictionref/sweep.hpp). All cores by default; a progress
// line on a terminal for long runs.
#include "frictionref/sweep.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "count_options.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/den_hartog.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "model_title.hpp"
#include "progress_line.hpp"
#include "shard_option.hpp"
#include "sweep_summary.hpp"

namespace frictionref::cli {
namespace {

constexpr double max_lambda = 1e6;           // every lambda >= 1 stops; larger adds nothing
constexpr double max_speed = 1e6;            // |v0| [B/(m w)]
constexpr double max_static_ratio = 1e6;     // Rs / R
constexpr double max_points = 1e7;           // about 40 bytes of results per point
constexpr double max_total_periods = 1e9;    // points * periods: a typo must not run for days
constexpr std::size_t max_plotted = 20'000;  // evenly spaced rows, plus every change

struct SweepCliOptions {
  // The model of every run but its friction (R = lambda B, Rs = ratio R) and
  // start time (t = 0): --mass ... --harmonic, --x0, --v0.
  ModelOptions model;
  std::string lambda_from;
  std::string lambda_to;
  std::string points;
  std::string static_ratio = "1";
  std::string periods = "100";
  std::string threads;  // empty: all cores
  std::string shard;    // empty: the whole sweep
  OutputFileOption output;
  std::string plot;
  // Model options that the sweep sets itself: registered out of the help
  // only to say so when one is given.
  struct Refused {
    std::string name, value;
    CLI::Option* option = nullptr;
  };
  std::vector<Refused> refused;
};

// "--lambda 0.3" on a sweep: why it is not taken, and what to use instead.
void refuse_fixed_options(const SweepCliOptions& typed) {
  for (const SweepCliOptions::Refused& option : typed.refused) {
    if (option.option->count() == 0) continue;
    const std::string& name = option.name;
    // "--lambda = 0.3", or "--lambda" when given without a value.
    const std::string given = option.value.empty() ? name : name + " = " + option.value;
    if (name == "--t0") throw bad_input(given + ": not a sweep option; every run starts at t = 0");
    if (name == "--friction" || name == "--lambda")
      throw bad_input(given +
                      ": not a sweep option; the sweep sets R = lambda B for lambda from "
                      "--lambda-from to --lambda-to");
    throw bad_input(given +
                    ": not a sweep option; the sweep sets Rs = S R at every lambda, S from "
                    "--static-ratio");
  }
}

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

// The model line: the base model with the friction as a function of each
// row's lambda. The seed's line (m = B = w = 1, no general term) is the one
// the sweep always wrote.
std::string model_line(const SweepOptions& options) {
  const Model& base = options.base;
  const std::string friction =
      base.amplitude == 1 ? std::string("lambda") : fmt::format("lambda*{}", base.amplitude);
  std::string fields = fmt::format("mass={} amplitude={} omega={} friction={} lambda=lambda",
                                   base.mass, base.amplitude, base.omega, friction);
  if (options.static_ratio != 1)
    fields += fmt::format(" static_friction={}*friction", options.static_ratio);
  if (base.stiffness != 0) fields += fmt::format(" stiffness={}", base.stiffness);
  if (base.damping != 0) fields += fmt::format(" damping={}", base.damping);
  if (base.force_offset != 0) fields += fmt::format(" force_offset={}", base.force_offset);
  for (const Harmonic& h : base.harmonics)
    fields += fmt::format(" harmonic={},{},{}", h.amplitude, h.omega, h.phase);
  return fields + fmt::format(" x0={} v0={} t0=0", base.x0, options.v0);
}

// Den Hartog's frequency ratio beta = w / sqrt(k / m) of the base model.
double frequency_ratio(const Model& base) {
  return base.omega / std::sqrt(base.stiffness / base.mass);
}

std::string regime_text(const SweepPoint& p) {
  return p.regime_threshold ? std::string(to_string(*p.regime_threshold)) : std::string("n/a");
}

// `grid` is the whole sweep's lambdas and `points` the computed ones (a
// shard's block of them, or all).
void write_table(std::FILE* out, const std::vector<double>& grid,
                 const std::vector<SweepPoint>& points, const SweepOptions& options,
                 const std::optional<Shard>& shard, const std::string& command) {
  const SweepWindow window = sweep_window(options.periods, options.base);
  const SweepThreshold rule = sweep_threshold_rule(options);
  RegimeCounts counts;
  for (const SweepPoint& p : points) {
    ++counts.rows;
    counts.differ += p.regimes_differ();
    counts.known += p.regime_threshold.has_value();
  }
  fmt::print(out, "# frictionref {}\n", version);
  fmt::print(out, "# model: {}\n", model_line(options));
  fmt::print(out, "# command: {}\n", command);
  std::string threshold;
  if (rule == SweepThreshold::lambda_star) {
    threshold = fmt::format("{}", regime_threshold());
  } else if (rule == SweepThreshold::den_hartog) {
    const double beta = frequency_ratio(options.base);
    threshold = fmt::format("den-hartog frequency_ratio={} den_hartog_boundary={}", beta,
                            den_hartog_boundary(beta, options.static_ratio));
  } else {
    threshold = "none";
  }
  const std::vector<std::string> lines = shard_lines(
      fmt::format("sweep: lambda_from={} lambda_to={} points={} periods={} measured_from={} "
                  "measured_to={} threshold={}",
                  grid.front(), grid.back(), grid.size(), options.periods, window.begin, window.end,
                  threshold),
      shard, grid.size());
  for (const std::string& line : lines) fmt::print(out, "# {}\n", line);
  // Of this file's rows (a shard's: merge recomputes it for the whole sweep).
  fmt::print(out, "# {}\n", regimes_line(rule, counts, options.periods));
  std::fputs(
      "lambda,regime_simulated,regime_threshold,stuck_fraction,slide_per_period,"
      "stops_per_period,reversals_per_period\n",
      out);
  for (const SweepPoint& p : points) {
    fmt::print(out, "{},{},{},{},{},{},{}\n", p.lambda, to_string(p.regime_simulated),
               regime_text(p), p.stuck_fraction, p.slide_per_period, p.stops_per_period,
               p.reversals_per_period);
  }
}

// Stuck fraction and stops per period against lambda, the closed-form steady
// state as the reference line (the seed's model only), lambda* (or Den
// Hartog's boundary) dashed. Long sweeps are thinned to about max_plotted
// evenly spaced points plus every point where a count or the regime changes,
// so jumps stay sharp.
Figure sweep_figure(const std::vector<SweepPoint>& points, const SweepOptions& options) {
  const SweepThreshold rule = sweep_threshold_rule(options);
  const bool seed = rule == SweepThreshold::lambda_star;
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
    if (seed) {
      // The seed's steady state depends on lambda alone.
      Model model;
      model.friction = p.lambda;
      const SteadyState steady = steady_state(model);
      stuck_exact.x.push_back(p.lambda);
      stuck_exact.y.push_back(steady.stuck_fraction);
      stops_exact.x.push_back(p.lambda);
      stops_exact.y.push_back(steady.stops_per_period);
    }
    stuck.x.push_back(p.lambda);
    stuck.y.push_back(p.stuck_fraction);
    stops.x.push_back(p.lambda);
    stops.y.push_back(p.stops_per_period);
    reversals.x.push_back(p.lambda);
    reversals.y.push_back(p.reversals_per_period);
  }
  std::vector<Series> stuck_series{stuck}, stops_series{stops, reversals};
  if (seed) {
    stuck_series.insert(stuck_series.begin(), stuck_exact);
    stops_series.insert(stops_series.begin(), stops_exact);
  }
  Panel stuck_panel = make_panel(
      seed ? fmt::format("fraction of the period at rest: simulated (red points, last of {} "
                         "periods), closed-form steady state (black line)",
                         options.periods)
           : fmt::format("fraction of the period at rest: simulated (red points, last of {} "
                         "periods)",
                         options.periods),
      "lambda = R / B [1]", "stuck fraction [1]", stuck_series);
  Panel stops_panel = make_panel(
      seed ? "per forcing period: stops into rest (red points; closed form: black line), "
             "reversals without rest (blue points)"
           : "per forcing period: stops into rest (red points), reversals without rest (blue "
             "points)",
      "lambda = R / B [1]", "stops, reversals per period [1]", stops_series);
  double line = std::numeric_limits<double>::quiet_NaN();
  std::string line_name;
  if (seed) {
    line = regime_threshold();
    line_name = fmt::format("lambda* = {}", line);
  } else if (rule == SweepThreshold::den_hartog) {
    line = den_hartog_boundary(frequency_ratio(options.base), options.static_ratio);
    line_name = fmt::format("Den Hartog's non-stop boundary lambda = {}", line);
  }
  const bool marked = !points.empty() && points.front().lambda <= line &&
                      line <= points.back().lambda && points.front().lambda < points.back().lambda;
  if (marked) stuck_panel.vertical_lines = stops_panel.vertical_lines = {line};
  const Model& base = options.base;
  const bool unit = base.mass == 1 && base.amplitude == 1 && base.omega == 1 && base.x0 == 0;
  Figure figure;
  if (seed && unit) {
    figure.title = fmt::format(
        "sweep: m=B=w=1, v0={}, measured over the last of {} periods; "
        "{}{}",
        options.v0, options.periods, line_name, marked ? " (dashed)" : "");
  } else {
    Model shown = base;
    shown.friction = 0;  // each row's lambda B
    if (options.static_ratio != 1) shown.static_friction = 0;
    shown.v0 = options.v0;
    std::string title = model_title(shown);
    // "R=0 (lambda=0)" stands for every row's friction.
    const std::string fixed = fmt::format("R=0 (lambda=0)");
    const std::size_t at = title.find(fixed);
    if (at != std::string::npos) title.replace(at, fixed.size(), "R=lambda B");
    const std::string rs = " Rs=0";
    const std::size_t rs_at = title.find(rs);
    if (rs_at != std::string::npos)
      title.replace(rs_at, rs.size(), fmt::format(" Rs={} R", options.static_ratio));
    figure.title =
        fmt::format("sweep: {}, measured over the last of {} periods{}{}", title, options.periods,
                    line_name.empty() ? "" : "; ", line_name + (marked ? " (dashed)" : ""));
  }
  figure.panels = {stuck_panel, stops_panel};
  return figure;
}

void run_sweep(const SweepCliOptions& typed, const Invocation& invocation) {
  refuse_fixed_options(typed);
  // The model options first: the same rules and messages as every command.
  const Model model = typed.model.model();
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
  options.threads = thread_count(typed.threads);
  options.v0 = model.v0;
  options.base = model;
  options.base.v0 = 0;
  options.static_ratio = parse_number({"--static-ratio", typed.static_ratio});
  // NaN and inf get the library's finite rule below.
  if (std::isfinite(options.static_ratio) && !(options.static_ratio <= max_static_ratio))
    throw bad_input(fmt::format("--static-ratio = {}: must be <= 1e6", typed.static_ratio));

  TypedInputs inputs = typed.model.typed_inputs();
  inputs["lambda_from"] = {"--lambda-from", typed.lambda_from};
  inputs["lambda_to"] = {"--lambda-to", typed.lambda_to};
  inputs["lambda"] = {"--lambda-to", typed.lambda_to};
  inputs["friction"] = {"--lambda-to", typed.lambda_to};  // R = lambda B beyond double
  inputs["static_ratio"] = {"--static-ratio", typed.static_ratio};
  inputs["static_friction"] = {"--static-ratio", typed.static_ratio};
  inputs["points"] = {"--points", typed.points};
  inputs["periods"] = {"--periods", typed.periods};
  naming_options(inputs, [&] { options.validate(); });
  // |v0| in the velocity unit B/(m w) of the forcing (the seed's 1e6).
  const double speed_unit = model.amplitude / (model.mass * model.omega);
  if (!(std::fabs(options.v0) <= max_speed * speed_unit))
    throw bad_input(
        fmt::format("--v0 = {}: must satisfy |v0| <= 1e6 (in B/(m w))", inputs.at("v0").text));
  std::optional<Shard> shard;
  if (!typed.shard.empty()) shard = parse_shard(typed.shard, typed.plot);
  if (!typed.plot.empty()) require_figure_path(typed.plot, "--plot");

  const std::vector<double> grid = naming_options(inputs, [&] {
    return sweep_grid(precise(typed.lambda_from, from), precise(typed.lambda_to, to), points);
  });
  // A shard runs its block of the grid; each lambda's run does not depend on the others.
  const Shard::Range block = shard ? shard->range(grid.size()) : Shard::Range{0, grid.size()};
  const std::vector<double> lambdas(grid.begin() + static_cast<std::ptrdiff_t>(block.begin),
                                    grid.begin() + static_cast<std::ptrdiff_t>(block.end));

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
  write_table(out.stream(), grid, results, options, shard, invocation.command_line);
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
  numeric(command->add_option("--static-ratio", options->static_ratio,
                              "static friction Rs = S * R at every lambda [1]; 1 to 1e6"))
      ->type_name("S")
      ->capture_default_str();
  numeric(command->add_option("--periods", options->periods,
                              "forcing periods simulated per lambda, the last one measured; "
                              "1 to 10^6, points x periods <= 10^9"))
      ->type_name("P")
      ->capture_default_str();
  add_threads_option(*command, options->threads);
  add_shard_option(*command, options->shard, "lambdas");
  options->output.add_to(*command);
  command
      ->add_option("--plot", options->plot,
                   "also draw stuck fraction and stops per period against lambda, lambda* "
                   "(or Den Hartog's boundary) dashed, into FILE (.svg or .png; needs gnuplot)")
      ->type_name("FILE");
  // Every model option but the friction (each row sets R = lambda B and
  // Rs = S R) and the start time (every run starts at t = 0).
  ModelOptions::Selection selection;
  selection.friction = false;
  selection.static_friction = false;
  selection.t0 = false;
  options->model.add_to(*command, /*friction_required=*/false, selection);
  for (const char* name :
       {"--friction", "--lambda", "--static-friction", "--static-lambda", "--t0"})
    options->refused.push_back({name, "", nullptr});
  // Bound after the vector is complete: the strings stay where they are.
  for (SweepCliOptions::Refused& refused : options->refused)
    refused.option = command->add_option(refused.name, refused.value)->group("")->expected(0, 1);
  command->footer(
      "For each lambda, runs the exact engine on the model with R = lambda B and Rs = S R\n"
      "(S = --static-ratio), from x0, v0 at t = 0 to P T + pi/(2 w), T the forcing period\n"
      "(2 pi / w with one harmonic), and measures the last period T (from force maximum to force\n"
      "maximum): the regime the simulation shows (stops: at rest for good; dead-bands: at rest\n"
      "part of the period; continuous: never at rest), the fraction of the period at rest, the\n"
      "distance slid, the stops (v = 0 and rest) and the reversals (v = 0, no rest).\n"
      "regime_threshold is the regime a closed form gives, where one does:\n"
      "  the seed's model (no spring, damper, offset, extra harmonic; S = 1; any m, B, w):\n"
      "    by lambda* = 2 / sqrt(4 + pi^2) = 0.5370293; the two regimes agree except just above\n"
      "    lambda*, within 2.7e-15 P, where the dead band is shorter than the engine's time\n"
      "    resolution (docs/cli.md);\n"
      "  a spring without damper, offset or extra harmonic (any S): 'continuous' where Den\n"
      "    Hartog's non-stop solution exists and is stable (as classify), else n/a;\n"
      "  any other model: n/a.\n"
      "The model options are those of every command except --friction/--lambda, "
      "--static-friction/\n"
      "--static-lambda (the sweep sets R and Rs) and --t0 (runs start at t = 0); B must be > 0.\n"
      "Output: '# ...' metadata lines (the whole model), then lambda,regime_simulated,\n"
      "regime_threshold,stuck_fraction,slide_per_period [length],stops_per_period,\n"
      "reversals_per_period.\n"
      "--shard I/N runs only the I-th of N contiguous blocks of the lambdas, with a '# shard:'\n"
      "line; 'frictionref merge' joins the N files into the whole sweep's table.\n"
      "A progress line is shown on a terminal (stderr) when the run takes over a second.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref sweep --lambda-from 0 --lambda-to 1.2 --points 1201 -o sweep.csv --plot "
      "sweep.svg\n"
      "  frictionref sweep --lambda-from 0.5 --lambda-to 0.6 --points 101 --periods 1000 --v0 1\n"
      "  # a spring, w = 2 sqrt(k/m): Den Hartog's boundary against the simulation\n"
      "  frictionref sweep --lambda-from 0 --lambda-to 1 --points 101 --stiffness 1 --omega 2\n"
      "  # static friction 1.5 times the sliding friction, a damper and a second harmonic\n"
      "  frictionref sweep --lambda-from 0 --lambda-to 1 --points 101 --static-ratio 1.5 "
      "--stiffness 1 --damping 0.1 --harmonic 0.3,3");
  return {command, [options](const Invocation& invocation) {
            run_sweep(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
