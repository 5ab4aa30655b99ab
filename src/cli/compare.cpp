// `frictionref compare`: another code's time history against the exact
// solution, with a PASS/FAIL verdict (library: comparison.hpp,
// time_history.hpp; docs/cross-checking.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/time_history.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "model_title.hpp"

namespace frictionref::cli {
namespace {

struct CompareCliOptions {
  ModelOptions model;
  std::string candidate;
  std::string time_column;
  std::string velocity_column;
  std::string displacement_column;
  // Tolerances as typed (numbers are parsed by parse_number, see model_options.hpp).
  std::string stick_threshold = number(CompareOptions{}.stick_threshold);
  std::string min_stick_duration = number(CompareOptions{}.min_stick_duration);
  std::string velocity_tolerance = number(CompareOptions{}.velocity_max_tolerance);
  std::string velocity_rms_tolerance = number(CompareOptions{}.velocity_rms_tolerance);
  std::string stop_time_tolerance = number(CompareOptions{}.stop_time_tolerance);
  std::string max_missed_stops = std::to_string(CompareOptions{}.max_missed_stops);
  std::string max_extra_stops = std::to_string(CompareOptions{}.max_extra_stops);
  std::string displacement_tolerance = number(CompareOptions{}.displacement_max_tolerance);
  std::string regime_window = number(CompareOptions{}.regime_window);
  bool json = false;
  std::string plot;
  CLI::Option* plot_option = nullptr;
  OutputFileOption output;
};

// Library parameter names whose InvalidInput value is already the text the
// user typed (or "(default: ...)"): only the option name is swapped in.
const std::map<std::string, std::string> renamed = {
    {"file", "--candidate"},
    {"time_column", "--time-column"},
    {"velocity_column", "--velocity-column"},
    {"displacement_column", "--displacement-column"},
};

CliError translate(const InvalidInput& error, const TypedInputs& inputs) {
  const auto option = renamed.find(error.parameter());
  if (option != renamed.end())
    return bad_input(fmt::format("{} = {}: {}", option->second, error.value(), error.rule()));
  return to_bad_input(error, inputs);
}

template <class F>
decltype(auto) translating(const TypedInputs& inputs, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InvalidInput& error) {
    throw translate(error, inputs);
  }
}

// A count as typed: digits only.
std::uint64_t parse_count(const TypedNumber& typed) {
  const std::string& s = typed.text;
  const bool digits = !s.empty() && s.size() <= 18 &&
                      std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits)
    throw bad_input(fmt::format("{} = {}: must be a whole number >= 0", typed.option, s));
  return std::strtoull(s.c_str(), nullptr, 10);
}

// At most about `limit` points: per bucket the first, lowest and highest, in
// time order, so spikes survive.
Series decimated(std::string title, const std::vector<double>& t, const std::vector<double>& y,
                 std::size_t limit) {
  Series series;
  series.title = std::move(title);
  if (t.size() <= limit) {
    series.x = t;
    series.y = y;
    return series;
  }
  const std::size_t buckets = limit / 3;
  const std::size_t size = (t.size() + buckets - 1) / buckets;
  for (std::size_t begin = 0; begin < t.size(); begin += size) {
    const std::size_t end = std::min(t.size(), begin + size);
    std::size_t lo = begin, hi = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    std::vector<std::size_t> rows{begin, lo, hi};
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (std::size_t i : rows) {
      series.x.push_back(t[i]);
      series.y.push_back(y[i]);
    }
  }
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
  GridOptions grid;
  grid.t_end = report.t_last;
  grid.dt = (report.t_last - model.t0) / 4000;
  grid.include_events = true;
  try {
    UniformSampler sampler(model, grid);
    State state;
    while (sampler.next(state)) {
      if (state.t < report.t_first) continue;
      exact.x.push_back(state.t);
      exact.y.push_back(state.v);
    }
  } catch (const InvalidInput&) {
    // A grid step below the resolution of t (a huge t0): the candidate's times.
    exact.x = history.t;
    exact.y.clear();
    for (const State& state : at_candidate) exact.y.push_back(state.v);
  }
  if (exact.x.size() > 2 * max_points) exact = decimated("exact", exact.x, exact.y, max_points);
  exact.role = Series::Role::reference;

  std::vector<double> error(history.t.size());
  for (std::size_t i = 0; i < error.size(); ++i) error[i] = history.v[i] - at_candidate[i].v;

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
  const double tolerance = report.options.velocity_max_tolerance * report.velocity_scale;
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
  figure.title = fmt::format("frictionref compare: {} vs exact, {}: {}", candidate_name, which,
                             verdict);
  figure.panels = {std::move(velocity), std::move(difference)};
  return figure;
}

