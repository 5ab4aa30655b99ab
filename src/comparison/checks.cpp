#include "checks.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "report_format.hpp"

namespace frictionref::comparison {
namespace {

void add(ComparisonReport& r, CheckKind kind, bool passed, double value, double tolerance,
         std::string message) {
  r.checks.push_back(Check{kind, passed, value, tolerance, std::move(message)});
}

void check_velocity(ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact,
                    const ErrorStats& velocity) {
  const CompareOptions& o = r.options;
  const double max = r.velocity_max_error / r.scales.velocity;
  const std::size_t n = velocity.max_row;
  add(r, CheckKind::velocity_max, max <= o.velocity_max_tolerance, max, o.velocity_max_tolerance,
      "max |v - v_exact| = " + g(max) + " " + r.scales.velocity_name + " (" +
          g(r.velocity_max_error) + ") at t = " + g(r.velocity_max_error_time) +
          " (v = " + g(history.v[n]) + ", v_exact = " + g(exact.states[n].v) + "); tolerance " +
          g(o.velocity_max_tolerance) + " " + r.scales.velocity_name);
  const double rms = r.velocity_rms_error / r.scales.velocity;
  add(r, CheckKind::velocity_rms, rms <= o.velocity_rms_tolerance, rms, o.velocity_rms_tolerance,
      "RMS(v - v_exact) = " + g(rms) + " " + r.scales.velocity_name + " (" +
          g(r.velocity_rms_error) + ") over t = " + g(r.t_first) + " .. " + g(r.t_last) +
          "; tolerance " + g(o.velocity_rms_tolerance) + " " + r.scales.velocity_name);
}

void check_displacement(ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact,
                        const ErrorStats& displacement) {
  const CompareOptions& o = r.options;
  const double max = r.displacement_max_error / r.scales.displacement;
  const std::size_t n = displacement.max_row;
  add(r, CheckKind::displacement_max, max <= o.displacement_max_tolerance, max,
      o.displacement_max_tolerance,
      "max |x - x_exact| = " + g(max) + " " + r.scales.displacement_name + " (" +
          g(r.displacement_max_error) + ") at t = " + g(r.displacement_max_error_time) +
          " (x = " + g((*history.x)[n]) + ", x_exact = " + g(exact.states[n].x) + "); tolerance " +
          g(o.displacement_max_tolerance) + " " + r.scales.displacement_name);
}

void check_stop_times(ComparisonReport& r) {
  const CompareOptions& o = r.options;
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
  const double relative = std::fabs(worst_error) / r.scales.period;
  std::string message;
  if (worst == nullptr) {
    message = "no stick to time (neither side shows a stick both share)";
  } else {
    message = "worst: " + std::string(worst_is_end ? "end" : "start") + " of stick " +
              std::to_string(worst->number) + " (exact " + interval(worst->exact) + ", candidate " +
              interval(worst->candidate) + "): error " + signed_g(worst_error) + " = " +
              g(relative) + " " + r.scales.period_unit + "; tolerance " + g(o.stop_time_tolerance) +
              " " + r.scales.period_unit + " (" + g(r.stop_time_margin) + ")";
    if (!outside.empty()) {
      message += "; " + std::to_string(outside.size()) + " of " + std::to_string(r.matched.size()) +
                 " sticks outside: ";
      for (std::size_t n = 0; n < outside.size() && n < 5; ++n)
        message += (n ? ", " : "") + outside[n];
      if (outside.size() > 5) message += ", ...";
    } else {
      message += "; all " + std::to_string(r.matched.size()) + " matched sticks within it";
    }
  }
  add(r, CheckKind::stop_times, outside.empty(), relative, o.stop_time_tolerance, message);
}

void check_stop_counts(ComparisonReport& r) {
  const CompareOptions& o = r.options;
  add(r, CheckKind::missed_stops, r.missed.size() <= o.max_missed_stops,
      static_cast<double>(r.missed.size()), static_cast<double>(o.max_missed_stops),
      std::to_string(r.missed.size()) + " of " + std::to_string(r.exact_sticks.size()) +
          " exact sticks have no candidate stick" +
          (r.missed.empty() ? std::string() : ": " + interval_list(r.missed)) + "; allowed " +
          std::to_string(o.max_missed_stops));
  add(r, CheckKind::extra_stops, r.extra.size() <= o.max_extra_stops,
      static_cast<double>(r.extra.size()), static_cast<double>(o.max_extra_stops),
      std::to_string(r.extra.size()) + " of " + std::to_string(r.candidate_sticks.size()) +
          " candidate sticks have no exact stick" +
          (r.extra.empty() ? std::string() : ": " + interval_list(r.extra)) + "; allowed " +
          std::to_string(o.max_extra_stops));
}

void check_creep(ComparisonReport& r, std::size_t creep_phase) {
  const double relative = r.creep_max_velocity / r.scales.velocity;
  std::string message;
  if (r.creep_samples == 0) {
    message = "no candidate sample inside an exact stick (less " + g(r.stop_time_margin) +
              " at each end)";
  } else {
    const StickInterval& s = r.exact_phases[creep_phase];
    message = "max |v| inside the exact sticks (less " + g(r.stop_time_margin) +
              " at each end) = " + g(relative) + " " + r.scales.velocity_name + " (" +
              g(r.creep_max_velocity) + ") at t = " + g(r.creep_time) + " in the exact stick " +
              interval(s) + "; must stay under the stick threshold " +
              g(r.options.stick_threshold) + " " + r.scales.velocity_name;
  }
  add(r, CheckKind::creep, r.creep_max_velocity < r.stick_velocity, relative,
      r.options.stick_threshold, message);
}

void check_regime(ComparisonReport& r) {
  const bool same = r.candidate_regime == r.exact_shown_regime;
  const std::string per = r.model.ground_motion ? "T*" : "period";
  const auto shown = [&per](Regime regime, double per_period) {
    std::string s(to_string(regime));
    if (regime != Regime::stops) s += " (" + g(per_period) + " sticks per " + per + ")";
    if (regime == Regime::stops) s += " (at rest throughout)";
    return s;
  };
  add(r, CheckKind::regime, same, same ? 0 : 1, 0,
      "over t = " + g(r.regime_window_start) + " .. " + g(r.t_last) + " the candidate shows " +
          shown(r.candidate_regime, r.candidate_stops_per_period) + ", the exact motion " +
          shown(r.exact_shown_regime, r.exact_stops_per_period) + "; steady state " +
          steady_text(r.exact_regime, r.exact_regime_method));
}

}  // namespace

void run_checks(ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact,
                const SampleErrors& errors, std::size_t creep_phase) {
  check_velocity(r, history, exact, errors.velocity);
  if (r.has_displacement) check_displacement(r, history, exact, errors.displacement);
  check_stop_times(r);
  check_stop_counts(r);
  check_creep(r, creep_phase);
  check_regime(r);
}

}  // namespace frictionref::comparison
