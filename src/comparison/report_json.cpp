// compare's report as JSON (frictionref/comparison_json.hpp).
#include <cmath>
#include <nlohmann/json.hpp>

#include "frictionref/comparison_json.hpp"
#include "frictionref/version.hpp"
#include "model_json.hpp"

namespace frictionref {
namespace {

using json = nlohmann::ordered_json;

json interval_json(double start, double end) { return {{"start", start}, {"end", end}}; }

json intervals_json(const std::vector<StickInterval>& list) {
  json out = json::array();
  for (const StickInterval& s : list) out.push_back(interval_json(s.start, s.end));
  return out;
}

json resolution_json(const ComparisonReport& r) {
  json parts = json::array();
  for (const UnresolvedPart& p : r.unresolved)
    parts.push_back({{"kind", p.kind == UnresolvedPart::Kind::phase ? "phase" : "event"},
                     {"phase", std::string(to_string(p.phase))},
                     {"start", p.start},
                     {"end", p.end},
                     {"spacing", p.spacing}});
  return {{"resolved", r.unresolved_phases + r.unresolved_events == 0},
          {"unresolved_phases", r.unresolved_phases},
          {"unresolved_events", r.unresolved_events},
          {"resolving_step", r.resolving_step},
          {"parts", parts}};
}

json error_json(double max, double scale, double max_time, double rms) {
  return {{"max", max},
          {"max_relative", max / scale},
          {"max_time", max_time},
          {"rms", rms},
          {"rms_relative", rms / scale}};
}

json sticks_json(const ComparisonReport& r) {
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
  return {{"exact_phases", intervals_json(r.exact_phases)},
          {"exact", intervals_json(r.exact_sticks)},
          {"candidate", intervals_json(r.candidate_sticks)},
          {"matched", matched},
          {"missed", intervals_json(r.missed)},
          {"extra", intervals_json(r.extra)}};
}

}  // namespace

std::string comparison_json(const ComparisonReport& r, std::string_view command_line) {
  json out;
  out["verdict"] = std::string(to_string(r.verdict));
  out["failed_checks"] = r.failed_checks();
  out["diagnosis"] = {{"defect", std::string(to_string(r.diagnosis.defect))},
                      {"value", r.diagnosis.value},
                      {"evidence", r.diagnosis.evidence},
                      {"text", r.diagnosis.text()}};
  out["resolution"] = resolution_json(r);
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
  out["model"] = detail::model_json(r.model);
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
  out["scales"] = {{"velocity", r.scales.velocity},
                   {"displacement", r.scales.displacement},
                   {"period", r.scales.period},
                   {"velocity_name", r.scales.velocity_name},
                   {"displacement_name", r.scales.displacement_name},
                   {"period_name", r.scales.period_name},
                   {"stick_velocity", r.stick_velocity},
                   {"min_stick_time", r.min_stick_time},
                   {"stop_time_margin", r.stop_time_margin}};
  out["velocity_error"] = error_json(r.velocity_max_error, r.scales.velocity,
                                     r.velocity_max_error_time, r.velocity_rms_error);
  out["displacement_error"] =
      r.has_displacement ? error_json(r.displacement_max_error, r.scales.displacement,
                                      r.displacement_max_error_time, r.displacement_rms_error)
                         : json(nullptr);
  out["sticks"] = sticks_json(r);
  out["creep"] = {{"max_velocity", r.creep_max_velocity},
                  {"max_relative", r.creep_max_velocity / r.scales.velocity},
                  {"time", r.creep_time},
                  {"samples", r.creep_samples}};
  out["regime"] = {{"candidate", std::string(to_string(r.candidate_regime))},
                   {"exact", std::string(to_string(r.exact_shown_regime))},
                   {"steady_state", std::string(to_string(r.exact_regime))},
                   {"steady_state_method", std::string(to_string(r.exact_regime_method))},
                   {"window_start", r.regime_window_start},
                   {"window_end", r.t_last},
                   {"candidate_stops_per_period", r.candidate_stops_per_period},
                   {"exact_stops_per_period", r.exact_stops_per_period}};
  out["notes"] = r.notes;
  out["version"] = version;
  if (!command_line.empty()) out["command"] = std::string(command_line);
  return out.dump(2);
}

}  // namespace frictionref
