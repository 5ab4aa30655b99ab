// Checking a candidate time history against the exact solution
// (comparison.hpp; docs/cross-checking.md explains every metric and default).
#include "frictionref/comparison.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "comparison/resolution.hpp"
#include "frictionref/classification.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model_fields.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string text(double value) { return detail::shortest_text(value); }

// "dead-bands", or "dead-bands (by simulation)" when no closed form gave it.
std::string steady_text(Regime regime, ClassificationMethod method) {
  std::string s(to_string(regime));
  if (method == ClassificationMethod::simulation) s += " (by simulation)";
  return s;
}

// Six significant digits (values in reports).
std::string g(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string signed_g(double value) { return (value > 0 ? "+" : "") + g(value); }

std::string interval(double start, double end) { return "[" + g(start) + ", " + g(end) + "]"; }
std::string interval(const StickInterval& s) { return interval(s.start, s.end); }

// Up to `limit` intervals, then "and N more".
std::string interval_list(const std::vector<StickInterval>& list, std::size_t limit = 5) {
  std::string out;
  for (std::size_t i = 0; i < list.size() && i < limit; ++i)
    out += (i ? ", " : "") + interval(list[i]);
  if (list.size() > limit) out += ", and " + std::to_string(list.size() - limit) + " more";
  return out;
}

// Where |v| crosses `threshold` between two samples on either side of it.
double crossing(double ta, double a, double tb, double b, double threshold) {
  if (a == b) return ta;
  const double fraction = std::clamp((a - threshold) / (a - b), 0.0, 1.0);
  return ta + fraction * (tb - ta);
}

// The start of a rest beginning at row i >= 1. A slip ends with a nonzero
// deceleration, so v is close to linear on the moving side: the zero of the
// line through the last two moving samples, if |v| falls along it, kept
// between the last moving and the first resting sample. This is what makes
// stop times at coarse sampling follow the true stop smoothly (a threshold
// crossing interpolated across the kink at the stop jumps by up to a whole
// sample spacing). Otherwise the interpolated threshold crossing.
double stop_time(const std::vector<double>& t, const std::vector<double>& v, std::size_t i,
                 double threshold) {
  double estimate = crossing(t[i - 1], std::fabs(v[i - 1]), t[i], std::fabs(v[i]), threshold);
  if (i >= 2 && (v[i - 2] > 0) == (v[i - 1] > 0) && std::fabs(v[i - 2]) > std::fabs(v[i - 1]))
    estimate = t[i - 1] + v[i - 1] * (t[i - 1] - t[i - 2]) / (v[i - 2] - v[i - 1]);
  return std::clamp(estimate, t[i - 1], t[i]);
}

struct ErrorStats {
  double max = 0;       // max |error|
  double max_time = 0;  // where
  std::size_t max_row = 0;
  double rms = 0;  // time-weighted (trapezoidal) root mean square
};

ErrorStats error_stats(const std::vector<double>& t, const std::vector<double>& candidate,
                       const std::vector<double>& exact) {
  ErrorStats stats;
  stats.max_time = t.front();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = std::fabs(candidate[i] - exact[i]);
    if (e > stats.max) {
      stats.max = e;
      stats.max_time = t[i];
      stats.max_row = i;
    }
  }
  // The squares are taken of errors scaled by the largest one, so huge values
  // in a candidate file cannot overflow into inf * 0 = NaN; an infinite error
  // gives an infinite RMS (a FAIL, never a NaN).
  if (!(stats.max > 0) || !std::isfinite(stats.max)) {
    stats.rms = stats.max;
    return stats;
  }
  double integral = 0;
  double previous = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = (candidate[i] - exact[i]) / stats.max;
    if (i > 0) integral += (t[i] - t[i - 1]) * (previous * previous + e * e) / 2;
    previous = e;
  }
  stats.rms = stats.max * std::sqrt(integral / (t.back() - t.front()));
  return stats;
}

struct Shown {
  Regime regime = Regime::stops;
  double stops_per_period = 0;
};

