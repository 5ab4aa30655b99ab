// `frictionref convergence`: how fast the stiff-spring (penalty) model
// approaches the exact solution as the friction spring stiffens and the time
// step shrinks. Each run is a StiffSpringSimulator history judged by
// compare(): the same metrics a user's own code gets. The observed order is
// measured between neighbouring stiffnesses, never assumed.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/motion_scales.hpp"
#include "frictionref/stiff_spring.hpp"
#include "model_options.hpp"
#include "model_title.hpp"
#include "stiff.hpp"

namespace frictionref::cli {
namespace {

struct ConvergenceOptions {
  ModelOptions model;
  std::string t_end = "30";
  std::string kf_list = "1e3,1e4,1e5,1e6,1e7,1e8,1e9";
  std::string dt_fractions = "0.5,0.1,0.02";
  std::string output_dt = "0.01";
  std::string contact_damping = "0";
  std::string format = "csv";
  OutputFileOption output;
  std::string plot;
};

// One stiff-spring run judged against the exact solution.
struct Run {
  double kf = 0;
  double dt_fraction = 0;  // of the stability limit 2 sqrt(m / kf)
  double dt = 0;           // the step used
  std::uint64_t steps = 0;
  ComparisonReport report;
  double stop_time_error = std::numeric_limits<double>::quiet_NaN();  // max |start/end error|
  double order_velocity = std::numeric_limits<double>::quiet_NaN();   // vs the previous kf
  double order_stop_time = std::numeric_limits<double>::quiet_NaN();
};

std::vector<double> parse_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const double value = parse_number({option, item});
    if (!std::isfinite(value) || !(value > 0))
      throw bad_input(
          fmt::format("{} = {}: every entry must be a finite number > 0", option, text));
    values.push_back(value);
  }
  if (values.empty())
    throw bad_input(fmt::format("{} = {}: must list at least one value", option, text));
  if (values.size() > 20) throw bad_input(fmt::format("{} = {}: at most 20 values", option, text));
  return values;
}

// The record a code with this stiffness and step would write, as a TimeHistory.
TimeHistory stiff_history(const Model& model, double t_end, const StiffSpringOptions& options) {
  StiffSpringSimulator simulator(model, t_end, options);
  TimeHistory history;
  history.source = fmt::format("stiff-spring kf={} dt={}", options.kf, simulator.step());
  StiffSample sample;
  while (simulator.next(sample)) {
    history.t.push_back(sample.t);
    history.v.push_back(sample.v);
  }
  return history;
}

// p in error ~ kf^(-p) between two runs; NaN where either error is not positive.
double observed_order(double error_before, double error_after, double kf_before, double kf_after) {
  if (!(error_before > 0) || !(error_after > 0)) return std::numeric_limits<double>::quiet_NaN();
  return -std::log(error_after / error_before) / std::log(kf_after / kf_before);
}

std::string csv_number(double value) { return std::isnan(value) ? "" : number(value); }

void write_csv(std::FILE* out, const std::vector<Run>& runs) {
  std::fputs(
      "kf,dt_fraction,dt,steps,velocity_max_error,velocity_max_error_relative,"
      "velocity_rms_error,stop_time_max_error,matched_stops,missed_stops,extra_stops,verdict,"
      "order_velocity,order_stop_time\n",
      out);
  for (const Run& r : runs) {
    fmt::print(out, "{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", number(r.kf),
               number(r.dt_fraction), number(r.dt), r.steps, number(r.report.velocity_max_error),
               number(r.report.velocity_max_error / r.report.scales.velocity),
               number(r.report.velocity_rms_error), csv_number(r.stop_time_error),
               r.report.matched.size(), r.report.missed.size(), r.report.extra.size(),
               to_string(r.report.verdict), csv_number(r.order_velocity),
               csv_number(r.order_stop_time));
  }
}

void write_markdown(std::FILE* out, const std::vector<Run>& runs, const MotionScales& scales) {
  const auto g = [](double value) {
    return std::isnan(value) ? std::string("-") : fmt::format("{:.3g}", value);
  };
  fmt::print(out,
             "| K_f | dt / limit | dt | max \\|v error\\| / ({}) | max stop-time error | "
             "matched / missed / extra stops | order (v) | order (stop) | compare |\n"
             "|---|---|---|---|---|---|---|---|---|\n",
             scales.velocity_name);
  for (const Run& r : runs) {
    fmt::print(out, "| {} | {} | {} | {} | {} | {} / {} / {} | {} | {} | {} |\n", g(r.kf),
               g(r.dt_fraction), g(r.dt), g(r.report.velocity_max_error / r.report.scales.velocity),
               g(r.stop_time_error), r.report.matched.size(), r.report.missed.size(),
               r.report.extra.size(), g(r.order_velocity), g(r.order_stop_time),
               to_string(r.report.verdict));
  }
}

