#include "events.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "frictionref/phase_estimate.hpp"
#include "model_options.hpp"

namespace frictionref::cli {
namespace {

struct EventsOptions {
  ModelOptions model;
  std::string t_end;
  OutputFileOption output;
  bool summary = false;
  bool force = false;
};

// One line of key=value: counts by phase kind and the state at the horizon.
std::string summary_line(const Summary& summary) {
  const State& end = summary.final_state;
  return fmt::format(
      "termination={} phases={} stick={} slip+={} slip-={} stops={} reversals={} breakaways={} "
      "t={} x={} v={} a={} phase={}",
      to_string(summary.termination), summary.phases, summary.count(PhaseKind::stick),
      summary.count(PhaseKind::slip_forward), summary.count(PhaseKind::slip_backward),
      summary.stops, summary.reversals, summary.breakaways, end.t, end.x, end.v, end.a,
      to_string(end.phase));
}

void run_events(const EventsOptions& options, const Invocation& invocation) {
  TypedInputs inputs = options.model.typed_inputs();
  inputs["t_end"] = {"--t-end", options.t_end};
  const Model model = options.model.model();
  const double t_end = parse_number(inputs.at("t_end"));
  ExactEngine engine = naming_options(inputs, [&] { return ExactEngine(model, t_end); });

  const PhaseEstimate estimate = estimate_phases(model, t_end);
  if (!options.force && !(estimate.phases <= static_cast<double>(max_rows_without_force))) {
    throw bad_input(
        fmt::format("--t-end = {}: about {:.3g} phases ({}), more than 10^9; pass --force "
                    "to run anyway",
                    options.t_end, estimate.phases, estimate.basis));
  }

  AtomicOutput out(options.output.path(), "-o");
  if (options.summary) {
    Phase phase;
    while (engine.next(phase)) {
    }
    require_reached_end(engine.summary());
    fmt::print(out.stream(), "{}\n", summary_line(engine.summary()));
  } else {
    const std::vector<std::string> horizon{fmt::format("horizon: t_end={}", t_end)};
    require_reached_end(write_events_csv(out.stream(), engine, invocation.command_line, horizon));
  }
  out.commit();
}

}  // namespace

Summary write_events_csv(std::FILE* out, ExactEngine& engine, const std::string& command,
                         const std::vector<std::string>& extra_metadata) {
  write_metadata(out, engine.model(), command, extra_metadata);
  write_phase_header(out);
  Phase phase;
  while (engine.next(phase)) write_phase_row(out, phase);
  return engine.summary();
}

Command add_events_command(CLI::App& app) {
  auto options = std::make_shared<EventsOptions>();
  CLI::App* command =
      app.add_subcommand("events", "Table of the stick/slip phases from t0 to T (CSV)");
  options->model.add_to(*command);
  numeric(command->add_option("--t-end", options->t_end, "horizon T [time]; > t0"))
      ->required()
      ->type_name("T");
  options->output.add_to(*command);
  command->add_flag("--summary", options->summary,
                    "print one key=value line (counts per phase kind, stops, final state) "
                    "instead of the table");
  command->add_flag("--force", options->force,
                    "allow more than 10^9 estimated phases (4 per period of the forcing or the "
                    "spring, 4 per record sample)");
  command->footer(
      "Computes every phase of the exact motion: its kind (stick, slip+, slip-) and t, x, v at\n"
      "both ends. Boundaries come from closed forms and bracketed roots, no time step; the\n"
      "last phase is cut at T. Streams: memory stays flat for any horizon.\n"
      "Output: '# ...' metadata lines, then phase,t_begin,t_end,x_begin,x_end,v_begin,v_end\n"
      "(t [time], x [length], v [length/time]); --summary: one line of key=value instead.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref events --lambda 0.7 --t-end 30\n"
      "  frictionref events --mass 2 --amplitude 5 --omega 3 --friction 1.5 --v0 -1 --t-end 100 "
      "-o events.csv\n"
      "  frictionref events --lambda 0.3 --t-end 1e6 --summary");
  return {command, [options](const Invocation& invocation) {
            run_events(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