// Stops if at rest throughout the window, dead bands if any stick reaches into
// it, continuous otherwise.
Shown shown_regime(const std::vector<double>& t, const std::vector<double>& v,
                   const std::vector<StickInterval>& sticks, double window_start, double threshold,
                   double window_periods) {
  bool at_rest = true;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= window_start && !(std::fabs(v[i]) < threshold)) at_rest = false;
  Shown shown;
  if (at_rest) return shown;
  const auto count = std::count_if(sticks.begin(), sticks.end(),
                                   [&](const StickInterval& s) { return s.end > window_start; });
  shown.regime = count > 0 ? Regime::dead_bands : Regime::continuous;
  shown.stops_per_period = static_cast<double>(count) / window_periods;
  return shown;
}

void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) throw InvalidInput(name, text(value), rule);
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

std::string_view to_string(CheckKind kind) {
  switch (kind) {
    case CheckKind::velocity_max:
      return "velocity_max";
    case CheckKind::velocity_rms:
      return "velocity_rms";
    case CheckKind::displacement_max:
      return "displacement_max";
    case CheckKind::stop_times:
      return "stop_times";
    case CheckKind::missed_stops:
      return "missed_stops";
    case CheckKind::extra_stops:
      return "extra_stops";
    case CheckKind::creep:
      return "creep";
    case CheckKind::regime:
      return "regime";
  }
  return "unknown";
}

std::string_view to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass:
      return "PASS";
    case Verdict::fail:
      return "FAIL";
    case Verdict::inconclusive:
      return "INCONCLUSIVE";
  }
  return "?";
}

std::optional<CheckKind> check_kind_from_string(std::string_view text) {
  for (CheckKind kind :
       {CheckKind::velocity_max, CheckKind::velocity_rms, CheckKind::displacement_max,
        CheckKind::stop_times, CheckKind::missed_stops, CheckKind::extra_stops, CheckKind::creep,
        CheckKind::regime})
    if (to_string(kind) == text) return kind;
  return std::nullopt;
}

std::optional<Verdict> verdict_from_string(std::string_view text) {
  if (text == "PASS") return Verdict::pass;
  if (text == "FAIL") return Verdict::fail;
  if (text == "INCONCLUSIVE") return Verdict::inconclusive;
  return std::nullopt;
}