Figure convergence_figure(const Model& model, const MotionScales& scales,
                          const std::vector<Run>& runs, const std::vector<double>& fractions) {
  Panel velocity = make_panel("max velocity error", "K_f [force/length]",
                              "max |v - v_exact| / (" + scales.velocity_name + ")", {});
  Panel stops = make_panel("max stop-time error (matched sticks)", "K_f [force/length]",
                           "max |t_stiff - t_exact| [time]", {});
  velocity.log_x = velocity.log_y = stops.log_x = stops.log_y = true;
  for (double fraction : fractions) {
    Series v{fmt::format("dt = {} x stability limit", fraction),
             {},
             {},
             Series::Role::candidate,
             false,
             true};
    Series s = v;
    for (const Run& r : runs) {
      if (r.dt_fraction != fraction) continue;
      const double relative = r.report.velocity_max_error / r.report.scales.velocity;
      if (relative > 0) v.x.push_back(r.kf), v.y.push_back(relative);
      if (r.stop_time_error > 0) s.x.push_back(r.kf), s.y.push_back(r.stop_time_error);
    }
    if (!v.x.empty()) velocity.series.push_back(v);
    if (!s.x.empty()) stops.series.push_back(s);
  }
  Figure figure;
  figure.title = "stiff-spring model vs exact solution: " + model_title(model);
  if (!velocity.series.empty()) figure.panels.push_back(velocity);
  if (!stops.series.empty()) figure.panels.push_back(stops);
  return figure;
}

ExitCode run_convergence(const ConvergenceOptions& options, const Invocation& invocation) {
  TypedInputs inputs = options.model.typed_inputs();
  inputs["t_end"] = {"--t-end", options.t_end};
  inputs["output_dt"] = {"--output-dt", options.output_dt};
  inputs["contact_damping"] = {"--contact-damping", options.contact_damping};
  const Model model = options.model.model();
  const double contact_damping = parse_number(inputs.at("contact_damping"));
  const double t_end = parse_number(inputs.at("t_end"));
  const double output_dt = parse_number(inputs.at("output_dt"));
  const std::vector<double> kfs = parse_list(options.kf_list, "--kf-list");
  const std::vector<double> fractions = parse_list(options.dt_fractions, "--dt-fractions");
  for (double fraction : fractions)
    if (!(fraction < 1))
      throw bad_input(
          fmt::format("--dt-fractions = {}: every entry must be < 1 (the step must "
                      "stay below the stability limit)",
                      options.dt_fractions));
  if (options.format != "csv" && options.format != "markdown")
    throw bad_input(fmt::format("--format = {}: must be csv or markdown", options.format));
  // The scales the errors are relative to exist (B > 0, or a record that is
  // not zero throughout).
  const MotionScales scales =
      naming_options(inputs, [&] { return motion_scales(model, "for convergence"); });
  if (!options.plot.empty()) require_figure_path(options.plot, "--plot");

  // Every run is validated before any is computed: bad input costs nothing.
  std::vector<StiffSpringOptions> settings;
  std::uint64_t total_steps = 0;
  for (double kf : kfs) {
    for (double fraction : fractions) {
      StiffSpringOptions stiff;
      stiff.kf = kf;
      stiff.output_dt = output_dt;
      stiff.contact_damping = contact_damping;
      stiff.dt = std::fmin(fraction * stiff.stability_limit(model), output_dt);
      inputs["kf"] = {"--kf-list", fmt::format("{}", kf)};
      const StiffSpringSimulator probe =
          naming_options(inputs, [&] { return StiffSpringSimulator(model, t_end, stiff); });
      total_steps += probe.total_steps();
      settings.push_back(stiff);
    }
  }
  if (total_steps > 10'000'000'000ULL)
    throw bad_input(
        fmt::format("--kf-list = {}: the runs need {} time steps in all, more than "
                    "10^10; use a shorter --t-end or fewer/smaller stiffnesses",
                    options.kf_list, total_steps));

  std::vector<Run> runs;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    Run run;
    run.kf = settings[i].kf;
    run.dt_fraction = fractions[i % fractions.size()];
    const StiffSpringSimulator probe(model, t_end, settings[i]);
    run.dt = probe.step();
    run.steps = probe.total_steps();
    run.report = compare(model, stiff_history(model, t_end, settings[i]));
    for (const MatchedStick& m : run.report.matched) {
      const double worst = std::fmax(std::fabs(m.start_error), std::fabs(m.end_error));
      run.stop_time_error =
          std::isnan(run.stop_time_error) ? worst : std::fmax(run.stop_time_error, worst);
    }
    if (i >= fractions.size()) {
      const Run& before = runs[i - fractions.size()];
      run.order_velocity = observed_order(before.report.velocity_max_error,
                                          run.report.velocity_max_error, before.kf, run.kf);
      run.order_stop_time =
          observed_order(before.stop_time_error, run.stop_time_error, before.kf, run.kf);
    }
    runs.push_back(std::move(run));
  }

  AtomicOutput out(options.output.path(), "-o");
  if (options.format == "csv") {
    std::vector<std::string> metadata = {
        fmt::format("convergence: t_end={} output_dt={} kf_list={} dt_fractions={} "
                    "contact_damping={}",
                    t_end, output_dt, options.kf_list, options.dt_fractions, contact_damping),
        "errors of the stiff-spring model (central differences, friction spring "
        "K_f in series with a Coulomb slider) against the exact solution, judged by "
        "`frictionref compare` with its default tolerances",
        "order_*: p in error ~ K_f^-p between this K_f and the previous one at the "
        "same dt_fraction"};
    StiffSpringOptions first;
    first.contact_damping = contact_damping;
    const std::string note = stiff_ringing_note(model, first);
    if (!note.empty()) metadata.push_back(note);
    write_metadata(out.stream(), model, invocation.command_line, metadata);
    write_csv(out.stream(), runs);
  } else {
    write_markdown(out.stream(), runs, scales);
  }
  if (!options.plot.empty())
    write_figure(convergence_figure(model, scales, runs, fractions), options.plot, "--plot");
  out.commit();
  return exit_success;
}

}  // namespace

