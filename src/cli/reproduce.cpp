// `frictionref reproduce`: the three cases of the seed problem (NRC problem 7,
// figures 10.1-10.3), each into its own folder, with a summary on stdout.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "atomic_output.hpp"
#include "classify.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "curve.hpp"
#include "events.hpp"
#include "figure.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/stiff_spring.hpp"
#include "stiff.hpp"
#include "frictionref/version.hpp"

namespace frictionref::cli {
namespace {

namespace fs = std::filesystem;

struct SeedCase {
  const char* id;  // the seed's figure number
  double lambda;   // R / B
  double v0;
  const char* title;     // the seed figure's title and subtitle, as printed there
  const char* subtitle;
};

// m = B = w = 1, t0 = 0; the seed plots these to t = 30. Also data/seed-cases.csv.
constexpr SeedCase seed_cases[] = {
    {"10.1", 0.3, 0.0, "Oscillating mass with friction R/F=.3 No Dead Bands",
     "Velocity of mass vs time (initial velocity =0.)"},
    {"10.2", 0.7, 0.0, "Oscillating mass with friction R/F=.7 Dead Bands Present",
     "Velocity of mass vs time (initial velocity = 0.)"},
    {"10.3", 1.01, -1.0, "Oscillating mass with friction R/F=1.01 mass eventually stops",
     "Velocity of mass vs time (initial velocity = -1.)"}};
constexpr double seed_t_end = 30;
constexpr double seed_dt = 0.01;
// The seed's friction spring (DYNARACK input, "K_f = 1 x 10^7") with the
// default (automatic) time step and the seed's archive step.
constexpr double seed_kf = 1e7;

struct ReproduceOptions {
  std::string out = "frictionref-results";
  bool no_figures = false;
};

StiffSpringOptions seed_stiff_options() {
  StiffSpringOptions options;
  options.kf = seed_kf;
  options.output_dt = seed_dt;
  return options;
}

Model seed_model(const SeedCase& seed) {
  Model model;
  model.friction = seed.lambda * model.amplitude;
  model.v0 = seed.v0;
  return model;
}

GridOptions seed_grid() {
  GridOptions grid;
  grid.t_end = seed_t_end;
  grid.dt = seed_dt;
  grid.include_events = true;
  return grid;
}

// One case, ready to write: building the engine, the sampler and the steady
// state validates everything, for all cases before the first file exists.
struct PreparedCase {
  explicit PreparedCase(const SeedCase& seed_case)
      : seed(seed_case),
        model(seed_model(seed_case)),
        engine(model, seed_t_end),
        sampler(model, seed_grid()),
        stiff(model, seed_t_end, seed_stiff_options()),
        steady(steady_state(model)) {}