std::vector<StickInterval> detect_sticks(const std::vector<double>& t, const std::vector<double>& v,
                                         double threshold, double min_duration) {
  std::vector<StickInterval> sticks;
  const std::size_t n = std::min(t.size(), v.size());
  const auto at_rest = [&](std::size_t i) { return std::fabs(v[i]) < threshold; };
  for (std::size_t i = 0; i < n;) {
    if (!at_rest(i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && at_rest(j + 1)) ++j;
    StickInterval stick;
    stick.first_row = i;
    stick.last_row = j;
    stick.start = i == 0 ? t[0] : stop_time(t, v, i, threshold);
    stick.end = j + 1 == n
                    ? t[n - 1]
                    : crossing(t[j], std::fabs(v[j]), t[j + 1], std::fabs(v[j + 1]), threshold);
    if (stick.duration() >= min_duration) sticks.push_back(stick);
    i = j + 1;
  }
  return sticks;
}

ComparisonReport compare(const Model& model, const TimeHistory& history,
                         const CompareOptions& options) {
  model.validate();
  options.validate();
  history.validate();
  if (!(model.amplitude > 0))
    throw InvalidInput("amplitude", text(model.amplitude),
                       "must be > 0 to compare (velocities are judged relative to B/(m w))");
  if (history.t.front() < model.t0)
    throw InvalidInput("t[0]", text(history.t.front()),
                       "must be >= t0 = " + text(model.t0) + " (the exact motion starts at t0)");

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
  r.velocity_scale = model.amplitude / (model.mass * model.omega);
  r.displacement_scale = r.velocity_scale / model.omega;
  r.period = boost::math::double_constants::two_pi / model.omega;
  r.stick_velocity = options.stick_threshold * r.velocity_scale;
  r.min_stick_time = options.min_stick_duration * r.period;
  r.stop_time_margin = options.stop_time_tolerance * r.period;

  // The exact state at the candidate's own times.
  const std::vector<State> exact = sample_at(model, history.t);
  std::vector<double> v_exact(exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) v_exact[i] = exact[i].v;
  const ErrorStats velocity = error_stats(history.t, history.v, v_exact);
  r.velocity_max_error = velocity.max;
  r.velocity_max_error_time = velocity.max_time;
  r.velocity_rms_error = velocity.rms;
  ErrorStats displacement;
  if (history.x) {
    std::vector<double> x_exact(exact.size());
    for (std::size_t i = 0; i < exact.size(); ++i) x_exact[i] = exact[i].x;
    displacement = error_stats(history.t, *history.x, x_exact);
    r.has_displacement = true;
    r.displacement_max_error = displacement.max;
    r.displacement_max_error_time = displacement.max_time;
    r.displacement_rms_error = displacement.rms;
  }

  // The engine's stick phases up to the last candidate time (a record
  // shorter than the engine's time resolution still gets a horizon it takes).
  ExactEngine engine(model, resolvable_t_end(model, r.t_last));
  std::vector<Phase> phases;
  Phase phase;
  while (engine.next(phase)) {
    if (phase.t_begin < r.t_last) phases.push_back(phase);
    if (phase.kind != PhaseKind::stick || !(phase.t_begin < r.t_last)) continue;
    StickInterval stick;
    stick.start = phase.t_begin;
    stick.end = std::fmin(phase.t_end, r.t_last);
    r.exact_phases.push_back(stick);
  }
  if (engine.summary().termination != Termination::reached_end)
    throw std::runtime_error("exact engine: " + engine.summary().message);

  // Sticks seen the same way on both sides, matched in time order: two
  // intervals match if they overlap once each is widened by the stop-time
  // tolerance.
  r.exact_sticks = detect_sticks(history.t, v_exact, r.stick_velocity, r.min_stick_time);
  r.candidate_sticks = detect_sticks(history.t, history.v, r.stick_velocity, r.min_stick_time);
  const double widen = r.stop_time_margin;
  std::size_t i = 0, j = 0, k = 0;
  while (i < r.exact_sticks.size() || j < r.candidate_sticks.size()) {
    if (j == r.candidate_sticks.size()) {
      r.missed.push_back(r.exact_sticks[i++]);
      continue;
    }
    if (i == r.exact_sticks.size()) {
      r.extra.push_back(r.candidate_sticks[j++]);
      continue;
    }
    const StickInterval& e = r.exact_sticks[i];
    const StickInterval& c = r.candidate_sticks[j];
    if (e.end + widen < c.start) {
      r.missed.push_back(r.exact_sticks[i++]);
    } else if (c.end + widen < e.start) {
      r.extra.push_back(r.candidate_sticks[j++]);
    } else {
      MatchedStick m;
      m.number = i + 1;
      m.exact = e;
      m.candidate = c;
      m.start_error = c.start - e.start;
      m.end_error = c.end - e.end;
      m.phase_start = m.phase_end = kNaN;
      // The engine's stick phase with the largest overlap.
      while (k < r.exact_phases.size() && r.exact_phases[k].end < e.start) ++k;
      double best = 0;
      for (std::size_t p = k; p < r.exact_phases.size() && r.exact_phases[p].start <= e.end; ++p) {
        const double overlap =
            std::min(e.end, r.exact_phases[p].end) - std::max(e.start, r.exact_phases[p].start);
        if (overlap > best) {
          best = overlap;
          m.phase_start = r.exact_phases[p].start;
          m.phase_end = r.exact_phases[p].end;
        }
      }
      r.matched.push_back(m);
      ++i;
      ++j;
    }
  }

  // Creep: inside each exact stick phase, less the stop-time margin at ends
  // that are real stops or breakaways (not the record's own ends).
  const std::size_t creep_phase_none = r.exact_phases.size();
  std::size_t creep_phase = creep_phase_none;
  for (std::size_t p = 0; p < r.exact_phases.size(); ++p) {
    const StickInterval& s = r.exact_phases[p];
    const double lo = s.start <= r.t_first ? s.start : s.start + r.stop_time_margin;
    const double hi = s.end >= r.t_last ? s.end : s.end - r.stop_time_margin;
    if (lo > hi) continue;
    auto row = std::lower_bound(history.t.begin(), history.t.end(), lo);
    for (; row != history.t.end() && *row <= hi; ++row) {
      const std::size_t n = static_cast<std::size_t>(row - history.t.begin());
      ++r.creep_samples;
      const double speed = std::fabs(history.v[n]);
      if (creep_phase == creep_phase_none || speed > r.creep_max_velocity) {
        r.creep_max_velocity = speed;
        r.creep_time = *row;
        creep_phase = p;
      }
    }
  }

  // Regime over the last window.
  const double record = r.t_last - r.t_first;
  const double window = std::min(options.regime_window * r.period, record);
  r.regime_window_start = r.t_last - window;
  // Every model's steady state: a closed form where one applies, else the
  // exact engine period after period (classification.hpp).
  const Classification steady = classify(model);
  r.exact_regime = steady.regime;
  r.exact_regime_method = steady.method;
  const Shown exact_shown = shown_regime(history.t, v_exact, r.exact_sticks, r.regime_window_start,
                                         r.stick_velocity, window / r.period);
  const Shown candidate_shown =
      shown_regime(history.t, history.v, r.candidate_sticks, r.regime_window_start,
                   r.stick_velocity, window / r.period);
  r.exact_shown_regime = exact_shown.regime;
  r.exact_stops_per_period = exact_shown.stops_per_period;
  r.candidate_regime = candidate_shown.regime;
  r.candidate_stops_per_period = candidate_shown.stops_per_period;

  // The checks.
  const auto add = [&](CheckKind kind, bool passed, double value, double tolerance,
                       std::string message) {
    r.checks.push_back(Check{kind, passed, value, tolerance, std::move(message)});
  };
  {
    const double relative = r.velocity_max_error / r.velocity_scale;
    const std::size_t n = velocity.max_row;
    add(CheckKind::velocity_max, relative <= options.velocity_max_tolerance, relative,
        options.velocity_max_tolerance,
        "max |v - v_exact| = " + g(relative) + " B/(m w) (" + g(r.velocity_max_error) +
            ") at t = " + g(r.velocity_max_error_time) + " (v = " + g(history.v[n]) +
            ", v_exact = " + g(v_exact[n]) + "); tolerance " + g(options.velocity_max_tolerance) +
            " B/(m w)");
  }
  {
    const double relative = r.velocity_rms_error / r.velocity_scale;
    add(CheckKind::velocity_rms, relative <= options.velocity_rms_tolerance, relative,
        options.velocity_rms_tolerance,
        "RMS(v - v_exact) = " + g(relative) + " B/(m w) (" + g(r.velocity_rms_error) +
            ") over t = " + g(r.t_first) + " .. " + g(r.t_last) + "; tolerance " +
            g(options.velocity_rms_tolerance) + " B/(m w)");
  }
  if (r.has_displacement) {
    const double relative = r.displacement_max_error / r.displacement_scale;
    const std::size_t n = displacement.max_row;
    add(CheckKind::displacement_max, relative <= options.displacement_max_tolerance, relative,
        options.displacement_max_tolerance,
        "max |x - x_exact| = " + g(relative) + " B/(m w^2) (" + g(r.displacement_max_error) +
            ") at t = " + g(r.displacement_max_error_time) + " (x = " + g((*history.x)[n]) +
            ", x_exact = " + g(exact[n].x) + "); tolerance " +
            g(options.displacement_max_tolerance) + " B/(m w^2)");
  }
  {
    const MatchedStick* worst = nullptr;
    bool worst_is_end = false;
    double worst_error = 0;
    std::vector<std::string> outside;
    for (const MatchedStick& m : r.matched) {
      for (const bool end : {false, true}) {
        const double error = end ? m.end_error : m.start_error;
        if (worst == nullptr || std::fabs(error) > std::fabs(worst_error)) {
          worst = &m;
          worst_is_end = end;
          worst_error = error;
        }
      }
      if (std::max(std::fabs(m.start_error), std::fabs(m.end_error)) > r.stop_time_margin)
        outside.push_back("stick " + std::to_string(m.number) + " " + interval(m.exact));
    }
    const double relative = std::fabs(worst_error) / r.period;
    std::string message;
    if (worst == nullptr) {
      message = "no stick to time (neither side shows a stick both share)";
    } else {
      message = "worst: " + std::string(worst_is_end ? "end" : "start") + " of stick " +
                std::to_string(worst->number) + " (exact " + interval(worst->exact) +
                ", candidate " + interval(worst->candidate) + "): error " + signed_g(worst_error) +
                " = " + g(relative) + " periods; tolerance " + g(options.stop_time_tolerance) +
                " periods (" + g(r.stop_time_margin) + ")";
      if (!outside.empty()) {
        message += "; " + std::to_string(outside.size()) + " of " +
                   std::to_string(r.matched.size()) + " sticks outside: ";
        for (std::size_t n = 0; n < outside.size() && n < 5; ++n)
          message += (n ? ", " : "") + outside[n];
        if (outside.size() > 5) message += ", ...";
      } else {
        message += "; all " + std::to_string(r.matched.size()) + " matched sticks within it";
      }
    }
    add(CheckKind::stop_times, outside.empty(), relative, options.stop_time_tolerance, message);
  }
  add(CheckKind::missed_stops, r.missed.size() <= options.max_missed_stops,
      static_cast<double>(r.missed.size()), static_cast<double>(options.max_missed_stops),
      std::to_string(r.missed.size()) + " of " + std::to_string(r.exact_sticks.size()) +
          " exact sticks have no candidate stick" +
          (r.missed.empty() ? std::string() : ": " + interval_list(r.missed)) + "; allowed " +
          std::to_string(options.max_missed_stops));
  add(CheckKind::extra_stops, r.extra.size() <= options.max_extra_stops,
      static_cast<double>(r.extra.size()), static_cast<double>(options.max_extra_stops),
      std::to_string(r.extra.size()) + " of " + std::to_string(r.candidate_sticks.size()) +
          " candidate sticks have no exact stick" +
          (r.extra.empty() ? std::string() : ": " + interval_list(r.extra)) + "; allowed " +
          std::to_string(options.max_extra_stops));
  {
    const double relative = r.creep_max_velocity / r.velocity_scale;
    std::string message;
    if (r.creep_samples == 0) {
      message = "no candidate sample inside an exact stick (less " + g(r.stop_time_margin) +
                " at each end)";
    } else {
      const StickInterval& s = r.exact_phases[creep_phase];
      message = "max |v| inside the exact sticks (less " + g(r.stop_time_margin) +
                " at each end) = " + g(relative) + " B/(m w) (" + g(r.creep_max_velocity) +
                ") at t = " + g(r.creep_time) + " in the exact stick " + interval(s) +
                "; must stay under the stick threshold " + g(options.stick_threshold) + " B/(m w)";
    }
    add(CheckKind::creep, r.creep_max_velocity < r.stick_velocity, relative,
        options.stick_threshold, message);
  }
  {
    const bool same = r.candidate_regime == r.exact_shown_regime;
    const auto shown = [](Regime regime, double per_period) {
      std::string s(to_string(regime));
      if (regime != Regime::stops) s += " (" + g(per_period) + " sticks per period)";
      if (regime == Regime::stops) s += " (at rest throughout)";
      return s;
    };
    add(CheckKind::regime, same, same ? 0 : 1, 0,
        "over t = " + g(r.regime_window_start) + " .. " + g(r.t_last) + " the candidate shows " +
            shown(r.candidate_regime, r.candidate_stops_per_period) + ", the exact motion " +
            shown(r.exact_shown_regime, r.exact_stops_per_period) + "; steady state " +
            steady_text(r.exact_regime, r.exact_regime_method));
  }
  // Whether the samples see every exact phase and event: a check that passed
  // without looking is no evidence.
  const comparison::Resolution seen = comparison::resolution(phases, history.t, r.stop_time_margin);
  r.unresolved = seen.parts;
  r.unresolved_phases = seen.phases;
  r.unresolved_events = seen.events;
  r.resolving_step = seen.resolving_step;
  const bool all_passed =
      std::all_of(r.checks.begin(), r.checks.end(), [](const Check& c) { return c.passed; });
  r.verdict = !all_passed                                     ? Verdict::fail
              : r.unresolved_phases + r.unresolved_events > 0 ? Verdict::inconclusive
                                                              : Verdict::pass;

  if (r.max_spacing > r.stop_time_margin)
    r.notes.push_back("the largest sample spacing " + g(r.max_spacing) +
                      " exceeds the stop-time tolerance " + g(r.stop_time_margin) +
                      ": stops are located only to about the spacing (both sides are read from "
                      "the same samples); archive more often for a sharper check");
  if (record < options.regime_window * r.period)
    r.notes.push_back("the record (" + g(record / r.period) +
                      " periods) is shorter than the regime window (" + g(options.regime_window) +
                      " periods): the regime is read from the whole record");
  if (r.exact_shown_regime != r.exact_regime)
    r.notes.push_back("over the regime window the exact motion shows " +
                      std::string(to_string(r.exact_shown_regime)) + " while its steady state is " +
                      steady_text(r.exact_regime, r.exact_regime_method) +
                      " (a transient that has not died out, or |v| lingering under the stick "
                      "threshold without a stop); the candidate is held to what the exact motion "
                      "shows");
  return r;
}

std::vector<std::string> ComparisonReport::failed_checks() const {
  std::vector<std::string> names;
  for (const Check& check : checks)
    if (!check.passed) names.emplace_back(check.name());
  return names;
}

std::string ComparisonReport::resolution_text() const {
  std::string out;
  const auto list = [&](UnresolvedPart::Kind kind, std::size_t total) {
    std::string items;
    std::size_t shown = 0;
    for (const UnresolvedPart& p : unresolved) {
      if (p.kind != kind || shown == 5) continue;
      items += (shown++ ? ", " : "");
      if (kind == UnresolvedPart::Kind::phase)
        items += std::string(to_string(p.phase)) + " [" + g(p.start) + ", " + g(p.end) +
                 "] (samples " + g(p.spacing) + " apart)";
      else
        items +=
            (p.phase == PhaseKind::stick ? "stop" : "start of " + std::string(to_string(p.phase))) +
            " at t = " + g(p.start) + " (samples " + g(p.spacing) + " apart)";
    }
    if (total > shown) items += ", ...";
    return items;
  };
  if (unresolved_phases > 0)
    out += std::to_string(unresolved_phases) + " exact phase" + (unresolved_phases > 1 ? "s" : "") +
           " longer than the stop-time tolerance " + g(stop_time_margin) + " hold" +
           (unresolved_phases > 1 ? "" : "s") +
           " no sample: " + list(UnresolvedPart::Kind::phase, unresolved_phases);
  if (unresolved_events > 0)
    out += std::string(out.empty() ? "" : "; ") + std::to_string(unresolved_events) +
           " exact event" + (unresolved_events > 1 ? "s lie" : " lies") +
           " between samples further apart than that tolerance " + g(stop_time_margin) + ": " +
           list(UnresolvedPart::Kind::event, unresolved_events);
  return out;
}

std::string ComparisonReport::resolution_advice() const {
  if (resolving_step > 0) return "archive at most every " + g(resolving_step) + " to resolve them";
  return "no archive step can with a stop-time tolerance of 0 (samples would have to fall on "
         "the events)";
}

std::string ComparisonReport::brief_report() const {
  std::string out;
  for (const Check& check : checks)
    out += std::string(check.name()) + ": " + (check.passed ? "PASS " : "FAIL ") + check.message +
           "\n";
  if (unresolved_phases + unresolved_events > 0) out += "resolution: " + resolution_text() + "\n";
  out += "verdict: " + std::string(to_string(verdict));
  const std::vector<std::string> failed = failed_checks();
  if (!failed.empty()) {
    out += " (checks ";
    for (std::size_t i = 0; i < failed.size(); ++i) out += (i ? ", " : "") + failed[i];
    out += ")";
  } else if (verdict == Verdict::inconclusive) {
    out += " (the samples do not resolve the exact motion: " + resolution_advice() + ")";
  }
  return out + "\n";
}

std::string ComparisonReport::full_report() const {
  const CompareOptions& o = options;
  std::string out;
  out += "candidate: " + source + "\n";
  out += "model: " + model_fields(model) + "\n";
  out += "record: " + std::to_string(rows) + " rows, t = " + g(t_first) + " .. " + g(t_last) +
         " (" + g((t_last - t_first) / period) + " periods), largest spacing " + g(max_spacing) +
         "\n";
  out += "scales: velocity B/(m w) = " + g(velocity_scale) +
         ", displacement B/(m w^2) = " + g(displacement_scale) +
         ", period 2 pi / w = " + g(period) + "\n";
  out += "stick detection: |v| < " + g(o.stick_threshold) + " B/(m w) = " + g(stick_velocity) +
         " for at least " + g(o.min_stick_duration) + " periods = " + g(min_stick_time) + "\n";
  out +=
      "tolerances: velocity_max " + g(o.velocity_max_tolerance) +
      " B/(m w) = " + g(o.velocity_max_tolerance * velocity_scale) + ", velocity_rms " +
      g(o.velocity_rms_tolerance) + " B/(m w) = " + g(o.velocity_rms_tolerance * velocity_scale) +
      ", stop_time " + g(o.stop_time_tolerance) + " periods = " + g(stop_time_margin) +
      ", missed_stops " + std::to_string(o.max_missed_stops) + ", extra_stops " +
      std::to_string(o.max_extra_stops) + ", creep under the stick threshold, regime equal" +
      (has_displacement ? ", displacement_max " + g(o.displacement_max_tolerance) +
                              " B/(m w^2) = " + g(o.displacement_max_tolerance * displacement_scale)
                        : std::string()) +
      "; regime window " + g(o.regime_window) + " periods\n";
  out += "velocity error: max " + g(velocity_max_error) + " (" +
         g(velocity_max_error / velocity_scale) + " B/(m w)) at t = " + g(velocity_max_error_time) +
         ", rms " + g(velocity_rms_error) + " (" + g(velocity_rms_error / velocity_scale) +
         " B/(m w))\n";
  if (has_displacement)
    out += "displacement error: max " + g(displacement_max_error) + " (" +
           g(displacement_max_error / displacement_scale) +
           " B/(m w^2)) at t = " + g(displacement_max_error_time) + ", rms " +
           g(displacement_rms_error) + " (" + g(displacement_rms_error / displacement_scale) +
           " B/(m w^2))\n";
  out += "sticks: exact " + std::to_string(exact_sticks.size()) + " (engine stick phases " +
         std::to_string(exact_phases.size()) + "), candidate " +
         std::to_string(candidate_sticks.size()) + ", matched " + std::to_string(matched.size()) +
         ", missed " + std::to_string(missed.size()) + ", extra " + std::to_string(extra.size()) +
         "\n";
  constexpr std::size_t table_rows = 50;
  for (std::size_t n = 0; n < matched.size() && n < table_rows; ++n) {
    const MatchedStick& m = matched[n];
    out += "  stick " + std::to_string(m.number) + ": exact " + interval(m.exact) + " candidate " +
           interval(m.candidate) + " errors " + signed_g(m.start_error) + " " +
           signed_g(m.end_error) +
           (std::isnan(m.phase_start)
                ? std::string(" (no exact stick phase)")
                : " (exact stick phase " + interval(m.phase_start, m.phase_end) + ")") +
           "\n";
  }
  if (matched.size() > table_rows)
    out += "  ... " + std::to_string(matched.size() - table_rows) + " more matched sticks\n";
  if (!missed.empty()) out += "  missed: " + interval_list(missed, 20) + "\n";
  if (!extra.empty()) out += "  extra: " + interval_list(extra, 20) + "\n";
  out += "regime: candidate " + std::string(to_string(candidate_regime)) + ", exact " +
         std::string(to_string(exact_shown_regime)) + " over t = " + g(regime_window_start) +
         " .. " + g(t_last) + "; steady state " + steady_text(exact_regime, exact_regime_method) +
         "\n";
  for (const std::string& note : notes) out += "note: " + note + "\n";
  return out + brief_report();
}

}  // namespace frictionref
