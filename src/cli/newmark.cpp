// `frictionref newmark`: Newmark's sliding-block analysis of ground-motion
// records, the permanent displacement for every record x yield acceleration
// x polarity, exact or by SLAMMER's algorithm (library:
// frictionref/newmark.hpp). All cores; a progress line on a terminal.
#include "frictionref/newmark.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "count_options.hpp"
#include "csv_format.hpp"
#include "figure.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model_input.hpp"
#include "frictionref/slammer_rigid_block.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"
#include "progress_line.hpp"

namespace frictionref::cli {
namespace {

struct NewmarkCliOptions {
  std::vector<std::string> records;
  std::vector<std::string> yield_accels;
  std::string record_dt, accel_units, gravity = "9.80665", scale, target_pga, threads;
  std::string method = "exact";
  bool one_way = false, two_way = false, inverse = false, both_polarities = false;
  bool json = false;
  OutputFileOption output;
  std::string plot;
  CLI::Option *record_dt_option = nullptr, *accel_units_option = nullptr, *scale_option = nullptr,
              *target_pga_option = nullptr;
};

// The records as the options say to read them. Errors name the option, or
// --record with the file (and line).
std::vector<std::shared_ptr<const GroundMotion>> read_records(const NewmarkCliOptions& typed) {
  if (typed.records.size() > NewmarkLimits::records)
    throw bad_input(fmt::format("--record: {} files given, at most {}", typed.records.size(),
                                NewmarkLimits::records));
  ModelInput input;
  input.record_option = "--record";
  input.gravity = typed.gravity;
  if (typed.record_dt_option->count() > 0) input.record_dt = typed.record_dt;
  if (typed.accel_units_option->count() > 0) input.accel_units = typed.accel_units;
  if (typed.scale_option->count() > 0) input.scale = typed.scale;
  if (typed.target_pga_option->count() > 0) input.target_pga = typed.target_pga;
  std::vector<std::shared_ptr<const GroundMotion>> records;
  for (const std::string& path : typed.records) {
    input.ground_accel = path;
    try {
      records.push_back(input.record());
    } catch (const InvalidInput& error) {
      throw bad_input(input_message(error));
    }
  }
  return records;
}

std::vector<double> yield_values(const NewmarkCliOptions& typed, NewmarkMethod method) {
  if (typed.yield_accels.size() > NewmarkLimits::yield_values)
    throw bad_input(fmt::format("--yield-accel: {} values given, at most {}",
                                typed.yield_accels.size(), NewmarkLimits::yield_values));
  std::vector<double> values;
  for (const std::string& text : typed.yield_accels) {
    const double ky = parse_number({"--yield-accel", text});
    if (const std::string rule = yield_accel_rule(ky, method); !rule.empty())
      throw bad_input(fmt::format("--yield-accel = {}: {}", text, rule));
    values.push_back(ky);
  }
  return values;
}

double pga_in_g(const GroundMotion& record) { return record.pga() / record.gravity; }

// "" for an unset value (CSV), the number otherwise.
std::string optional_number(const std::optional<double>& value) {
  return value ? number(*value) : std::string();
}

void write_csv(std::FILE* out, const std::vector<NewmarkResult>& results,
               const std::vector<std::shared_ptr<const GroundMotion>>& records,
               const NewmarkOptions& options, double gravity, const std::string& command) {
  fmt::print(out, "# frictionref {}\n# command: {}\n", version, command);
  std::vector<std::string> polarities;
  for (const Polarity p : options.polarities) polarities.emplace_back(to_string(p));
  fmt::print(out,
             "# newmark: method={} sliding={} polarities={} gravity={} length_unit={} "
             "records={} yield_values={}\n",
             to_string(options.method), options.one_way ? "one-way" : "two-way",
             fmt::join(polarities, ","), number(gravity), length_unit_of_gravity(gravity),
             records.size(), options.yield_accels_g.size());
  fmt::print(out,
             "# newmark: displacement positive downslope (SLAMMER, Jibson 1993): the block "
             "slides when the ground acceleration (normal) or its negative (inverse) exceeds "
             "KY g\n");
  for (const auto& record : records)
    for (const std::string& line : record_metadata(*record)) fmt::print(out, "# {}\n", line);
  std::fputs(
      "record,yield_accel_g,pga_g,polarity,method,displacement_at_record_end,"
      "permanent_displacement,slip_episodes,max_relative_velocity\n",
      out);
  const std::size_t per_record = results.size() / std::max<std::size_t>(records.size(), 1);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const NewmarkResult& r = results[i];
    std::string record = r.record;
    // Quoted as CSV if the name needs it.
    if (record.find_first_of(",\"\n") != std::string::npos) {
      std::string quoted = "\"";
      for (const char c : record) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      record = quoted + "\"";
    }
    fmt::print(out, "{},{},{},{},{},{},{},{},{}\n", record, number(r.yield_accel_g),
               number(pga_in_g(*records[i / per_record])), to_string(r.polarity),
               to_string(r.method), number(r.displacement_at_record_end),
               optional_number(r.permanent_displacement), r.slip_episodes,
               number(r.max_relative_velocity));
  }
}

void write_json(std::FILE* out, const std::vector<NewmarkResult>& results,
                const std::vector<std::shared_ptr<const GroundMotion>>& records, double gravity) {
  nlohmann::json array = nlohmann::json::array();
  const std::size_t per_record = results.size() / std::max<std::size_t>(records.size(), 1);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const NewmarkResult& r = results[i];
    const GroundMotion& record = *records[i / per_record];
    nlohmann::json item;
    item["record"] = r.record;
    item["record_sha256"] = record.sha256;
    item["yield_accel_g"] = r.yield_accel_g;
    item["pga_g"] = pga_in_g(record);
    item["polarity"] = to_string(r.polarity);
    item["method"] = to_string(r.method);
    item["displacement_at_record_end"] = r.displacement_at_record_end;
    item["permanent_displacement"] =
        r.permanent_displacement ? nlohmann::json(*r.permanent_displacement) : nlohmann::json();
    item["slip_episodes"] = r.slip_episodes;
    item["max_relative_velocity"] = r.max_relative_velocity;
    item["length_unit"] = length_unit_of_gravity(gravity);
    array.push_back(std::move(item));
  }
  fmt::print(out, "{}\n", array.dump(2));
}