  SeedCase seed;
  Model model;
  ExactEngine engine;
  UniformSampler sampler;
  StiffSpringSimulator stiff;
  SteadyState steady;
};

// What a case produced, for the summary line.
struct CaseResult {
  Summary events;
  ComparisonReport comparison;
  std::vector<std::string> figures;
};

void write_file(const fs::path& path, const std::function<void(std::FILE*)>& write) {
  AtomicOutput out(path.string(), "--out");
  write(out.stream());
  out.commit();
}

// The seed's figure: exact velocity (thick black) and the stiff-spring
// velocity overlaid, titled as in the seed.
Figure velocity_figure(const SeedCase& seed, const std::vector<State>& exact,
                       const TimeHistory& stiff) {
  Series exact_series{"exact (frictionref)", {}, {}, Series::Role::reference};
  for (const State& state : exact) {
    exact_series.x.push_back(state.t);
    exact_series.y.push_back(state.v);
  }
  Series stiff_series{fmt::format("stiff spring Kf = {:g}, central differences", seed_kf),
                      stiff.t, stiff.v, Series::Role::candidate};
  Figure figure;
  figure.title = fmt::format("Figure {} reproduced: {}", seed.id, seed.title);
  figure.panels.push_back(make_panel(seed.subtitle, "t [time]  (m = B = w = 1)",
                                     "v [length/time]", {exact_series, stiff_series}));
  return figure;
}

// Case 10.3 after the stop: the exact mass is at rest, the stiff-spring mass
// rings on its spring: the residual velocity the seed mentions. Two panels:
// from the stop on, and the last third, where the ringing has settled.
Figure residual_figure(const SeedCase& seed, double stop_time, const TimeHistory& stiff) {
  const auto panel = [&](double from, const std::string& title) {
    Series exact_series{"exact (frictionref): at rest, v = 0", {}, {}, Series::Role::reference};
    Series stiff_series{fmt::format("stiff spring Kf = {:g}: residual velocity", seed_kf), {}, {},
                        Series::Role::candidate};
    for (std::size_t i = 0; i < stiff.t.size(); ++i) {
      if (stiff.t[i] < from) continue;
      stiff_series.x.push_back(stiff.t[i]);
      stiff_series.y.push_back(stiff.v[i]);
      exact_series.x.push_back(stiff.t[i]);
      exact_series.y.push_back(0);
    }
    return make_panel(title, "t [time]", "v [length/time]", {exact_series, stiff_series});
  };
  Figure figure;
  figure.title = fmt::format("Figure {} after the stop at t = {:.6f}: the finite friction spring "
                             "leaves a residual velocity",
                             seed.id, stop_time);
  figure.panels.push_back(panel(stop_time, seed.subtitle + std::string(", from the stop on")));
  figure.panels.push_back(panel(2 * seed_t_end / 3, "the same, last third of the record"));
  return figure;
}

// Writes events.csv, curve.csv, classify.json, stiff.csv, compare.txt and
// (unless no_figures) the figures into `dir`.
CaseResult write_case(PreparedCase& prepared, const fs::path& dir, const std::string& command,
                      bool figures) {
  const SeedCase& seed = prepared.seed;
  const std::string case_line = fmt::format("case: {} (seed problem 7, figure {}) lambda={} v0={}",
                                            seed.id, seed.id, seed.lambda, seed.v0);
  CaseResult result;
  write_file(dir / "events.csv", [&](std::FILE* file) {
    result.events = write_events_csv(file, prepared.engine, command,
                                     {case_line, fmt::format("horizon: t_end={}", seed_t_end)});
    require_reached_end(result.events);
  });
  FigureSamples exact(seed_grid().grid_rows(prepared.model.t0));
  write_file(dir / "curve.csv", [&](std::FILE* file) {
    require_reached_end(write_curve_csv(file, prepared.model, prepared.sampler, command,
                                        {case_line, grid_metadata(prepared.model, seed_grid())},
                                        [&](const State& state) { exact.add(state); }));
  });
  write_file(dir / "classify.json", [&](std::FILE* file) {
    nlohmann::ordered_json json;
    json["case"] = seed.id;
    json.update(classify_json(prepared.model, prepared.steady));
    fmt::print(file, "{}\n", json.dump(2));
  });
  TimeHistory stiff;
  stiff.source = (dir / "stiff.csv").string();
  write_file(dir / "stiff.csv", [&](std::FILE* file) {
    write_stiff_csv(file, prepared.stiff, command, {case_line}, [&](const StiffSample& sample) {
      stiff.t.push_back(sample.t);
      stiff.v.push_back(sample.v);
    });
  });
  result.comparison = compare(prepared.model, stiff);
  write_file(dir / "compare.txt", [&](std::FILE* file) {
    fmt::print(file, "# {}\n# {}\n{}", command, case_line, result.comparison.full_report());
  });
  if (!figures) return result;

  const Figure velocity = velocity_figure(seed, exact.states(), stiff);
  for (const char* extension : {"svg", "png"}) {
    const fs::path path = dir / fmt::format("velocity.{}", extension);
    write_figure(velocity, path.string(), "--out");
    result.figures.push_back(path.string());
  }
  // The case that stops for good: a zoom on what the finite spring leaves.
  if (prepared.steady.regime == Regime::stops && result.events.stops > 0) {
    // The event row where the last slip ends (curve rows include events).
    double stop_time = 0;
    PhaseKind previous = PhaseKind::stick;
    for (const State& state : exact.states()) {
      if (state.phase == PhaseKind::stick && previous != PhaseKind::stick) stop_time = state.t;
      previous = state.phase;
    }
    const Figure residual = residual_figure(seed, stop_time, stiff);
    for (const char* extension : {"svg", "png"}) {
      const fs::path path = dir / fmt::format("residual-velocity.{}", extension);
      write_figure(residual, path.string(), "--out");
      result.figures.push_back(path.string());
    }
  }
  return result;
}

void run_reproduce(const ReproduceOptions& options, const Invocation& invocation) {
  if (!options.no_figures && !gnuplot_available()) {
    throw bad_input(
        "--out = " + options.out +
        ": the figures need gnuplot, which was not found on PATH (Debian: apt-get install "
        "gnuplot-nox); pass --no-figures to write the tables only");
  }
  std::vector<std::unique_ptr<PreparedCase>> cases;
  for (const SeedCase& seed : seed_cases) cases.push_back(std::make_unique<PreparedCase>(seed));

  // Every folder exists before anything is printed or written.
  std::vector<fs::path> dirs;
  for (const auto& prepared : cases) {
    const SeedCase& seed = prepared->seed;
    dirs.push_back(fs::path(options.out) /
                   fmt::format("case-{}-lambda-{}", seed.id, seed.lambda));
    std::error_code error;
    fs::create_directories(dirs.back(), error);
    if (error) {
      throw bad_input(fmt::format("--out = {}: cannot create {}: {}", options.out,
                                  dirs.back().string(), error.message()));
    }
  }

  AtomicOutput summary(std::nullopt, "");
  fmt::print(summary.stream(),
             "# frictionref {} reproduce: seed problem 7, m=1 B=1 w=1 t0=0 t_end={} dt={}; "
             "stiff spring K_f={:g} (central differences) checked by compare\n",
             version, seed_t_end, seed_dt, seed_kf);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& prepared = cases[k];
    const SeedCase& seed = prepared->seed;
    const fs::path& dir = dirs[k];
    const CaseResult result = write_case(*prepared, dir, invocation.command_line,
                                         !options.no_figures);
    const Summary& events = result.events;
    const State& end = events.final_state;
    fmt::print(summary.stream(),
               "case {}: lambda={} v0={} regime={} stick={} slip+={} slip-={} stops={} "
               "reversals={} t={} x={} v={} stiff_vs_exact={} dir={}\n",
               seed.id, seed.lambda, seed.v0, to_string(prepared->steady.regime),
               events.count(PhaseKind::stick), events.count(PhaseKind::slip_forward),
               events.count(PhaseKind::slip_backward), events.stops, events.reversals, end.t, end.x,
               end.v, to_string(result.comparison.verdict), dir.string());
    for (const std::string& figure : result.figures)
      fmt::print(summary.stream(), "  figure: {}\n", figure);
  }
  summary.commit();
}

}  // namespace