Command add_convergence_command(CLI::App& app) {
  auto options = std::make_shared<ConvergenceOptions>();
  CLI::App* command = app.add_subcommand(
      "convergence",
      "Error of the stiff-spring model against the exact solution as K_f and dt vary");
  options->model.add_to(*command);
  numeric(command->add_option("--t-end", options->t_end, "horizon T [time]; > t0"))
      ->type_name("T")
      ->capture_default_str();
  command
      ->add_option("--kf-list", options->kf_list,
                   "friction spring stiffnesses to run [force/length], comma-separated")
      ->type_name("K1,K2,...")
      ->capture_default_str();
  command
      ->add_option("--dt-fractions", options->dt_fractions,
                   "time steps as fractions (< 1) of the stability limit "
                   "2 (sqrt(1+Z^2)-Z) sqrt(m/(K_f+k)), "
                   "comma-separated; a step above --output-dt is cut to it")
      ->type_name("F1,F2,...")
      ->capture_default_str();
  numeric(command->add_option("--output-dt", options->output_dt,
                              "archive step of the stiff runs, where errors are measured [time]"))
      ->type_name("H")
      ->capture_default_str();
  numeric(command->add_option("--contact-damping", options->contact_damping,
                              "damping ratio Z of the friction contact while stuck, as `stiff` "
                              "[1]; >= 0; with static friction > R use about 1, or the runs do "
                              "not converge"))
      ->type_name("Z")
      ->capture_default_str();
  command->add_option("--format", options->format, "table format: csv or markdown")
      ->type_name("FORMAT")
      ->capture_default_str();
  options->output.add_to(*command);
  command
      ->add_option("--plot", options->plot,
                   "also draw both errors against K_f on log-log axes into FILE (.svg or "
                   ".png; needs gnuplot)")
      ->type_name("FILE");
  command->footer(
      "For every K_f and every dt fraction, runs the stiff-spring model (as `frictionref stiff`)\n"
      "and judges its velocity record with `frictionref compare` (default tolerances): max and\n"
      "RMS velocity error, stop-time errors of the matched sticks, missed and extra stops. The\n"
      "observed order p (error ~ K_f^-p) is measured between neighbouring K_f values.\n"
      "Output: CSV (with '# ...' metadata) or a markdown table; see docs/validation.md.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Example:\n"
      "  frictionref convergence --lambda 0.7 --format markdown --plot convergence.svg");
  return {command, [options](const Invocation& invocation) {
            return run_convergence(*options, invocation);
          }};
}

}  // namespace frictionref::cli
