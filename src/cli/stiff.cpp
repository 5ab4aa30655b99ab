// `frictionref stiff`: the stiff-spring (penalty friction) model that the exact
// solution is used to check, integrated by central differences as DYNARACK
// does; CSV t,x,v at the archive step (docs/stiff-spring.md).
#include "stiff.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "frictionref/stiff_spring.hpp"
#include "model_options.hpp"

namespace frictionref::cli {
namespace {

// Without --force a run may take at most this many time steps (about an hour
// of CPU at the worst; a typo in --t-end or --kf must not run for days).
constexpr double max_steps_without_force = 1e12;

struct StiffOptions {
  ModelOptions model;
  std::string t_end;
  std::string kf = "1e7";
  std::string dt;  // empty: automatic
  std::string output_dt = "0.01";
  std::string contact_damping = "0";
  OutputFileOption output;
  bool force = false;
  CLI::Option* dt_option = nullptr;
};

void run_stiff(const StiffOptions& options, const Invocation& invocation) {
  const bool dt_given = options.dt_option != nullptr && options.dt_option->count() > 0;
  TypedInputs inputs = options.model.typed_inputs();
  inputs["t_end"] = {"--t-end", options.t_end};
  inputs["kf"] = {"--kf", options.kf};
  inputs["output_dt"] = {"--output-dt", options.output_dt};
  inputs["contact_damping"] = {"--contact-damping", options.contact_damping};
  if (dt_given) inputs["dt"] = {"--dt", options.dt};

  const Model model = options.model.model();
  const double t_end = parse_number(inputs.at("t_end"));
  StiffSpringOptions stiff;
  stiff.kf = parse_number(inputs.at("kf"));
  stiff.output_dt = parse_number(inputs.at("output_dt"));
  stiff.contact_damping = parse_number(inputs.at("contact_damping"));
  if (dt_given) {
    stiff.dt = parse_number(inputs.at("dt"));
    // 0 means "automatic" in the library; on the command line that is
    // spelled by leaving --dt out.
    if (std::isfinite(stiff.dt) && !(stiff.dt > 0)) {
      throw bad_input(fmt::format("--dt = {}: must be > 0 (leave --dt out for the automatic step)",
                                  options.dt));
    }
  }
  StiffSpringSimulator simulator =
      naming_options(inputs, [&] { return StiffSpringSimulator(model, t_end, stiff); });

  const std::uint64_t rows = simulator.total_samples();
  if (!options.force && rows > max_rows_without_force) {
    throw bad_input(fmt::format(
        "--output-dt = {}: the output up to --t-end = {} has {} rows, more than 10^9; pass "
        "--force to write them anyway",
        options.output_dt, options.t_end, rows));
  }
  const std::uint64_t steps = simulator.total_steps();
  if (!options.force && static_cast<double>(steps) > max_steps_without_force) {
    const std::string culprit = dt_given ? fmt::format("--dt = {}", options.dt)
                                         : fmt::format("--t-end = {}", options.t_end);
    throw bad_input(fmt::format(
        "{}: {} time steps of dt = {} (--kf = {}) up to t = {}, more than 10^12; pass --force to "
        "run anyway",
        culprit, steps, simulator.step(), options.kf, options.t_end));
  }

  AtomicOutput out(options.output.path(), "-o");
  write_stiff_csv(out.stream(), simulator, invocation.command_line, {});
  out.commit();
}

}  // namespace

std::string stiff_metadata(const StiffSpringSimulator& simulator) {
  return fmt::format(
      "stiff: kf={} contact_damping={} dt={} dt_auto={} output_dt={} stability_limit={} "
      "steps_per_output={} t_end={} steps={} rows={}",
      simulator.options().kf, simulator.options().contact_damping, simulator.step(),
      simulator.options().dt == 0, simulator.options().output_dt, simulator.stability_limit(),
      simulator.steps_per_output(), simulator.t_end(), simulator.total_steps(),
      simulator.total_samples());
}

std::string stiff_ringing_note(const Model& model, const StiffSpringOptions& options) {
  if (!(model.static_limit() > model.friction) || options.contact_damping > 0) return "";
  return "note: static friction Rs > R with --contact-damping 0: the undamped friction spring "
         "rings past Rs at every stop and breaks loose again, so this model does not converge "
         "to the exact motion as kf grows; pass --contact-damping 1 (docs/stiff-spring.md)";
}

void write_stiff_csv(std::FILE* out, StiffSpringSimulator& simulator, const std::string& command,
                     const std::vector<std::string>& extra_metadata,
                     const std::function<void(const StiffSample&)>& observe) {
  std::vector<std::string> metadata = extra_metadata;
  metadata.push_back(stiff_metadata(simulator));
  const std::string note = stiff_ringing_note(simulator.model(), simulator.options());
  if (!note.empty()) metadata.push_back(note);
  write_metadata(out, simulator.model(), command, metadata);
  std::fputs("t,x,v\n", out);
  StiffSample sample;
  while (simulator.next(sample)) {
    fmt::print(out, "{},{},{}\n", sample.t, sample.x, sample.v);
    if (observe) observe(sample);
  }
}

Command add_stiff_command(CLI::App& app) {
  auto options = std::make_shared<StiffOptions>();
  CLI::App* command = app.add_subcommand(
      "stiff",
      "The stiff-spring (penalty) friction model, by central differences as DYNARACK (CSV t,x,v)");
  options->model.add_to(*command);
  numeric(command->add_option("--t-end", options->t_end, "last time T [time]; > t0"))
      ->required()
      ->type_name("T");
  numeric(
      command->add_option("--kf", options->kf, "friction spring stiffness K [force/length]; > 0"))
      ->type_name("K")
      ->capture_default_str();
  options->dt_option =
      numeric(command->add_option("--dt", options->dt,
                                  "time step H [time]; > 0, below the stability limit "
                                  "2 (sqrt(1+Z^2)-Z) sqrt(m/(K+k)) and at most --output-dt "
                                  "(default: 0.1 of the limit)"))
          ->type_name("H");
  numeric(command->add_option("--output-dt", options->output_dt,
                              "archive step H2 [time]: rows at t0, t0 + H2, ... and T; > 0"))
      ->type_name("H2")
      ->capture_default_str();
  numeric(command->add_option("--contact-damping", options->contact_damping,
                              "damping ratio Z of the friction contact while stuck: a dashpot "
                              "2 Z sqrt(K m) beside the spring [1]; >= 0 (needed with static "
                              "friction > R, see below)"))
      ->type_name("Z")
      ->capture_default_str();
  options->output.add_to(*command);
  command->add_flag("--force", options->force, "allow more than 10^9 rows or 10^12 time steps");
  command->footer(
      "Friction acts through a spring K in series with a Coulomb slider z: f = -K (x - z)\n"
      "(- 2 Z sqrt(K m) x' while stuck). The slider is stuck until |f| exceeds the static\n"
      "friction Rs, then slides with |f| = R until the mass turns back (with Rs = R: it\n"
      "moves whenever |f| would exceed R). The model's own spring k, damper c, offset and\n"
      "harmonics act on the mass: explicit central differences\n"
      "  m (x_{n+1} - 2 x_n + x_{n-1}) / H^2 + c (x_{n+1} - x_{n-1}) / 2H + k x_n = F(t_n) + f_n,\n"
      "stable for H < 2 (sqrt(1+Z^2) - Z) sqrt(m/(K+k)); the slider starts at x0 (unloaded\n"
      "spring). With Rs > R use Z near 1: the undamped spring rings past Rs at every stop\n"
      "and breaks loose again, so it does not converge to the exact motion as K grows.\n"
      "The step used is the largest step <= H that divides H2; v is the central difference\n"
      "(x_{n+1} - x_{n-1}) / 2H.\n"
      "The row at T is interpolated between the two steps around it.\n"
      "Output: '# ...' metadata lines (including '# stiff: kf=... dt=... output_dt=...\n"
      "stability_limit=...'), then t,x,v (t [time], x [length], v [length/time]).\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref stiff --lambda 1.01 --v0 -1 --t-end 30 -o stiff.csv\n"
      "  frictionref stiff --lambda 0.7 --t-end 30 --kf 1e5 --dt 1e-4 --output-dt 0.01\n"
      "  frictionref stiff --lambda 0.5 --static-lambda 0.8 --stiffness 1 --kf 1e6 \\\n"
      "    --contact-damping 1 --t-end 30 -o stiff.csv");
  return {command, [options](const Invocation& invocation) {
            run_stiff(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
