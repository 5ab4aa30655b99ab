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
#include "frictionref/steady_state.hpp"
#include "frictionref/version.hpp"

namespace frictionref::cli {
namespace {

namespace fs = std::filesystem;

struct SeedCase {
  const char* id;  // the seed's figure number
  double lambda;   // R / B
  double v0;
};

// m = B = w = 1, t0 = 0; the seed plots these to t = 30.
constexpr SeedCase seed_cases[] = {{"10.1", 0.3, 0.0}, {"10.2", 0.7, 0.0}, {"10.3", 1.01, -1.0}};
constexpr double seed_t_end = 30;
constexpr double seed_dt = 0.01;

struct ReproduceOptions {
  std::string out = "frictionref-results";
};

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
        steady(steady_state(model)) {}

  SeedCase seed;
  Model model;
  ExactEngine engine;
  UniformSampler sampler;
  SteadyState steady;
};

void write_file(const fs::path& path, const std::function<void(std::FILE*)>& write) {
  AtomicOutput out(path.string(), "--out");
  write(out.stream());
  out.commit();
}

// Writes events.csv, curve.csv and classify.json into `dir`; returns the
// events summary.
Summary write_case(PreparedCase& prepared, const fs::path& dir, const std::string& command) {
  const SeedCase& seed = prepared.seed;
  const std::string case_line = fmt::format("case: {} (seed problem 7, figure {}) lambda={} v0={}",
                                            seed.id, seed.id, seed.lambda, seed.v0);
  Summary events_summary;
  write_file(dir / "events.csv", [&](std::FILE* file) {
    events_summary = write_events_csv(file, prepared.engine, command,
                                      {case_line, fmt::format("horizon: t_end={}", seed_t_end)});
    require_reached_end(events_summary);
  });
  write_file(dir / "curve.csv", [&](std::FILE* file) {
    require_reached_end(write_curve_csv(file, prepared.model, prepared.sampler, command,
                                        {case_line, grid_metadata(prepared.model, seed_grid())}));
  });
  write_file(dir / "classify.json", [&](std::FILE* file) {
    nlohmann::ordered_json json;
    json["case"] = seed.id;
    json.update(classify_json(prepared.model, prepared.steady));
    fmt::print(file, "{}\n", json.dump(2));
  });
  return events_summary;
}

void run_reproduce(const ReproduceOptions& options, const Invocation& invocation) {
  std::vector<std::unique_ptr<PreparedCase>> cases;
  for (const SeedCase& seed : seed_cases) cases.push_back(std::make_unique<PreparedCase>(seed));

  AtomicOutput summary(std::nullopt, "");
  fmt::print(summary.stream(),
             "# frictionref {} reproduce: seed problem 7, m=1 B=1 w=1 t0=0 t_end={} dt={}\n",
             version, seed_t_end, seed_dt);
  for (const auto& prepared : cases) {
    const SeedCase& seed = prepared->seed;
    const fs::path dir =
        fs::path(options.out) / fmt::format("case-{}-lambda-{}", seed.id, seed.lambda);
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) {
      throw bad_input(fmt::format("--out = {}: cannot create {}: {}", options.out, dir.string(),
                                  error.message()));
    }
    const Summary events = write_case(*prepared, dir, invocation.command_line);
    const State& end = events.final_state;
    fmt::print(summary.stream(),
               "case {}: lambda={} v0={} regime={} stick={} slip+={} slip-={} stops={} "
               "reversals={} t={} x={} v={} dir={}\n",
               seed.id, seed.lambda, seed.v0, to_string(prepared->steady.regime),
               events.count(PhaseKind::stick), events.count(PhaseKind::slip_forward),
               events.count(PhaseKind::slip_backward), events.stops, events.reversals, end.t, end.x,
               end.v, dir.string());
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
  command->footer(
      "Computes the three cases of the seed problem (NRC problem 7, figures 10.1-10.3) with\n"
      "m = B = w = 1, t0 = 0, T = 30: lambda = 0.3 and 0.7 from rest, lambda = 1.01 with\n"
      "v0 = -1. Writes DIR/case-<figure>-lambda-<lambda>/ with events.csv, curve.csv (dt = 0.01,\n"
      "event rows included) and classify.json, and prints one summary line per case.\n"
      "Takes no model options: the cases are fixed.\n"
      "Exit codes: 0 ok, 2 bad input or unwritable DIR (one line on stderr), 3 internal error.\n"
      "Example:\n"
      "  frictionref reproduce --out results && head results/case-10.2-lambda-0.7/events.csv");
  return {command,
          [options](const Invocation& invocation) {
            run_reproduce(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
