// Shared by `compare` and `report` (compare_run.hpp).
#include "compare_run.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>

#include "csv_format.hpp"
#include "frictionref/motion_scales.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::cli {
namespace {

// Library parameter names whose InvalidInput value is already the text the
// user typed (or "(default: ...)"): only the option name is swapped in.
const std::map<std::string, std::string> renamed = {
    {"file", "--candidate"},
    {"time_column", "--time-column"},
    {"velocity_column", "--velocity-column"},
    {"displacement_column", "--displacement-column"},
    {"skip_rows", "--skip-rows"},
};

// A count as typed: digits only.
std::uint64_t parse_count(const TypedNumber& typed) {
  const std::string& s = typed.text;
  const bool digits = !s.empty() && s.size() <= 18 &&
                      std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits)
    throw bad_input(fmt::format("{} = {}: must be a whole number >= 0", typed.option, s));
  return std::strtoull(s.c_str(), nullptr, 10);
}

}  // namespace

CompareInputs::CompareInputs()
    : stick_threshold(number(CompareOptions{}.stick_threshold)),
      min_stick_duration(number(CompareOptions{}.min_stick_duration)),
      velocity_tolerance(number(CompareOptions{}.velocity_max_tolerance)),
      velocity_rms_tolerance(number(CompareOptions{}.velocity_rms_tolerance)),
      stop_time_tolerance(number(CompareOptions{}.stop_time_tolerance)),
      max_missed_stops(std::to_string(CompareOptions{}.max_missed_stops)),
      max_extra_stops(std::to_string(CompareOptions{}.max_extra_stops)),
      displacement_tolerance(number(CompareOptions{}.displacement_max_tolerance)),
      regime_window(number(CompareOptions{}.regime_window)) {}

void CompareInputs::add_to(CLI::App& command, ModelOptions& model) {
  command
      .add_option("--candidate", candidate,
                  "the other code's time history: CSV or white-space columns, optional header, "
                  "'#' comments; '-' reads stdin")
      ->required()
      ->type_name("FILE");
  model.add_to(command);

  const char* columns = "Columns (a header name, case-insensitive, or a 1-based number)";
  command
      .add_option("--time-column", time_column,
                  "time column [default: the header's t or time, else column 1]")
      ->type_name("C")
      ->group(columns);
  command
      .add_option("--velocity-column", velocity_column,
                  "velocity column [default: the header's v, vel or velocity, else column 2]")
      ->type_name("C")
      ->group(columns);
  command
      .add_option("--displacement-column", displacement_column,
                  "displacement column; adds the displacement_max check [default: none]")
      ->type_name("C")
      ->group(columns);
  command
      .add_flag("--decimal-comma", decimal_comma,
                "numbers have a decimal comma (1,5) [always so with ';' between columns]")
      ->group(columns);
  command
      .add_option("--skip-rows", skip_rows,
                  "skip N lines before the header or first row [default: 0; title lines before "
                  "a header are skipped anyway, with a note]")
      ->type_name("N")
      ->group(columns)
      ->capture_default_str();
  command
      .add_option("--on-overlap", on_overlap,
                  "when time goes back (a restart wrote the overlap again): error, or keep-last "
                  "(the later segment counts, with a note)")
      ->type_name("MODE")
      ->group(columns)
      ->capture_default_str();

  const char* checks =
      "Checks (relative to the forcing: velocities in B/(m w), displacements in B/(m w^2), times "
      "in periods 2 pi / w; with --ground-accel in the record's PGV, PGV^2/PGA and "
      "T* = 2 pi PGV/PGA instead)";
  const auto number_option = [&](const char* name, std::string& text, const char* help,
                                 const char* type) {
    numeric(command.add_option(name, text, help))
        ->type_name(type)
        ->group(checks)
        ->capture_default_str();
  };
  number_option("--stick-threshold", stick_threshold,
                "at rest while |v| < S B/(m w); also the creep limit inside exact sticks; > 0",
                "S");
  number_option("--min-stick-duration", min_stick_duration,
                "a rest counts as a stick if it lasts D periods or more; >= 0", "D");
  number_option("--velocity-tolerance", velocity_tolerance,
                "velocity_max: max |v - v_exact| <= E B/(m w); >= 0", "E");
  number_option("--velocity-rms-tolerance", velocity_rms_tolerance,
                "velocity_rms: time-weighted RMS of v - v_exact <= E B/(m w); >= 0", "E");
  number_option("--stop-time-tolerance", stop_time_tolerance,
                "stop_times: start and end of every matched stick within E periods; also the "
                "margin at each end of an exact stick for creep; >= 0",
                "E");
  command
      .add_option("--max-missed-stops", max_missed_stops,
                  "missed_stops: exact sticks the candidate may lack")
      ->type_name("N")
      ->group(checks)
      ->capture_default_str();
  command
      .add_option("--max-extra-stops", max_extra_stops,
                  "extra_stops: candidate sticks the exact motion may lack")
      ->type_name("N")
      ->group(checks)
      ->capture_default_str();
  number_option("--displacement-tolerance", displacement_tolerance,
                "displacement_max (with --displacement-column): max |x - x_exact| <= E "
                "B/(m w^2); >= 0",
                "E");
  number_option("--regime-window", regime_window,
                "regime: read from the last P periods of the record; > 0", "P");
}

