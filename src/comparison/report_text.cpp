// The words of a comparison: the names of checks, verdicts and defects, and
// the text reports (comparison.hpp).
#include <cmath>
#include <string>

#include "frictionref/comparison.hpp"
#include "frictionref/model_fields.hpp"
#include "report_format.hpp"

namespace frictionref {

using comparison::g;
using comparison::interval;
using comparison::interval_list;
using comparison::signed_g;

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

std::string_view to_string(Defect defect) {
  switch (defect) {
    case Defect::none:
      return "none";
    case Defect::unresolved:
      return "unresolved";
    case Defect::time_shift:
      return "time_shift";
    case Defect::scale:
      return "scale";
    case Defect::chattering:
      return "chattering";
    case Defect::creep:
      return "creep";
    case Defect::missed_breakaway:
      return "missed_breakaway";
    case Defect::missed_stop:
      return "missed_stop";
    case Defect::drift:
      return "drift";
    case Defect::offset:
      return "offset";
    case Defect::unclassified:
      return "unclassified";
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

std::optional<Defect> defect_from_string(std::string_view text) {
  for (Defect defect : {Defect::none, Defect::unresolved, Defect::time_shift, Defect::scale,
                        Defect::chattering, Defect::creep, Defect::missed_breakaway,
                        Defect::missed_stop, Defect::drift, Defect::offset, Defect::unclassified})
    if (to_string(defect) == text) return defect;
  return std::nullopt;
}

std::string Diagnosis::text() const {
  std::string name(to_string(defect));
  for (char& c : name)
    if (c == '_') c = ' ';
  if (defect == Defect::none) name = "no defect";
  return name + ": " + evidence;
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

namespace {

// The checks, the resolution and the verdict: the end of both reports.
std::string checks_and_verdict(const ComparisonReport& r) {
  std::string out;
  for (const Check& check : r.checks)
    out += std::string(check.name()) + ": " + (check.passed ? "PASS " : "FAIL ") + check.message +
           "\n";
  if (r.unresolved_phases + r.unresolved_events > 0)
    out += "resolution: " + r.resolution_text() + "\n";
  out += "verdict: " + std::string(to_string(r.verdict));
  const std::vector<std::string> failed = r.failed_checks();
  if (!failed.empty()) {
    out += " (checks ";
    for (std::size_t i = 0; i < failed.size(); ++i) out += (i ? ", " : "") + failed[i];
    out += ")";
  } else if (r.verdict == Verdict::inconclusive) {
    out += " (the samples do not resolve the exact motion: " + r.resolution_advice() + ")";
  }
  return out + "\n";
}

}  // namespace

std::string ComparisonReport::brief_report() const {
  return "diagnosis: " + diagnosis.text() + "\n" + checks_and_verdict(*this);
}

std::string ComparisonReport::full_report() const {
  const CompareOptions& o = options;
  const std::string v_unit = " " + scales.velocity_name;
  const std::string x_unit = " " + scales.displacement_name;
  const std::string t_unit = " " + scales.period_unit;
  std::string out = "diagnosis: " + diagnosis.text() + "\n";
  out += "candidate: " + source + "\n";
  out += "model: " + model_fields(model) + "\n";
  out += "record: " + std::to_string(rows) + " rows, t = " + g(t_first) + " .. " + g(t_last) +
         " (" + g((t_last - t_first) / scales.period) + t_unit + "), largest spacing " +
         g(max_spacing) + "\n";
  out += "scales: velocity " + scales.velocity_name + " = " + g(scales.velocity) +
         ", displacement " + scales.displacement_name + " = " + g(scales.displacement) + ", " +
         scales.period_name + " = " + g(scales.period) + "\n";
  out += "stick detection: |v| < " + g(o.stick_threshold) + v_unit + " = " + g(stick_velocity) +
         " for at least " + g(o.min_stick_duration) + t_unit + " = " + g(min_stick_time) + "\n";
  out += "tolerances: velocity_max " + g(o.velocity_max_tolerance) + v_unit + " = " +
         g(o.velocity_max_tolerance * scales.velocity) + ", velocity_rms " +
         g(o.velocity_rms_tolerance) + v_unit + " = " +
         g(o.velocity_rms_tolerance * scales.velocity) + ", stop_time " + g(o.stop_time_tolerance) +
         t_unit + " = " + g(stop_time_margin) + ", missed_stops " +
         std::to_string(o.max_missed_stops) + ", extra_stops " + std::to_string(o.max_extra_stops) +
         ", creep under the stick threshold, regime equal" +
         (has_displacement ? ", displacement_max " + g(o.displacement_max_tolerance) + x_unit +
                                 " = " + g(o.displacement_max_tolerance * scales.displacement)
                           : std::string()) +
         "; regime window " + g(o.regime_window) + t_unit + "\n";
  out += "velocity error: max " + g(velocity_max_error) + " (" +
         g(velocity_max_error / scales.velocity) + v_unit +
         ") at t = " + g(velocity_max_error_time) + ", rms " + g(velocity_rms_error) + " (" +
         g(velocity_rms_error / scales.velocity) + v_unit + ")\n";
  if (has_displacement)
    out += "displacement error: max " + g(displacement_max_error) + " (" +
           g(displacement_max_error / scales.displacement) + x_unit +
           ") at t = " + g(displacement_max_error_time) + ", rms " + g(displacement_rms_error) +
           " (" + g(displacement_rms_error / scales.displacement) + x_unit + ")\n";
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
         " .. " + g(t_last) + "; steady state " +
         comparison::steady_text(exact_regime, exact_regime_method) + "\n";
  for (const std::string& note : notes) out += "note: " + note + "\n";
  return out + checks_and_verdict(*this);
}

}  // namespace frictionref