// The classical Newmark curve: permanent displacement (log scale) against
// KY / PGA, one series per record and polarity. Zero and unset
// displacements cannot be drawn on a log scale and are left out.
Figure curve_figure(const std::vector<NewmarkResult>& results,
                    const std::vector<std::shared_ptr<const GroundMotion>>& records,
                    const NewmarkOptions& options, double gravity) {
  std::vector<Series> series;
  const std::size_t per_record = results.size() / records.size();
  std::size_t left_out = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    for (std::size_t p = 0; p < options.polarities.size(); ++p) {
      Series s;
      s.title = records.size() * options.polarities.size() > 12
                    ? ""
                    : fmt::format("{} ({})", records[r]->file, to_string(options.polarities[p]));
      s.markers = true;
      const double pga = pga_in_g(*records[r]);
      for (std::size_t k = 0; k < options.yield_accels_g.size(); ++k) {
        const NewmarkResult& result = results[r * per_record + k * options.polarities.size() + p];
        const std::optional<double>& d = result.permanent_displacement;
        if (!d || !(*d > 0) || !(pga > 0)) {
          ++left_out;
          continue;
        }
        s.x.push_back(result.yield_accel_g / pga);
        s.y.push_back(*d);
      }
      if (!s.x.empty()) series.push_back(std::move(s));
    }
  }
  Panel panel = make_panel(
      fmt::format("permanent displacement against KY / PGA ({}, {}){}",
                  options.one_way ? "one-way" : "two-way", to_string(options.method),
                  left_out > 0 ? fmt::format("; {} zero or unset values not drawn", left_out)
                               : std::string()),
      "KY / PGA [1]", fmt::format("permanent displacement [{}]", length_unit_of_gravity(gravity)),
      series);
  panel.log_y = true;
  Figure figure;
  figure.title = fmt::format("Newmark sliding block: {} record(s), {} yield acceleration(s)",
                             records.size(), options.yield_accels_g.size());
  figure.panels = {panel};
  return figure;
}

