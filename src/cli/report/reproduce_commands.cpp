// Commands that reproduce a report (reproduce_commands.hpp).
#include "reproduce_commands.hpp"

#include <cmath>
#include <cstring>

#include "../csv_format.hpp"

namespace frictionref::cli {
namespace {

// "frictionref" and `args`, shell-quoted as "# command:" lines are.
std::string shell_line(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"frictionref"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  return command_line(static_cast<int>(argv.size()), argv.data());
}

void append(std::vector<std::string>& to, const std::vector<std::string>& more) {
  to.insert(to.end(), more.begin(), more.end());
}

}  // namespace

std::vector<std::string> model_arguments(const Model& m) {
  std::vector<std::string> args{"--mass",  number(m.mass),  "--amplitude", number(m.amplitude),
                                "--omega", number(m.omega), "--friction",  number(m.friction)};
  if (m.static_friction) append(args, {"--static-friction", number(*m.static_friction)});
  if (m.stiffness != 0) append(args, {"--stiffness", number(m.stiffness)});
  if (m.damping != 0) append(args, {"--damping", number(m.damping)});
  if (m.force_offset != 0) append(args, {"--force-offset", number(m.force_offset)});
  for (const Harmonic& h : m.harmonics)
    append(args,
           {"--harmonic", number(h.amplitude) + "," + number(h.omega) + "," + number(h.phase)});
  append(args, {"--x0", number(m.x0), "--v0", number(m.v0), "--t0", number(m.t0)});
  return args;
}

double reference_step(double spacing) {
  const double power = std::pow(10.0, std::floor(std::log10(spacing)));
  for (const double factor : {5.0, 2.0, 1.0})
    if (factor * power <= spacing) return factor * power;
  return power / 2;  // log10 rounded up: spacing is just under the power
}

ReproduceCommands reproduce_commands(const ComparisonReport& report, const CompareInputs& typed) {
  const Model& model = report.model;
  const CompareOptions& o = report.options;
  ReproduceCommands commands;
  const std::string file = typed.candidate;
  // The file name quoted as in the other lines: shell_line without its program.
  commands.checksum = file == "-"
                          ? std::string("sha256sum")
                          : "sha256sum" + shell_line({file}).substr(std::strlen("frictionref"));

  std::vector<std::string> compare{"compare", "--candidate", file};
  append(compare, model_arguments(model));
  if (!typed.time_column.empty()) append(compare, {"--time-column", typed.time_column});
  if (!typed.velocity_column.empty()) append(compare, {"--velocity-column", typed.velocity_column});
  if (!typed.displacement_column.empty())
    append(compare, {"--displacement-column", typed.displacement_column});
  append(compare,
         {"--stick-threshold", number(o.stick_threshold), "--min-stick-duration",
          number(o.min_stick_duration), "--velocity-tolerance", number(o.velocity_max_tolerance),
          "--velocity-rms-tolerance", number(o.velocity_rms_tolerance), "--stop-time-tolerance",
          number(o.stop_time_tolerance), "--max-missed-stops", std::to_string(o.max_missed_stops),
          "--max-extra-stops", std::to_string(o.max_extra_stops)});
  if (!typed.displacement_column.empty())
    append(compare, {"--displacement-tolerance", number(o.displacement_max_tolerance)});
  append(compare, {"--regime-window", number(o.regime_window)});
  commands.compare = shell_line(compare);

  std::vector<std::string> curve{"curve"};
  append(curve, model_arguments(model));
  append(curve,
         {"--t-end", number(report.t_last), "--dt", number(reference_step(report.max_spacing)),
          "--include-events", "-o", "exact-curve.csv"});
  commands.curve = shell_line(curve);

  std::vector<std::string> events{"events"};
  append(events, model_arguments(model));
  append(events, {"--t-end", number(report.t_last), "-o", "exact-events.csv"});
  commands.events = shell_line(events);
  return commands;
}

}  // namespace frictionref::cli
