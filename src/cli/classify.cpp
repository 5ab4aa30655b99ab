#include "classify.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "frictionref/version.hpp"
#include "model_options.hpp"

namespace frictionref::cli {
namespace {

struct ClassifyOptions {
  ModelOptions model;
  bool json = false;
};

// NaN marks a figure that does not apply to the regime: JSON null.
nlohmann::ordered_json value_or_null(double value) {
  if (std::isnan(value)) return nullptr;
  return value;
}

// The same names as the JSON keys, "n/a" where JSON has null.
std::string text_value(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "n/a";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return number(value.get<double>());
  return value.dump();
}

void run_classify(const ClassifyOptions& options, const Invocation&) {
  const Model model = options.model.model();
  const SteadyState steady =
      naming_options(options.model.typed_inputs(), [&] { return steady_state(model); });
  const nlohmann::ordered_json json = classify_json(model, steady);

  AtomicOutput out(std::nullopt, "");
  if (options.json) {
    fmt::print(out.stream(), "{}\n", json.dump(2));
  } else {
    for (const auto& [key, value] : json.items()) {
      if (key == "model") {
        fmt::print(out.stream(), "model: {}\n", model_fields(model));
      } else {
        fmt::print(out.stream(), "{}: {}\n", key, text_value(value));
      }
    }
  }
  out.commit();
}

}  // namespace

nlohmann::ordered_json classify_json(const Model& model, const SteadyState& steady) {
  nlohmann::ordered_json json;
  json["regime"] = std::string(to_string(steady.regime));
  json["lambda"] = value_or_null(steady.lambda);
  json["threshold"] = value_or_null(steady.threshold);
  json["threshold_quoted"] = value_or_null(steady.threshold_quoted);
  json["regime_by_quoted_threshold"] = std::string(to_string(steady.regime_by_quoted_threshold));
  json["reversal_phase"] = value_or_null(steady.reversal_phase);
  json["breakaway_phase"] = value_or_null(steady.breakaway_phase);
  json["stop_phase"] = value_or_null(steady.stop_phase);
  json["stops_per_period"] = value_or_null(steady.stops_per_period);
  json["stuck_fraction"] = value_or_null(steady.stuck_fraction);
  json["slide_per_half_period"] = value_or_null(steady.slide_per_half_period);
  json["peak_velocity"] = value_or_null(steady.peak_velocity);
  json["energy_per_period"] = value_or_null(steady.energy_per_period);
  json["model"] = {{"mass", model.mass},       {"amplitude", model.amplitude},
                   {"omega", model.omega},     {"friction", model.friction},
                   {"lambda", model.lambda()}, {"x0", model.x0},
                   {"v0", model.v0},           {"t0", model.t0}};
  json["version"] = version;
  return json;
}

Command add_classify_command(CLI::App& app) {
  auto options = std::make_shared<ClassifyOptions>();
  CLI::App* command = app.add_subcommand(
      "classify", "Steady-state regime for lambda = R / B, with its closed-form figures");
  options->model.add_to(*command);
  command->add_flag("--json", options->json, "print one JSON object instead of name: value lines");
  command->footer(
      "Computes the regime: 'continuous' if lambda < lambda* = 2 / sqrt(4 + pi^2) = 0.5370293\n"
      "(no dead bands), 'dead-bands' if lambda* <= lambda < 1 (two stops per forcing period),\n"
      "'stops' if lambda >= 1 (at rest after the transient); also what the seed's quoted\n"
      "threshold 0.536 would say. Needs B > 0; x0, v0 and t0 do not matter.\n"
      "Output: 'name: value' lines, or with --json an object with the keys regime, lambda,\n"
      "threshold, threshold_quoted, regime_by_quoted_threshold, reversal_phase, breakaway_phase,\n"
      "stop_phase (forcing phases w t mod 2 pi [rad]), stops_per_period, stuck_fraction,\n"
      "slide_per_half_period [length], peak_velocity [length/time], energy_per_period [energy],\n"
      "model and version; figures that do not apply to the regime are null ('n/a' in text).\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr).\n"
      "Examples:\n"
      "  frictionref classify --lambda 0.7\n"
      "  frictionref classify --amplitude 2 --friction 1.2 --json");
  return {command, [options](const Invocation& invocation) {
            run_classify(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