// One record and one KY: the ground acceleration with the yield level, the
// relative velocity and the displacement of the exact solution against time
// (SLAMMER's displacement too with --method slammer), per polarity.
Figure history_figure(const std::shared_ptr<const GroundMotion>& record, double ky,
                      const NewmarkOptions& options, double gravity) {
  const std::string unit = length_unit_of_gravity(gravity);
  std::vector<Series> ground, velocity, displacement;
  double t_plot_end = record->t.back();
  for (const Polarity polarity : options.polarities) {
    const std::string name(to_string(polarity));
    const Model model = newmark_model(newmark_record(record, polarity), ky, options.one_way);
    const Solution solution = solve(model, newmark_horizon(model));
    // To the end of the last slide, or of the record.
    for (const Phase& phase : solution.phases)
      if (phase.kind != PhaseKind::stick) t_plot_end = std::max(t_plot_end, phase.t_end);
    // Samples of the record (the motion is a quadratic between them) and
    // every event.
    std::vector<double> times(record->t.begin(), record->t.end());
    for (const Phase& phase : solution.phases) times.push_back(phase.t_begin);
    times.push_back(std::min(t_plot_end, solution.phases.back().t_end));
    std::sort(times.begin(), times.end());
    Series a{fmt::format("a_g downslope ({}) [g]", name), {}, {}};
    Series v{fmt::format("exact ({})", name), {}, {}};
    Series x{fmt::format("exact ({})", name), {}, {}};
    if (options.polarities.size() == 1 && options.method == NewmarkMethod::exact)
      v.role = x.role = Series::Role::reference;
    for (const double t : times) {
      if (t < model.t0 || t > t_plot_end) continue;
      const State state = solution.state_at(t);
      a.x.push_back(t);
      a.y.push_back(-model.ground_acceleration(t) / gravity);
      v.x.push_back(t);
      v.y.push_back(state.v);
      x.x.push_back(t);
      x.y.push_back(state.x);
    }
    ground.push_back(std::move(a));
    velocity.push_back(std::move(v));
    displacement.push_back(std::move(x));
    if (options.method == NewmarkMethod::slammer) {
      SlammerOptions slammer;
      slammer.yield_accel_g = ky;
      slammer.two_way = !options.one_way;
      slammer.inverse = polarity == Polarity::inverse;
      slammer.keep_history = true;
      const SlammerResult run = slammer_rigid_block(
          polarity == Polarity::inverse ? *newmark_record(record, Polarity::normal) : *record,
          slammer);
      Series s{fmt::format("SLAMMER ({})", name), {}, {}};
      s.x = record->t;
      s.y = run.displacement_history;
      displacement.push_back(std::move(s));
    }
  }
  Series level{fmt::format("KY = {} g", number(ky)),
               {record->t.front(), t_plot_end},
               {ky, ky},
               Series::Role::level};
  ground.push_back(level);
  if (!options.one_way) {
    Series minus = level;
    minus.title = "";
    minus.y = {-ky, -ky};
    ground.push_back(minus);
  }
  Figure figure;
  figure.title = fmt::format("Newmark sliding block: {}, KY = {} g, {}", record->file, number(ky),
                             options.one_way ? "one-way (downslope)" : "two-way");
  figure.panels = {make_panel("ground acceleration, downslope positive, and the yield level",
                              "t [s]", "a_g [g]", ground),
                   make_panel("velocity relative to the ground", "t [s]",
                              fmt::format("v [{}/s]", unit), velocity),
                   make_panel("displacement relative to the ground, downslope positive", "t [s]",
                              fmt::format("displacement [{}]", unit), displacement)};
  return figure;
}

