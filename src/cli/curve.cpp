#include "curve.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "model_options.hpp"
#include "model_title.hpp"

namespace frictionref::cli {
namespace {

struct CurveOptions {
  ModelOptions model;
  std::string t_end;
  std::string dt;
  OutputFileOption output;
  bool include_events = false;
  bool force = false;
  std::string plot;
};

void run_curve(const CurveOptions& options, const Invocation& invocation) {
  TypedInputs inputs = options.model.typed_inputs();
  inputs["t_end"] = {"--t-end", options.t_end};
  inputs["dt"] = {"--dt", options.dt};
  const Model model = options.model.model();
  GridOptions grid;
  grid.t_end = parse_number(inputs.at("t_end"));
  grid.dt = parse_number(inputs.at("dt"));
  grid.include_events = options.include_events;
  naming_options(inputs, [&] { grid.validate(model.t0); });

  const std::uint64_t rows = grid.grid_rows(model.t0);
  if (!options.force && rows > max_rows_without_force) {
    throw bad_input(fmt::format(
        "--dt = {}: the grid up to --t-end = {} has {} rows, more than 10^9; pass --force to "
        "write them anyway",
        options.dt, options.t_end, rows));
  }
  if (!options.plot.empty()) require_figure_path(options.plot, "--plot");
  UniformSampler sampler = naming_options(inputs, [&] { return UniformSampler(model, grid); });

  AtomicOutput out(options.output.path(), "-o");
  FigureSamples samples(rows);
  std::function<void(const State&)> observe;
  if (!options.plot.empty()) observe = [&](const State& state) { samples.add(state); };
  require_reached_end(write_curve_csv(out.stream(), model, sampler, invocation.command_line,
                                      {grid_metadata(model, grid)}, observe));
  // The figure first: if gnuplot fails, the table is not committed either.
  if (!options.plot.empty())
    write_figure(exact_curve_figure(model, samples.states()), options.plot, "--plot");
  out.commit();
}

}  // namespace

std::string grid_metadata(const Model& model, const GridOptions& grid) {
  return fmt::format("grid: t0={} t_end={} dt={} include_events={} grid_rows={}", model.t0,
                     grid.t_end, grid.dt, grid.include_events, grid.grid_rows(model.t0));
}

Summary write_curve_csv(std::FILE* out, const Model& model, UniformSampler& sampler,
                        const std::string& command, const std::vector<std::string>& extra_metadata,
                        const std::function<void(const State&)>& observe) {
  write_metadata(out, model, command, extra_metadata);
  write_state_header(out);
  StateRows rows;
  while (sampler.next(rows)) {
    write_state_rows(out, rows);
    if (observe)
      for (std::size_t i = 0; i < rows.size; ++i) observe(rows[i]);
  }
  return sampler.engine_summary();
}

void FigureSamples::add(const State& state) {
  const bool kink = !states_.empty() && states_.back().phase != state.phase;
  if (seen_++ % stride_ == 0 || kink) states_.push_back(state);
}

Figure exact_curve_figure(const Model& model, const std::vector<State>& states) {
  Series velocity{"exact", {}, {}, Series::Role::reference};
  Series position{"exact", {}, {}, Series::Role::reference};
  for (const State& s : states) {
    velocity.x.push_back(s.t);
    velocity.y.push_back(s.v);
    position.x.push_back(s.t);
    position.y.push_back(s.x);
  }
  Figure figure;
  figure.title = "frictionref exact solution: " + model_title(model);
  figure.panels.push_back(make_panel("velocity", "t [time]", "v [length/time]", {velocity}));
  figure.panels.push_back(make_panel("position", "t [time]", "x [length]", {position}));
  return figure;
}

Command add_curve_command(CLI::App& app) {
  auto options = std::make_shared<CurveOptions>();
  CLI::App* command = app.add_subcommand(
      "curve", "Position, velocity and acceleration on a uniform time grid (CSV)");
  options->model.add_to(*command);
  numeric(command->add_option("--t-end", options->t_end, "last time T [time]; > t0"))
      ->required()
      ->type_name("T");
  numeric(command->add_option("--dt", options->dt, "grid step H [time]; > 0"))
      ->required()
      ->type_name("H");
  options->output.add_to(*command);
  command->add_flag("--include-events", options->include_events,
                    "also write a row at every phase boundary, so plots keep the kinks (a time "
                    "on both the grid and the boundaries appears once)");
  command->add_flag("--force", options->force, "allow more than 10^9 grid rows");
  command->add_option("--plot", options->plot,
                      "also draw velocity and position against time into FILE (.svg or .png; "
                      "needs gnuplot)")
      ->type_name("FILE");
  command->footer(
      "Computes the exact state at t0, t0 + H, t0 + 2 H, ... (each time computed as t0 + i H,\n"
      "never accumulated) and at T itself; with --include-events also at every phase boundary.\n"
      "Output: '# ...' metadata lines (including '# grid: ...'), then t,x,v,a,phase\n"
      "(t [time], x [length], v [length/time], a [length/time^2]). At a phase\n"
      "boundary the row carries the new phase and its acceleration (right limit); the row at T\n"
      "carries the last phase.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref curve --lambda 0.7 --t-end 30 --dt 0.01 --include-events -o curve.csv\n"
      "  frictionref curve --friction 0.3 --t0 -5 --t-end 5 --dt 0.5");
  return {command, [options](const Invocation& invocation) {
            run_curve(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
