// Checking a candidate time history against the exact solution
// (comparison.hpp; docs/cross-checking.md explains every metric and default).
// compare() runs the steps in src/comparison/ over one pass of the engine.
#include "frictionref/comparison.hpp"

#include <algorithm>
#include <cmath>

#include "comparison/checks.hpp"
#include "comparison/diagnosis.hpp"
#include "comparison/exact_motion.hpp"
#include "comparison/regime.hpp"
#include "comparison/report_format.hpp"
#include "comparison/resolution.hpp"
#include "comparison/sample_errors.hpp"
#include "comparison/sticks.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/motion_scales.hpp"

namespace frictionref {
namespace {

using comparison::g;

std::string text(double value) { return detail::shortest_text(value); }

void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) throw InvalidInput(name, text(value), rule);
}

// The record, and the scales every tolerance is relative to.
ComparisonReport describe_record(const Model& model, const TimeHistory& history,
                                 const CompareOptions& options) {
  ComparisonReport r;
  r.model = model;
  r.options = options;
  r.source = history.source;
  r.notes = history.notes;  // what the reader did (title lines, restarts)
  r.rows = history.rows();
  r.t_first = history.t.front();
  r.t_last = history.t.back();
  for (std::size_t i = 1; i < history.t.size(); ++i)
    r.max_spacing = std::max(r.max_spacing, history.t[i] - history.t[i - 1]);
  r.scales = motion_scales(model, "to compare");
  r.stick_velocity = options.stick_threshold * r.scales.velocity;
  r.min_stick_time = options.min_stick_duration * r.scales.period;
  r.stop_time_margin = options.stop_time_tolerance * r.scales.period;
  return r;
}

// Whether the samples see every exact phase and event: a check that passed
// without looking is no evidence.
void judge(ComparisonReport& r, const comparison::ExactMotion& exact,
           const std::vector<double>& t) {
  const comparison::Resolution seen = comparison::resolution(exact.phases, t, r.stop_time_margin);
  r.unresolved = seen.parts;
  r.unresolved_phases = seen.phases;
  r.unresolved_events = seen.events;
  r.resolving_step = seen.resolving_step;
  const bool all_passed =
      std::all_of(r.checks.begin(), r.checks.end(), [](const Check& c) { return c.passed; });
  r.verdict = !all_passed                                     ? Verdict::fail
              : r.unresolved_phases + r.unresolved_events > 0 ? Verdict::inconclusive
                                                              : Verdict::pass;
}

void add_notes(ComparisonReport& r) {
  const double record = r.t_last - r.t_first;
  if (r.max_spacing > r.stop_time_margin)
    r.notes.push_back("the largest sample spacing " + g(r.max_spacing) +
                      " exceeds the stop-time tolerance " + g(r.stop_time_margin) +
                      ": stops are located only to about the spacing (both sides are read from "
                      "the same samples); archive more often for a sharper check");
  if (record < r.options.regime_window * r.scales.period)
    r.notes.push_back("the record (" + g(record / r.scales.period) + " " + r.scales.period_unit +
                      ") is shorter than the regime window (" + g(r.options.regime_window) + " " +
                      r.scales.period_unit + "): the regime is read from the whole record");
  if (r.exact_shown_regime != r.exact_regime)
    r.notes.push_back("over the regime window the exact motion shows " +
                      std::string(to_string(r.exact_shown_regime)) + " while its steady state is " +
                      comparison::steady_text(r.exact_regime, r.exact_regime_method) +
                      " (a transient that has not died out, or |v| lingering under the stick "
                      "threshold without a stop); the candidate is held to what the exact motion "
                      "shows");
}

}  // namespace

void CompareOptions::validate() const {
  const auto finite_non_negative = [](const char* name, double value) {
    require(std::isfinite(value), name, value, "must be a finite number");
    require(value >= 0, name, value, "must be >= 0");
  };
  require(std::isfinite(stick_threshold), "stick_threshold", stick_threshold,
          "must be a finite number");
  require(stick_threshold > 0, "stick_threshold", stick_threshold, "must be > 0");
  finite_non_negative("min_stick_duration", min_stick_duration);
  finite_non_negative("velocity_max_tolerance", velocity_max_tolerance);
  finite_non_negative("velocity_rms_tolerance", velocity_rms_tolerance);
  finite_non_negative("stop_time_tolerance", stop_time_tolerance);
  finite_non_negative("displacement_max_tolerance", displacement_max_tolerance);
  require(std::isfinite(regime_window), "regime_window", regime_window, "must be a finite number");
  require(regime_window > 0, "regime_window", regime_window, "must be > 0");
}

ComparisonReport compare(const Model& model, const TimeHistory& history,
                         const CompareOptions& options) {
  model.validate();
  options.validate();
  history.validate();
  if (history.t.front() < model.t0)
    throw InvalidInput("t[0]", text(history.t.front()),
                       "must be >= t0 = " + text(model.t0) + " (the exact motion starts at t0)");

  ComparisonReport r = describe_record(model, history, options);
  const comparison::ExactMotion exact = comparison::exact_motion(model, history.t);
  const std::vector<double> v_exact = exact.v();
  const comparison::SampleErrors errors = comparison::measure_errors(r, history, v_exact, exact);

  // Sticks seen the same way on both sides, from the same samples; the
  // engine's stick phases beside them.
  r.exact_phases = comparison::stick_phases(exact.phases, r.t_last);
  r.exact_sticks = detect_sticks(history.t, v_exact, r.stick_velocity, r.min_stick_time);
  r.candidate_sticks = detect_sticks(history.t, history.v, r.stick_velocity, r.min_stick_time);
  comparison::match_sticks(r);
  const std::size_t creep_phase = comparison::measure_creep(r, history.t, history.v);

  comparison::read_regime(r, history.t, v_exact, history.v);
  comparison::run_checks(r, history, exact, errors, creep_phase);
  judge(r, exact, history.t);
  r.diagnosis = comparison::diagnose(r, history, exact);
  add_notes(r);
  return r;
}

}  // namespace frictionref