void run_newmark(const NewmarkCliOptions& typed, const Invocation& invocation) {
  NewmarkOptions options;
  const std::optional<NewmarkMethod> method = newmark_method_from_string(typed.method);
  if (!method)
    throw bad_input(fmt::format("--method = {}: must be exact or slammer", typed.method));
  options.method = *method;
  options.one_way = !typed.two_way;
  if (typed.inverse) options.polarities = {Polarity::inverse};
  if (typed.both_polarities) options.polarities = {Polarity::normal, Polarity::inverse};
  options.yield_accels_g = yield_values(typed, options.method);
  options.threads = thread_count(typed.threads);
  const double runs = static_cast<double>(typed.records.size()) *
                      static_cast<double>(options.yield_accels_g.size()) *
                      static_cast<double>(options.polarities.size());
  if (runs > NewmarkLimits::runs)
    throw bad_input(fmt::format(
        "--yield-accel: {} records x {} yield values x {} polarities = {:.3g} runs, more than "
        "10^7",
        typed.records.size(), options.yield_accels_g.size(), options.polarities.size(), runs));
  if (!typed.plot.empty()) require_figure_path(typed.plot, "--plot");
  const std::vector<std::shared_ptr<const GroundMotion>> records = read_records(typed);
  ModelInput gravity_input;
  gravity_input.gravity = typed.gravity;
  const double gravity = gravity_input.gravity_value();
  if (options.method == NewmarkMethod::slammer) {
    for (const auto& record : records) {
      if (!record->dt)
        throw bad_input(fmt::format(
            "--record = {}: has no uniform step (a table of times); --method slammer integrates "
            "at the record's step: give an .AT2 file, or one column with --record-dt",
            record->file));
    }
  }

  AtomicOutput out(typed.output.path(), "-o");
  std::vector<NewmarkResult> results;
  {
    ProgressLine progress("newmark", "runs");
    options.progress = [&progress](std::size_t done, std::size_t all) {
      progress.update(done, all);
    };
    try {
      results = newmark_batch(records, options);
    } catch (const InvalidInput& error) {
      throw bad_input(input_message(error));
    }
  }
  if (typed.json)
    write_json(out.stream(), results, records, gravity);
  else
    write_csv(out.stream(), results, records, options, gravity, invocation.command_line);
  if (!typed.plot.empty()) {
    const bool single = records.size() == 1 && options.yield_accels_g.size() == 1;
    write_figure(
        single ? history_figure(records.front(), options.yield_accels_g.front(), options, gravity)
               : curve_figure(results, records, options, gravity),
        typed.plot, "--plot");
  }
  out.commit();
}

}  // namespace

