// `frictionref compare`: another code's time history against the exact
// solution, with a PASS/FAIL verdict (library: comparison.hpp,
// time_history.hpp; docs/cross-checking.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "compare_run.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/comparison_json.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/time_history.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "model_title.hpp"

namespace frictionref::cli {
namespace {

struct CompareCliOptions {
  ModelOptions model;
  CompareInputs inputs;
  bool json = false;
  std::string plot;
  CLI::Option* plot_option = nullptr;
  OutputFileOption output;
};

// compare_run's decimation as a titled series.
Series decimated(std::string title, const std::vector<double>& t, const std::vector<double>& y,
                 std::size_t limit) {
  Curve curve = cli::decimated(t, y, limit);
  Series series;
  series.title = std::move(title);
  series.x = std::move(curve.x);
  series.y = std::move(curve.y);
  return series;
}

Figure comparison_figure(const ComparisonReport& report, const TimeHistory& history,
                         const std::string& candidate_name) {
  constexpr std::size_t max_points = 20000;
  const Model& model = report.model;

  // The exact velocity: a uniform grid of about 4000 steps plus every event,
  // so the kinks are drawn where they are.
  Series exact;
  exact.title = "exact";
  exact.role = Series::Role::reference;
  const std::vector<State> at_candidate = sample_at(model, history.t);
  {
    Curve curve = exact_velocity_curve(report, history, at_candidate);
    exact.x = std::move(curve.x);
    exact.y = std::move(curve.y);
  }
  if (exact.x.size() > 2 * max_points) exact = decimated("exact", exact.x, exact.y, max_points);
  exact.role = Series::Role::reference;

  const std::vector<double> error = velocity_error(history, at_candidate);

  Panel velocity;
  velocity.title = "velocity";
  velocity.x_label = "t [time]";
  velocity.y_label = "v [length/time]";
  velocity.series.push_back(std::move(exact));
  velocity.series.push_back(decimated("candidate", history.t, history.v, max_points));

  Panel difference;
  difference.title = fmt::format("velocity error (max {:.6g} at t = {:.6g})",
                                 report.velocity_max_error, report.velocity_max_error_time);
  difference.x_label = "t [time]";
  difference.y_label = "v - v_exact [length/time]";
  difference.series.push_back(decimated("candidate - exact", history.t, error, max_points));
  // The tolerance band as one closed outline.
  const double tolerance = report.options.velocity_max_tolerance * report.scales.velocity;
  Series band;
  band.title = fmt::format("tolerance +-{}", number(tolerance));
  band.x = {report.t_first, report.t_last, report.t_last, report.t_first, report.t_first};
  band.y = {tolerance, tolerance, -tolerance, -tolerance, tolerance};
  difference.series.push_back(std::move(band));
  difference.vertical_lines = {report.velocity_max_error_time};

  Figure figure;
  const std::vector<std::string> failed = report.failed_checks();
  std::string verdict(to_string(report.verdict));
  if (!failed.empty()) {
    verdict += " (";
    for (std::size_t i = 0; i < failed.size(); ++i) verdict += (i ? ", " : "") + failed[i];
    verdict += ")";
  }
  const std::string which = model.is_harmonic_coulomb()
                                ? fmt::format("lambda = {}", number(model.lambda()))
                                : model_title(model);
  figure.title =
      fmt::format("frictionref compare: {} vs exact, {}: {}", candidate_name, which, verdict);
  figure.panels = {std::move(velocity), std::move(difference)};
  return figure;
}

ExitCode run_compare(const CompareCliOptions& options, const Invocation& invocation) {
  // Everything typed is checked before the file is read.
  const PreparedComparison prepared = prepare_comparison(options.inputs, options.model);
  const bool plot = options.plot_option->count() > 0;
  if (plot) require_figure_path(options.plot, "--plot");
  AtomicOutput out(options.output.path(), "-o");

  const std::string& candidate = options.inputs.candidate;
  const TimeHistory history = read_candidate(prepared, candidate);
  const ComparisonReport report = run_comparison(prepared, history, candidate);

  if (plot) {
    const std::string name =
        candidate == "-" ? "stdin" : std::filesystem::path(candidate).filename().string();
    write_figure(comparison_figure(report, history, name), options.plot, "--plot");
  }
  if (options.json) {
    fmt::print(out.stream(), "{}\n", comparison_json(report, invocation.command_line));
  } else {
    fmt::print(out.stream(), "# frictionref {} compare\n# command: {}\n{}", version,
               invocation.command_line, report.full_report());
  }
  out.commit();
  return verdict_exit_code(report.verdict);
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareCliOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "Check another code's time history (t, v [, x]) against the exact solution");
  options->inputs.add_to(*command, options->model);

  command->add_flag("--json", options->json, "print one JSON object instead of the text report");
  options->plot_option =
      command
          ->add_option("--plot", options->plot,
                       "also draw the exact and candidate velocities and the error into FILE "
                       "(.svg or .png, by gnuplot)")
          ->type_name("FILE");
  options->output.add_to(*command);
  command->footer(
      "Reads the candidate's times and velocities (same units as the model options), computes\n"
      "the exact motion at those very times, and checks:\n"
      "  velocity_max, velocity_rms  the velocity error (absolute and relative to B/(m w));\n"
      "  displacement_max            the position error, with --displacement-column;\n"
      "  stop_times                  each stick (|v| under the threshold long enough) matched\n"
      "                              to the exact one: start and end time errors;\n"
      "  missed_stops, extra_stops   sticks one side shows and the other does not;\n"
      "  creep                       inside each exact stick the candidate must be at rest;\n"
      "  regime                      continuous / dead-bands / stops over the last periods.\n"
      "Sticks and regime are read the same way from the exact motion at the candidate's times,\n"
      "so sampling affects both sides alike. The defaults pass a stiff friction spring\n"
      "(K_f = 1e7, as in the seed problem) and fail creeping, shifted or scaled velocities.\n"
      "PASS needs the samples to resolve the exact motion: every exact phase longer than the\n"
      "stop-time tolerance holds a sample, and the samples around every exact event are at\n"
      "most that tolerance apart. Otherwise a run that passes every check is INCONCLUSIVE (a\n"
      "defect between the samples would pass too), and the report names what is unresolved\n"
      "and the archive step that would resolve it.\n"
      "Output: a text report that opens with 'diagnosis: <defect>: <evidence>' (the most likely\n"
      "defect: time shift, scale, chattering, creep, missed stop, missed breakaway, drift,\n"
      "offset; with its value) and ends in one 'name: PASS|FAIL ...' line per check, a\n"
      "'resolution: ...' line if something is unresolved, and 'verdict: PASS',\n"
      "'verdict: FAIL (checks ...)' or 'verdict: INCONCLUSIVE (...)'; --json gives the same as\n"
      "one object.\n"
      "Exit codes: 0 PASS, 1 FAIL, 3 INCONCLUSIVE, 2 bad input or bad file (one line on stderr\n"
      "naming the file, line and column, no output), 4 internal error.\n"
      "Examples:\n"
      "  frictionref compare --candidate run.csv --lambda 0.7\n"
      "  frictionref compare --candidate out.txt --mass 2 --amplitude 5 --omega 3 --friction 1.5 "
      "--time-column 1 --velocity-column 3 --json\n"
      "  frictionref compare --candidate run.csv --lambda 1.01 --v0 -1 --plot compare.svg\n"
      "docs/cross-checking.md explains every metric and default.");
  return {command,
          [options](const Invocation& invocation) { return run_compare(*options, invocation); }};
}

}  // namespace frictionref::cli
