// The report page (report_page.hpp).
#include "report_page.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "../csv_format.hpp"
#include "frictionref/version.hpp"
#include "html_writer.hpp"
#include "report_figures.hpp"
#include "svg_plot.hpp"

namespace frictionref::cli {
namespace {

// Plain, printable, and nothing from outside: generic font families only.
constexpr const char* style = R"(
body { font-family: sans-serif; color: #222; max-width: 980px; margin: 1.5em auto; padding: 0 1em; line-height: 1.4; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.5em 0; }
th, td { border: 1px solid #bbb; padding: 2px 8px; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
td.number { font-family: monospace; text-align: right; white-space: nowrap; }
code, pre { font-family: monospace; }
pre { background: #f5f5f5; border: 1px solid #ddd; padding: 0.6em; white-space: pre-wrap; overflow-wrap: anywhere; }
.verdict { display: inline-block; font-size: 1.6em; font-weight: bold; padding: 0.15em 0.7em; color: #fff; }
.PASS { background: #1a7f37; }
.FAIL { background: #c62828; }
.INCONCLUSIVE { background: #9a6700; }
td.PASS, td.FAIL { color: #fff; font-weight: bold; }
figure { margin: 1em 0; }
figcaption { font-size: 0.92em; color: #444; max-width: 900px; }
svg.plot { max-width: 100%; height: auto; }
div.scroll { overflow-x: auto; }
table.events { font-size: 0.85em; }
.meta { color: #555; }
)";

std::string g(double value) { return number(value); }

void row(HtmlWriter& html, const std::vector<std::string>& cells,
         const std::vector<bool>& numeric = {}) {
  html.open("tr");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const bool is_number = i < numeric.size() && numeric[i];
    html.element("td", cells[i], is_number ? Attributes{{"class", "number"}} : Attributes{});
  }
  html.close("tr");
}

void header_row(HtmlWriter& html, const std::vector<std::string>& cells) {
  html.open("thead");
  html.open("tr");
  for (const std::string& cell : cells) html.element("th", cell);
  html.close("tr");
  html.close("thead");
}

// Each check's value and tolerance are in this unit.
std::string check_unit(CheckKind kind, const MotionScales& scales) {
  switch (kind) {
    case CheckKind::velocity_max:
    case CheckKind::velocity_rms:
    case CheckKind::creep:
      return scales.velocity_name;
    case CheckKind::displacement_max:
      return scales.displacement_name;
    case CheckKind::stop_times:
      return scales.period_unit;
    case CheckKind::missed_stops:
    case CheckKind::extra_stops:
      return "sticks";
    case CheckKind::regime:
      return "0 same, 1 different";
  }
  return "";
}

void provenance(HtmlWriter& html, const ReportSources& s) {
  const ComparisonReport& r = s.report;
  html.element("h2", "1. Candidate and provenance", {{"id", "provenance"}});
  html.open("table");
  html.open("tbody");
  const std::string file_name = s.candidate.path == "-"
                                    ? "standard input"
                                    : std::filesystem::path(s.candidate.path).filename().string();
  row(html, {"candidate file (as given)",
             s.candidate.path == "-" ? "- (standard input)" : s.candidate.path});
  row(html, {"file name", file_name});
  row(html, {"size", fmt::format("{} bytes", s.candidate.bytes.size())});
  html.open("tr");
  html.element("td", "SHA-256");
  html.open("td");
  html.element("code", s.sha256, {{"id", "sha256"}});
  html.close("td");
  html.close("tr");
  row(html, {"read as", r.source});
  row(html, {"samples", fmt::format("{} rows, t = {} .. {}, largest step {}", r.rows, g(r.t_first),
                                    g(r.t_last), g(r.max_spacing))});
  row(html, {"program", std::string("frictionref ") + version});
  html.open("tr");
  html.element("td", "command");
  html.open("td");
  html.element("code", s.command_line, {{"id", "command"}});
  html.close("td");
  html.close("tr");
  row(html, {"date", s.date});
  html.close("tbody");
  html.close("table");
}

void model_section(HtmlWriter& html, const ComparisonReport& r) {
  const Model& m = r.model;
  html.element("h2", "2. Model", {{"id", "model"}});
  html.element("p",
               "m x'' + c x' + k x = F0 + B sin(w t) + sum of B_i sin(w_i t + phi_i) - f, with "
               "Coulomb friction f: R sign(v) while sliding; at rest while the net force stays "
               "within the static limit Rs. Any consistent units (force = mass * length / "
               "time^2); w in rad per time unit.");
  html.open("table");
  header_row(html, {"parameter", "symbol", "value", "unit"});
  html.open("tbody");
  const std::vector<bool> numeric{false, false, true, false};
  row(html, {"mass", "m", g(m.mass), "mass"}, numeric);
  row(html, {"force amplitude", "B", g(m.amplitude), "force"}, numeric);
  row(html, {"angular frequency", "w", g(m.omega), "rad/time"}, numeric);
  row(html, {"sliding friction", "R", g(m.friction), "force"}, numeric);
  row(html, {"friction ratio", "lambda = R/B", g(m.lambda()), "1"}, numeric);
  row(html,
      {m.static_friction ? "static friction" : "static friction (not set: equal to R)", "Rs",
       g(m.static_limit()), "force"},
      numeric);
  row(html, {"spring stiffness", "k", g(m.stiffness), "force/length"}, numeric);
  row(html, {"viscous damping", "c", g(m.damping), "force*time/length"}, numeric);
  row(html, {"constant force", "F0", g(m.force_offset), "force"}, numeric);
  if (m.harmonics.empty()) row(html, {"further harmonics", "B_i, w_i, phi_i", "none", ""});
  for (std::size_t i = 0; i < m.harmonics.size(); ++i) {
    const Harmonic& h = m.harmonics[i];
    const std::string n = std::to_string(i + 1);
    row(html, {"harmonic " + n + ": amplitude", "B_" + n, g(h.amplitude), "force"}, numeric);
    row(html, {"harmonic " + n + ": angular frequency", "w_" + n, g(h.omega), "rad/time"}, numeric);
    row(html, {"harmonic " + n + ": phase", "phi_" + n, g(h.phase), "rad"}, numeric);
  }
  row(html, {"initial position", "x0", g(m.x0), "length"}, numeric);
  row(html, {"initial velocity", "v0", g(m.v0), "length/time"}, numeric);
  row(html, {"initial time", "t0", g(m.t0), "time"}, numeric);
  html.close("tbody");
  html.close("table");
  html.element("p",
               fmt::format("Steady state of this model: {} ({}). Scales of the checks: velocity "
                           "{} = {}, displacement {} = {}, {} = {}.",
                           to_string(r.exact_regime), to_string(r.exact_regime_method),
                           r.scales.velocity_name, g(r.scales.velocity), r.scales.displacement_name,
                           g(r.scales.displacement), r.scales.period_name, g(r.scales.period)));
}

void checks_section(HtmlWriter& html, const ComparisonReport& r) {
  html.element("h2", "3. Verdict and checks", {{"id", "checks"}});
  const std::string verdict(to_string(r.verdict));
  html.open("p");
  html.element("span", verdict, {{"class", "verdict " + verdict}, {"id", "verdict"}});
  const std::vector<std::string> failed = r.failed_checks();
  if (!failed.empty()) {
    std::string list;
    for (const std::string& name : failed) list += (list.empty() ? "" : ", ") + name;
    html.text(" failed checks: " + list);
  }
  html.close("p");
  // The most likely defect first: the checks below are its symptoms.
  html.element("p", "Diagnosis: " + r.diagnosis.text(), {{"id", "diagnosis"}});
  if (r.unresolved_phases + r.unresolved_events > 0)
    html.element("p",
                 "Resolution: " + r.resolution_text() + ". " +
                     std::string(r.verdict == Verdict::inconclusive
                                     ? "Every check passed, but a defect there would pass "
                                       "too: "
                                     : "") +
                     r.resolution_advice() + ".",
                 {{"id", "resolution"}});
  html.open("table", {{"id", "check-table"}});
  header_row(html, {"check", "result", "value", "tolerance", "unit", "what was measured"});
  html.open("tbody");
  for (const Check& check : r.checks) {
    html.open("tr");
    html.element("td", std::string(check.name()));
    const std::string result = check.passed ? "PASS" : "FAIL";
    html.element("td", result, {{"class", result}});
    html.element("td", g(check.value), {{"class", "number"}});
    html.element("td", g(check.tolerance), {{"class", "number"}});
    html.element("td", check_unit(check.kind, r.scales));
    html.element("td", check.message);
    html.close("tr");
  }
  html.close("tbody");
  html.close("table");

  const CompareOptions& o = r.options;
  html.element("h3", "Options used");
  html.open("table");
  header_row(html, {"option", "value", "in the model's units"});
  html.open("tbody");
  const std::vector<bool> numeric{false, true, false};
  row(html, {"--stick-threshold", g(o.stick_threshold), "|v| < " + g(r.stick_velocity)}, numeric);
  row(html, {"--min-stick-duration", g(o.min_stick_duration), g(r.min_stick_time) + " time"},
      numeric);
  row(html,
      {"--velocity-tolerance", g(o.velocity_max_tolerance),
       g(o.velocity_max_tolerance * r.scales.velocity) + " length/time"},
      numeric);
  row(html,
      {"--velocity-rms-tolerance", g(o.velocity_rms_tolerance),
       g(o.velocity_rms_tolerance * r.scales.velocity) + " length/time"},
      numeric);
  row(html, {"--stop-time-tolerance", g(o.stop_time_tolerance), g(r.stop_time_margin) + " time"},
      numeric);
  row(html, {"--max-missed-stops", std::to_string(o.max_missed_stops), ""}, numeric);
  row(html, {"--max-extra-stops", std::to_string(o.max_extra_stops), ""}, numeric);
  if (r.has_displacement)
    row(html,
        {"--displacement-tolerance", g(o.displacement_max_tolerance),
         g(o.displacement_max_tolerance * r.scales.displacement) + " length"},
        numeric);
  row(html, {"--regime-window", g(o.regime_window), g(o.regime_window * r.scales.period) + " time"},
      numeric);
  html.close("tbody");
  html.close("table");
  if (!r.notes.empty()) {
    html.element("h3", "Notes");
    html.open("ul");
    for (const std::string& note : r.notes) html.element("li", note);
    html.close("ul");
  }
}

void figure(HtmlWriter& html, const Plot& plot, const std::string& caption) {
  html.open("figure");
  html.raw(svg_plot(plot));
  html.element("figcaption", caption);
  html.close("figure");
}

void figures_section(HtmlWriter& html, const ComparisonReport& r, const TimeHistory& history) {
  const ReportFigures figures = report_figures(r, history);
  html.element("h2", "4. Figures", {{"id", "figures"}});
  figure(html, figures.velocity,
         "Figure 1. The exact velocity (black; every stop and breakaway drawn where it is) and "
         "the candidate's (orange).");
  figure(html, figures.error,
         fmt::format("Figure 2. The candidate's velocity error at its own times, with the "
                     "velocity_max tolerance {} {} (dashed). Largest error {} at t = {}.",
                     g(r.options.velocity_max_tolerance), r.scales.velocity_name,
                     g(r.velocity_max_error), g(r.velocity_max_error_time)));
  figure(html, figures.zoom,
         "Figure 3. " + figures.zoom_caption +
             " Dots: the candidate's samples; dashed: the stick threshold and the stops.");
}

void interval_table(HtmlWriter& html, const std::string& id,
                    const std::vector<StickInterval>& list) {
  html.open("table", {{"id", id}, {"class", "events"}});
  header_row(html, {"#", "start", "end", "duration"});
  html.open("tbody");
  for (std::size_t i = 0; i < list.size() && i < max_table_rows; ++i)
    row(html, {std::to_string(i + 1), g(list[i].start), g(list[i].end), g(list[i].duration())},
        {true, true, true, true});
  html.close("tbody");
  html.close("table");
}

void omitted(HtmlWriter& html, std::size_t total) {
  if (total > max_table_rows)
    html.element("p", fmt::format("The first {} of {} rows are shown; `frictionref compare "
                                  "--json` (section 6) lists them all.",
                                  max_table_rows, total));
}

void events_section(HtmlWriter& html, const ComparisonReport& r) {
  html.element("h2", "5. Event matching", {{"id", "events"}});
  html.element(
      "p", fmt::format("Sticks are runs of samples with |v| < {} (the stick threshold) lasting "
                       "at least {}, found the same way in the candidate's velocity and in the "
                       "exact velocity at the candidate's times. The exact motion shows {} "
                       "sticks, the candidate {}; {} are matched, {} missed, {} extra. Errors "
                       "are candidate - exact, in time units and in {}.",
                       g(r.stick_velocity), g(r.min_stick_time), r.exact_sticks.size(),
                       r.candidate_sticks.size(), r.matched.size(), r.missed.size(), r.extra.size(),
                       r.scales.period_unit));
  html.element("h3", "Matched sticks");
  html.open("div", {{"class", "scroll"}});
  html.open("table", {{"id", "matched-sticks"}, {"class", "events"}});
  header_row(html,
             {"#", "exact start", "exact end", "candidate start", "candidate end", "start error",
              "end error", "worst [" + r.scales.period_unit + "]", "exact stick phase"});
  html.open("tbody");
  for (std::size_t i = 0; i < r.matched.size() && i < max_table_rows; ++i) {
    const MatchedStick& m = r.matched[i];
    const double worst =
        std::max(std::fabs(m.start_error), std::fabs(m.end_error)) / r.scales.period;
    const std::string phase =
        std::isnan(m.phase_start) ? "none" : g(m.phase_start) + " .. " + g(m.phase_end);
    row(html,
        {std::to_string(m.number), g(m.exact.start), g(m.exact.end), g(m.candidate.start),
         g(m.candidate.end), g(m.start_error), g(m.end_error), g(worst), phase},
        {true, true, true, true, true, true, true, true, false});
  }
  html.close("tbody");
  html.close("table");
  html.close("div");
  omitted(html, r.matched.size());
  html.element("h3", "Missed sticks (exact, no candidate stick)");
  if (r.missed.empty()) {
    html.element("p", "none");
  } else {
    interval_table(html, "missed-sticks", r.missed);
    omitted(html, r.missed.size());
  }
  html.element("h3", "Extra sticks (candidate, no exact stick)");
  if (r.extra.empty()) {
    html.element("p", "none");
  } else {
    interval_table(html, "extra-sticks", r.extra);
    omitted(html, r.extra.size());
  }
  html.element("h3", "Regime");
  html.open("table");
  header_row(
      html, {"", "regime", std::string("sticks per ") + (r.model.ground_motion ? "T*" : "period")});
  html.open("tbody");
  row(html,
      {"candidate", std::string(to_string(r.candidate_regime)), g(r.candidate_stops_per_period)},
      {false, false, true});
  row(html,
      {"exact (at the candidate's times)", std::string(to_string(r.exact_shown_regime)),
       g(r.exact_stops_per_period)},
      {false, false, true});
  html.close("tbody");
  html.close("table");
  html.element("p", fmt::format("Read over t = {} .. {}. Creep: max |v| inside the exact sticks "
                                "(less {} at each end) = {} at t = {}, over {} samples.",
                                g(r.regime_window_start), g(r.t_last), g(r.stop_time_margin),
                                g(r.creep_max_velocity), g(r.creep_time), r.creep_samples));
}

void reproduce_section(HtmlWriter& html, const ReportSources& s) {
  html.element("h2", "6. Reproduce", {{"id", "reproduce"}});
  html.element("p", "From the directory the report was made in, with frictionref " +
                        std::string(version) +
                        ". The model and every tolerance are spelled out with numbers that read "
                        "back to the same doubles.");
  html.open("pre", {{"id", "commands"}});
  html.text("# the candidate is the file compared: this must print " + s.sha256 + "\n" +
            s.commands.checksum + "\n" + "# this report\n" + s.command_line + "\n" +
            "# the verdict and the full text report (add --json for every stick)\n" +
            s.commands.compare + "\n" +
            "# the exact reference curve (t,x,v,a,phase with every event) and phase table\n" +
            s.commands.curve + "\n" + s.commands.events + "\n");
  html.close("pre");
}

}  // namespace

std::string report_page(const ReportSources& s) {
  const ComparisonReport& r = s.report;
  const std::string file_name = s.candidate.path == "-"
                                    ? "standard input"
                                    : std::filesystem::path(s.candidate.path).filename().string();
  const std::string verdict(to_string(r.verdict));
  HtmlWriter html;
  html.open("head");
  html.void_element("meta", {{"charset", "utf-8"}});
  html.void_element("meta",
                    {{"name", "viewport"}, {"content", "width=device-width, initial-scale=1"}});
  html.void_element("meta",
                    {{"name", "generator"}, {"content", std::string("frictionref ") + version}});
  html.element("title", "frictionref validation report: " + file_name + ": " + verdict);
  html.open("style");
  html.raw(style);  // CSS is raw text in HTML: no character references there
  html.close("style");
  html.close("head");
  html.open("body");
  html.open("header");
  html.element("h1", "Validation report: " + file_name + " against the exact solution");
  html.element("p", fmt::format("Verdict {} · frictionref {} · {}", verdict, version, s.date),
               {{"class", "meta"}});
  html.close("header");
  html.open("main");
  provenance(html, s);
  model_section(html, r);
  checks_section(html, r);
  figures_section(html, r, s.history);
  events_section(html, r);
  reproduce_section(html, s);
  html.close("main");
  html.open("footer");
  html.element("p",
               "Made by frictionref compare's checks (docs/cross-checking.md). Self-contained: "
               "no scripts, no fonts, styles or images from outside this file.",
               {{"class", "meta"}});
  html.close("footer");
  html.close("body");
  return html.finish();
}

}  // namespace frictionref::cli