nlohmann::ordered_json interval_json(double start, double end) {
  return {{"start", start}, {"end", end}};
}

nlohmann::ordered_json intervals_json(const std::vector<StickInterval>& list) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StickInterval& s : list) out.push_back(interval_json(s.start, s.end));
  return out;
}

nlohmann::ordered_json report_json(const ComparisonReport& r) {
  using json = nlohmann::ordered_json;
  json out;
  out["verdict"] = std::string(to_string(r.verdict));
  out["failed_checks"] = r.failed_checks();
  json checks = json::array();
  for (const Check& check : r.checks)
    checks.push_back({{"name", std::string(check.name())},
                      {"passed", check.passed},
                      {"value", check.value},
                      {"tolerance", check.tolerance},
                      {"message", check.message}});
  out["checks"] = checks;
  out["candidate"] = {{"source", r.source},           {"rows", r.rows},
                      {"t_first", r.t_first},         {"t_last", r.t_last},
                      {"max_spacing", r.max_spacing}, {"has_displacement", r.has_displacement}};
  const Model& m = r.model;
  out["model"] = {{"mass", m.mass},       {"amplitude", m.amplitude},
                  {"omega", m.omega},     {"friction", m.friction},
                  {"lambda", m.lambda()}, {"x0", m.x0},
                  {"v0", m.v0},           {"t0", m.t0}};
  const CompareOptions& o = r.options;
  out["options"] = {{"stick_threshold", o.stick_threshold},
                    {"min_stick_duration", o.min_stick_duration},
                    {"velocity_max_tolerance", o.velocity_max_tolerance},
                    {"velocity_rms_tolerance", o.velocity_rms_tolerance},
                    {"stop_time_tolerance", o.stop_time_tolerance},
                    {"max_missed_stops", o.max_missed_stops},
                    {"max_extra_stops", o.max_extra_stops},
                    {"displacement_max_tolerance", o.displacement_max_tolerance},
                    {"regime_window", o.regime_window}};
  out["scales"] = {{"velocity", r.velocity_scale},
                   {"displacement", r.displacement_scale},
                   {"period", r.period},
                   {"stick_velocity", r.stick_velocity},
                   {"min_stick_time", r.min_stick_time},
                   {"stop_time_margin", r.stop_time_margin}};
  out["velocity_error"] = {{"max", r.velocity_max_error},
                           {"max_relative", r.velocity_max_error / r.velocity_scale},
                           {"max_time", r.velocity_max_error_time},
                           {"rms", r.velocity_rms_error},
                           {"rms_relative", r.velocity_rms_error / r.velocity_scale}};
  if (r.has_displacement) {
    out["displacement_error"] = {{"max", r.displacement_max_error},
                                 {"max_relative", r.displacement_max_error / r.displacement_scale},
                                 {"max_time", r.displacement_max_error_time},
                                 {"rms", r.displacement_rms_error},
                                 {"rms_relative", r.displacement_rms_error / r.displacement_scale}};
  } else {
    out["displacement_error"] = nullptr;
  }
  json matched = json::array();
  for (const MatchedStick& s : r.matched) {
    json phase = nullptr;
    if (!std::isnan(s.phase_start)) phase = interval_json(s.phase_start, s.phase_end);
    matched.push_back({{"number", s.number},
                       {"exact", interval_json(s.exact.start, s.exact.end)},
                       {"candidate", interval_json(s.candidate.start, s.candidate.end)},
                       {"start_error", s.start_error},
                       {"end_error", s.end_error},
                       {"exact_phase", phase}});
  }
  out["sticks"] = {{"exact_phases", intervals_json(r.exact_phases)},
                   {"exact", intervals_json(r.exact_sticks)},
                   {"candidate", intervals_json(r.candidate_sticks)},
                   {"matched", matched},
                   {"missed", intervals_json(r.missed)},
                   {"extra", intervals_json(r.extra)}};
  out["creep"] = {{"max_velocity", r.creep_max_velocity},
                  {"max_relative", r.creep_max_velocity / r.velocity_scale},
                  {"time", r.creep_time},
                  {"samples", r.creep_samples}};
  out["regime"] = {{"candidate", std::string(to_string(r.candidate_regime))},
                   {"exact", std::string(to_string(r.exact_shown_regime))},
                   {"steady_state", std::string(to_string(r.exact_regime))},
                   {"window_start", r.regime_window_start},
                   {"window_end", r.t_last},
                   {"candidate_stops_per_period", r.candidate_stops_per_period},
                   {"exact_stops_per_period", r.exact_stops_per_period}};
  out["notes"] = r.notes;
  out["version"] = version;
  return out;
}