Command add_reproduce_command(CLI::App& app) {
  auto options = std::make_shared<ReproduceOptions>();
  CLI::App* command = app.add_subcommand(
      "reproduce", "The seed problem's three cases (lambda = 0.3, 0.7, 1.01) into files");
  command
      ->add_option("--out", options->out,
                   "output directory (created if missing; existing case files are replaced)")
      ->type_name("DIR")
      ->capture_default_str();
  command->add_flag("--no-figures", options->no_figures,
                    "write the tables and reports only (no gnuplot needed)");
  command->footer(
      "Computes the three cases of the seed problem (NRC problem 7, figures 10.1-10.3) with\n"
      "m = B = w = 1, t0 = 0, T = 30: lambda = 0.3 and 0.7 from rest, lambda = 1.01 with\n"
      "v0 = -1. Writes DIR/case-<figure>-lambda-<lambda>/ with the exact solution (events.csv,\n"
      "curve.csv with dt = 0.01 and event rows, classify.json), the seed's stiff-spring model\n"
      "(stiff.csv: K_f = 1e7, central differences, archived every 0.01), its check against the\n"
      "exact solution (compare.txt, as `frictionref compare`), and the seed's figure with both\n"
      "velocities (velocity.svg/.png; for 10.3 also residual-velocity.svg/.png, the zoom after\n"
      "the stop). Prints one summary line per case and where the figures are.\n"
      "Takes no model options: the cases are fixed.\n"
      "Exit codes: 0 ok, 2 bad input or unwritable DIR (one line on stderr), 4 internal error.\n"
      "Example:\n"
      "  frictionref reproduce --out results && head results/case-10.2-lambda-0.7/events.csv");
  return {command,
          [options](const Invocation& invocation) {
            run_reproduce(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