Command add_newmark_command(CLI::App& app) {
  auto options = std::make_shared<NewmarkCliOptions>();
  CLI::App* command = app.add_subcommand(
      "newmark",
      "Newmark's sliding block: the permanent displacement for records x yield accelerations, "
      "exact (or by SLAMMER's algorithm)");
  command
      ->add_option("--record", options->records,
                   "a ground-motion record: PEER .AT2, a time,acceleration table, or one column "
                   "with --record-dt; repeat for several")
      ->required()
      ->type_name("FILE");
  command
      ->add_option("--yield-accel", options->yield_accels,
                   "yield acceleration(s) KY [g], comma-separated or repeated; finite, >= 0 "
                   "(> 0 with --method slammer)")
      ->required()
      ->delimiter(',')
      ->type_name("KY[,KY...]");
  options->scale_option =
      numeric(command->add_option("--scale", options->scale,
                                  "multiply every record's accelerations by S; > 0"))
          ->type_name("S");
  options->target_pga_option =
      numeric(command->add_option("--target-pga", options->target_pga,
                                  "scale each record to this peak ground acceleration [g]; > 0"))
          ->type_name("P");
  options->target_pga_option->excludes(options->scale_option);
  options->record_dt_option =
      numeric(command->add_option("--record-dt", options->record_dt,
                                  "the step of one-column records [s]; > 0"))
          ->type_name("H");
  options->accel_units_option =
      command
          ->add_option("--accel-units", options->accel_units,
                       "units of the files' accelerations: g, m/s2, cm/s2, ft/s2 or in/s2 "
                       "(default g; .AT2 files say G)")
          ->type_name("U");
  numeric(command->add_option("--gravity", options->gravity,
                              "standard gravity in the output's length unit per s^2: 9.80665 "
                              "gives metres, 980.665 centimetres"))
      ->type_name("G")
      ->capture_default_str();
  CLI::Option* one_way =
      command->add_flag("--one-way", options->one_way,
                        "the downslope block, never moving upslope (the default, as SLAMMER)");
  CLI::Option* two_way = command->add_flag("--two-way", options->two_way,
                                           "a block on a horizontal base, sliding both ways");
  one_way->excludes(two_way);
  CLI::Option* inverse = command->add_flag("--inverse", options->inverse,
                                           "the record negated (SLAMMER's inverse polarity) only");
  CLI::Option* both = command->add_flag("--both-polarities", options->both_polarities,
                                        "the normal and the inverse polarity");
  inverse->excludes(both);
  command
      ->add_option("--method", options->method,
                   "exact (the engine; the record linear between samples) or slammer (SLAMMER "
                   "1.1's trapezoidal rigid block, a numerical peer)")
      ->type_name("M")
      ->capture_default_str();
  add_threads_option(*command, options->threads);
  options->output.add_to(*command);
  command->add_flag("--json", options->json,
                    "write a JSON array of objects instead of the CSV table");
  command
      ->add_option("--plot", options->plot,
                   "also draw the Newmark curve (displacement against KY / PGA, log scale) or, "
                   "for one record and one KY, the acceleration, velocity and displacement "
                   "histories, into FILE (.svg or .png; needs gnuplot)")
      ->type_name("FILE");
  command->footer(
      "For each record, KY and polarity, the rigid block's motion relative to the ground:\n"
      "x'' = a - KY g sign(x') while sliding (a the ground acceleration, downslope positive),\n"
      "at rest while |a| <= KY g (one-way: while a <= KY g; it never moves upslope). The\n"
      "record is linear between its samples and 0 after the last, so the exact method solves\n"
      "each interval in closed form (stops are roots of quadratics); 'permanent' is where the\n"
      "block comes to rest once the ground is still (empty / null if it never does: KY = 0).\n"
      "Convention (SLAMMER's, Jibson 1993): displacement positive downslope; 'normal' is the\n"
      "record as given, 'inverse' the record negated. --method slammer runs SLAMMER 1.1's\n"
      "RigidBlock algorithm (trapezoidal rule at the record's step, rest threshold 1e-15, zero\n"
      "samples skipped in the normal polarity), to show its discretisation error; its\n"
      "permanent displacement is its value at the last sample if it is at rest there.\n"
      "Output (CSV): '# ...' metadata (each record's file, SHA-256, header, NPTS, dt, PGA as\n"
      "read, scaling), then record,yield_accel_g,pga_g,polarity,method,\n"
      "displacement_at_record_end,permanent_displacement [length unit of --gravity],\n"
      "slip_episodes,max_relative_velocity [length/s]. --json: an array of objects with those\n"
      "keys (and record_sha256, length_unit). Rows: records, then KY, then polarity.\n"
      "A progress line is shown on a terminal (stderr) when the run takes over a second.\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr, no file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref newmark --record data/records/synthetic/pulse-train.AT2 --yield-accel 0.1\n"
      "  frictionref newmark --record a.AT2 --record b.AT2 --yield-accel 0.02,0.05,0.1,0.2 "
      "--target-pga 0.4 --both-polarities -o newmark.csv --plot newmark.svg\n"
      "  frictionref newmark --record a.AT2 --yield-accel 0.1 --method slammer --gravity 980.665");
  return {command, [options](const Invocation& invocation) {
            run_newmark(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