CliError translate_compare_error(const InvalidInput& error, const TypedInputs& inputs) {
  const auto option = renamed.find(error.parameter());
  if (option != renamed.end())
    return bad_input(fmt::format("{} = {}: {}", option->second, error.value(), error.rule()));
  return to_bad_input(error, inputs);
}

PreparedComparison prepare_comparison(const CompareInputs& typed, const ModelOptions& model) {
  PreparedComparison prepared;
  TypedInputs& inputs = prepared.inputs;
  inputs = model.typed_inputs();
  inputs["stick_threshold"] = {"--stick-threshold", typed.stick_threshold};
  inputs["min_stick_duration"] = {"--min-stick-duration", typed.min_stick_duration};
  inputs["velocity_max_tolerance"] = {"--velocity-tolerance", typed.velocity_tolerance};
  inputs["velocity_rms_tolerance"] = {"--velocity-rms-tolerance", typed.velocity_rms_tolerance};
  inputs["stop_time_tolerance"] = {"--stop-time-tolerance", typed.stop_time_tolerance};
  inputs["displacement_max_tolerance"] = {"--displacement-tolerance", typed.displacement_tolerance};
  inputs["regime_window"] = {"--regime-window", typed.regime_window};

  // Everything typed is checked before the file is read.
  prepared.model = model.model();
  CompareOptions& options = prepared.options;
  options.stick_threshold = parse_number(inputs.at("stick_threshold"));
  options.min_stick_duration = parse_number(inputs.at("min_stick_duration"));
  options.velocity_max_tolerance = parse_number(inputs.at("velocity_max_tolerance"));
  options.velocity_rms_tolerance = parse_number(inputs.at("velocity_rms_tolerance"));
  options.stop_time_tolerance = parse_number(inputs.at("stop_time_tolerance"));
  options.displacement_max_tolerance = parse_number(inputs.at("displacement_max_tolerance"));
  options.regime_window = parse_number(inputs.at("regime_window"));
  options.max_missed_stops = parse_count({"--max-missed-stops", typed.max_missed_stops});
  options.max_extra_stops = parse_count({"--max-extra-stops", typed.max_extra_stops});
  translating(inputs, [&] { options.validate(); });
  // The scales every tolerance is relative to exist (B > 0, or a record
  // that is not zero throughout).
  translating(inputs, [&] { (void)motion_scales(prepared.model, "to compare"); });
  prepared.read_options.time_column = typed.time_column;
  prepared.read_options.velocity_column = typed.velocity_column;
  prepared.read_options.displacement_column = typed.displacement_column;
  prepared.read_options.decimal_comma = typed.decimal_comma;
  prepared.read_options.skip_rows = parse_count({"--skip-rows", typed.skip_rows});
  if (typed.on_overlap == "keep-last")
    prepared.read_options.on_overlap = TimeHistoryReadOptions::OnOverlap::keep_last;
  else if (typed.on_overlap != "error")
    throw bad_input(fmt::format("--on-overlap = {}: must be error or keep-last", typed.on_overlap));
  translating(inputs, [&] { prepared.read_options.validate(); });
  return prepared;
}

TimeHistory read_candidate(const PreparedComparison& prepared, const std::string& candidate) {
  return translating(prepared.inputs,
                     [&] { return read_time_history(candidate, prepared.read_options); });
}

ComparisonReport run_comparison(const PreparedComparison& prepared, const TimeHistory& history,
                                const std::string& candidate) {
  if (history.t.front() < prepared.model.t0)
    throw bad_input(fmt::format(
        "--candidate = {}: its first time {} is before --t0 = {}; the exact motion starts at t0 "
        "(pass the candidate's start time as --t0)",
        candidate, number(history.t.front()), prepared.inputs.at("t0").text));
  return translating(prepared.inputs,
                     [&] { return compare(prepared.model, history, prepared.options); });
}

Curve decimated(const std::vector<double>& x, const std::vector<double>& y, std::size_t limit) {
  Curve curve;
  if (x.size() <= limit) {
    curve.x = x;
    curve.y = y;
    return curve;
  }
  const std::size_t buckets = limit / 3;
  const std::size_t size = (x.size() + buckets - 1) / buckets;
  for (std::size_t begin = 0; begin < x.size(); begin += size) {
    const std::size_t end = std::min(x.size(), begin + size);
    std::size_t lo = begin, hi = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    std::vector<std::size_t> rows{begin, lo, hi};
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (std::size_t i : rows) {
      curve.x.push_back(x[i]);
      curve.y.push_back(y[i]);
    }
  }
  return curve;
}

Curve exact_velocity_curve(const ComparisonReport& report, const TimeHistory& history,
                           const std::vector<State>& at_candidate) {
  const Model& model = report.model;
  Curve exact;
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
  return exact;
}

std::vector<double> velocity_error(const TimeHistory& history,
                                   const std::vector<State>& at_candidate) {
  std::vector<double> error(history.t.size());
  for (std::size_t i = 0; i < error.size(); ++i) error[i] = history.v[i] - at_candidate[i].v;
  return error;
}

}  // namespace frictionref::cli