ExitCode run_compare(const CompareCliOptions& options, const Invocation& invocation) {
  TypedInputs inputs = options.model.typed_inputs();
  inputs["stick_threshold"] = {"--stick-threshold", options.stick_threshold};
  inputs["min_stick_duration"] = {"--min-stick-duration", options.min_stick_duration};
  inputs["velocity_max_tolerance"] = {"--velocity-tolerance", options.velocity_tolerance};
  inputs["velocity_rms_tolerance"] = {"--velocity-rms-tolerance", options.velocity_rms_tolerance};
  inputs["stop_time_tolerance"] = {"--stop-time-tolerance", options.stop_time_tolerance};
  inputs["displacement_max_tolerance"] = {"--displacement-tolerance",
                                          options.displacement_tolerance};
  inputs["regime_window"] = {"--regime-window", options.regime_window};

  // Everything typed is checked before the file is read.
  const Model model = options.model.model();
  CompareOptions compare_options;
  compare_options.stick_threshold = parse_number(inputs.at("stick_threshold"));
  compare_options.min_stick_duration = parse_number(inputs.at("min_stick_duration"));
  compare_options.velocity_max_tolerance = parse_number(inputs.at("velocity_max_tolerance"));
  compare_options.velocity_rms_tolerance = parse_number(inputs.at("velocity_rms_tolerance"));
  compare_options.stop_time_tolerance = parse_number(inputs.at("stop_time_tolerance"));
  compare_options.displacement_max_tolerance =
      parse_number(inputs.at("displacement_max_tolerance"));
  compare_options.regime_window = parse_number(inputs.at("regime_window"));
  compare_options.max_missed_stops = parse_count({"--max-missed-stops", options.max_missed_stops});
  compare_options.max_extra_stops = parse_count({"--max-extra-stops", options.max_extra_stops});
  translating(inputs, [&] { compare_options.validate(); });
  if (!(model.amplitude > 0))
    throw bad_input(
        fmt::format("--amplitude = {}: must be > 0 to compare (velocities are judged "
                    "relative to B/(m w))",
                    inputs.at("amplitude").text));
  TimeHistoryReadOptions read_options;
  read_options.time_column = options.time_column;
  read_options.velocity_column = options.velocity_column;
  read_options.displacement_column = options.displacement_column;
  translating(inputs, [&] { read_options.validate(); });
  const bool plot = options.plot_option->count() > 0;
  if (plot) require_figure_path(options.plot, "--plot");
  AtomicOutput out(options.output.path(), "-o");

  const TimeHistory history =
      translating(inputs, [&] { return read_time_history(options.candidate, read_options); });
  if (history.t.front() < model.t0)
    throw bad_input(fmt::format(
        "--candidate = {}: its first time {} is before --t0 = {}; the exact motion starts at t0 "
        "(pass the candidate's start time as --t0)",
        options.candidate, number(history.t.front()), inputs.at("t0").text));
  const ComparisonReport report =
      translating(inputs, [&] { return compare(model, history, compare_options); });

  if (plot) {
    const std::string name = options.candidate == "-"
                                 ? "stdin"
                                 : std::filesystem::path(options.candidate).filename().string();
    write_figure(comparison_figure(report, history, name), options.plot, "--plot");
  }
  if (options.json) {
    nlohmann::ordered_json json = report_json(report);
    json["command"] = invocation.command_line;
    fmt::print(out.stream(), "{}\n", json.dump(2));
  } else {
    fmt::print(out.stream(), "# frictionref {} compare\n# command: {}\n{}", version,
               invocation.command_line, report.full_report());
  }
  out.commit();
  return report.verdict == Verdict::pass ? exit_success : exit_compare_failed;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareCliOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "Check another code's time history (t, v [, x]) against the exact solution");
  command
      ->add_option("--candidate", options->candidate,
                   "the other code's time history: CSV or white-space columns, optional header, "
                   "'#' comments; '-' reads stdin")
      ->required()
      ->type_name("FILE");
  options->model.add_to(*command);

  const char* columns = "Columns (a header name, case-insensitive, or a 1-based number)";
  command
      ->add_option("--time-column", options->time_column,
                   "time column [default: the header's t or time, else column 1]")
      ->type_name("C")
      ->group(columns);
  command
      ->add_option("--velocity-column", options->velocity_column,
                   "velocity column [default: the header's v, vel or velocity, else column 2]")
      ->type_name("C")
      ->group(columns);
  command
      ->add_option("--displacement-column", options->displacement_column,
                   "displacement column; adds the displacement_max check [default: none]")
      ->type_name("C")
      ->group(columns);

  const char* checks =
      "Checks (relative to the model: velocities in B/(m w), displacements in B/(m w^2), times "
      "in forcing periods 2 pi / w)";
  const auto number_option = [&](const char* name, std::string& text, const char* help,
                                 const char* type) {
    numeric(command->add_option(name, text, help))
        ->type_name(type)
        ->group(checks)
        ->capture_default_str();
  };
  number_option("--stick-threshold", options->stick_threshold,
                "at rest while |v| < S B/(m w); also the creep limit inside exact sticks; > 0",
                "S");
  number_option("--min-stick-duration", options->min_stick_duration,
                "a rest counts as a stick if it lasts D periods or more; >= 0", "D");
  number_option("--velocity-tolerance", options->velocity_tolerance,
                "velocity_max: max |v - v_exact| <= E B/(m w); >= 0", "E");
  number_option("--velocity-rms-tolerance", options->velocity_rms_tolerance,
                "velocity_rms: time-weighted RMS of v - v_exact <= E B/(m w); >= 0", "E");
  number_option("--stop-time-tolerance", options->stop_time_tolerance,
                "stop_times: start and end of every matched stick within E periods; also the "
                "margin at each end of an exact stick for creep; >= 0",
                "E");
  command
      ->add_option("--max-missed-stops", options->max_missed_stops,
                   "missed_stops: exact sticks the candidate may lack")
      ->type_name("N")
      ->group(checks)
      ->capture_default_str();
  command
      ->add_option("--max-extra-stops", options->max_extra_stops,
                   "extra_stops: candidate sticks the exact motion may lack")
      ->type_name("N")
      ->group(checks)
      ->capture_default_str();
  number_option("--displacement-tolerance", options->displacement_tolerance,
                "displacement_max (with --displacement-column): max |x - x_exact| <= E "
                "B/(m w^2); >= 0",
                "E");
  number_option("--regime-window", options->regime_window,
                "regime: read from the last P periods of the record; > 0", "P");

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
      "Output: a text report ending in one 'name: PASS|FAIL ...' line per check and\n"
      "'verdict: PASS' or 'verdict: FAIL (checks ...)'; --json gives the same as one object.\n"
      "Exit codes: 0 PASS, 1 FAIL, 2 bad input or bad file (one line on stderr naming the\n"
      "file, line and column, no output), 3 internal error.\n"
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
