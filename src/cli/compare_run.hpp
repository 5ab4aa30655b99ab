// What `compare` and `report` share: the candidate, column and check options
// as typed, their translation into the library's inputs (everything typed is
// checked before the file is read), the comparison itself, and the curves
// both draw. One place, so a report says exactly what compare says.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/time_history.hpp"
#include "model_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace frictionref::cli {

// --candidate, the column options and the check options, as typed.
struct CompareInputs {
  std::string candidate;
  std::string time_column;
  std::string velocity_column;
  std::string displacement_column;
  bool decimal_comma = false;
  std::string skip_rows = "0";
  std::string on_overlap = "error";
  // Tolerances as typed (numbers are parsed by parse_number, see model_options.hpp).
  std::string stick_threshold;
  std::string min_stick_duration;
  std::string velocity_tolerance;
  std::string velocity_rms_tolerance;
  std::string stop_time_tolerance;
  std::string max_missed_stops;
  std::string max_extra_stops;
  std::string displacement_tolerance;
  std::string regime_window;

  CompareInputs();  // the library's defaults, as text

  // Registers --candidate, then `model`'s options, then the column and check
  // options (in this order: it is the order of --help).
  void add_to(CLI::App& command, ModelOptions& model);
};

// The typed inputs, parsed and validated.
struct PreparedComparison {
  Model model;
  CompareOptions options;
  TimeHistoryReadOptions read_options;
  TypedInputs inputs;  // library field name -> option and text, for messages
};

// Parses and checks everything typed (model, tolerances, counts, columns, B >
// 0); throws bad input naming the option. Reads no file.
PreparedComparison prepare_comparison(const CompareInputs& inputs, const ModelOptions& model);

// The library's InvalidInput as bad input naming the option (--candidate for
// the file, --time-column ... for a column).
CliError translate_compare_error(const InvalidInput& error, const TypedInputs& inputs);

template <class F>
decltype(auto) translating(const TypedInputs& inputs, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InvalidInput& error) {
    throw translate_compare_error(error, inputs);
  }
}

// read_time_history(candidate) with errors naming --candidate.
TimeHistory read_candidate(const PreparedComparison& prepared, const std::string& candidate);

// compare() on a history read from `candidate`; bad input if it starts
// before t0.
ComparisonReport run_comparison(const PreparedComparison& prepared, const TimeHistory& history,
                                const std::string& candidate);

// x-y points of one curve.
struct Curve {
  std::vector<double> x, y;
};

// At most about `limit` points: per bucket the first, lowest and highest, in
// time order, so spikes survive.
Curve decimated(const std::vector<double>& x, const std::vector<double>& y, std::size_t limit);

// The exact velocity over [t_first, t_last] for a figure: a uniform grid of
// about 4000 steps plus every event (kinks drawn where they are), or the
// exact values at the candidate's times (`at_candidate`) if the grid step is
// below the resolution of t (a huge t0).
Curve exact_velocity_curve(const ComparisonReport& report, const TimeHistory& history,
                           const std::vector<State>& at_candidate);

// v - v_exact at the candidate's times.
std::vector<double> velocity_error(const TimeHistory& history,
                                   const std::vector<State>& at_candidate);

}  // namespace frictionref::cli
