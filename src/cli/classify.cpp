#include "classify.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <string>

#include "atomic_output.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "frictionref/classification_json.hpp"
#include "model_options.hpp"

namespace frictionref::cli {
namespace {

struct ClassifyCommandOptions {
  ModelOptions model;
  bool json = false;
  bool simulate = false;
  std::string max_periods = "400";
};

// The same names as the JSON keys, "n/a" where JSON has null.
std::string text_value(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "n/a";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return number(value.get<double>());
  return value.dump();
}

void run_classify(const ClassifyCommandOptions& options, const Invocation&) {
  const Model model = options.model.model();
  ClassifyOptions classify_options;
  classify_options.closed_forms = !options.simulate;
  const double periods = parse_number({"--max-periods", options.max_periods});
  if (!(periods >= 2 && periods <= 1e6 && periods == std::floor(periods)))
    throw bad_input(fmt::format("--max-periods = {}: must be a whole number from 2 to 1000000",
                                options.max_periods));
  classify_options.max_periods = static_cast<std::uint64_t>(periods);
  TypedInputs typed = options.model.typed_inputs();
  const Classification classification = naming_options(typed, [&] {
    try {
      return classify(model, classify_options);
    } catch (const std::runtime_error& error) {
      if (dynamic_cast<const InvalidInput*>(&error)) throw;
      throw internal_error(error.what());
    }
  });
  const nlohmann::ordered_json json = classify_json(model, classification);

  AtomicOutput out(std::nullopt, "");
  if (options.json) {
    fmt::print(out.stream(), "{}\n", json.dump(2));
  } else {
    for (const auto& [key, value] : json.items()) {
      if (key == "model") {
        fmt::print(out.stream(), "model: {}\n", model_fields(model, number));
      } else if (key == "den_hartog" && value.is_object()) {
        for (const auto& [name, field] : value.items())
          fmt::print(out.stream(), "den_hartog.{}: {}\n", name, text_value(field));
      } else {
        fmt::print(out.stream(), "{}: {}\n", key, text_value(value));
      }
    }
  }
  out.commit();
}

}  // namespace

// The library's writer (classification_json.hpp), as values to embed.
nlohmann::ordered_json classify_json(const Model& model, const SteadyState& steady) {
  return nlohmann::ordered_json::parse(steady_state_json(model, steady));
}

nlohmann::ordered_json classify_json(const Model& model, const Classification& c) {
  return nlohmann::ordered_json::parse(classification_json(model, c));
}

Command add_classify_command(CLI::App& app) {
  auto options = std::make_shared<ClassifyCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "classify", "Steady state of the motion: regime, stops per period, method and figures");
  options->model.add_to(*command);
  command->add_flag("--json", options->json, "print one JSON object instead of name: value lines");
  command->add_flag("--simulate", options->simulate,
                    "simulate even where a closed form holds (a cross-check)");
  numeric(command->add_option("--max-periods", options->max_periods,
                              "forcing periods simulated at most before giving up on a "
                              "repeating motion; 2..1000000"))
      ->type_name("N")
      ->capture_default_str();
  command->footer(
      "Regimes: 'continuous' (moves throughout, reversals without stops), 'dead-bands' (sticks\n"
      "of non-zero duration in the steady motion), 'stops' (at rest after the transient),\n"
      "'aperiodic' (moving, no repetition found within --max-periods).\n"
      "method 'closed-form': the seed's model (m x'' = B sin(w t) - R sign v; the regime follows\n"
      "from lambda = R/B against lambda* = 2 / sqrt(4 + pi^2) = 0.5370293, also what the seed's\n"
      "quoted 0.536 would say; needs B > 0, x0, v0, t0 do not matter), or Den Hartog's non-stop\n"
      "solution (spring, no damper, one harmonic) where it exists and is stable.\n"
      "method 'simulation': every other model, with the exact engine from (x0, v0, t0), period\n"
      "after period of the forcing until the motion repeats (multiplicity p periods); the last\n"
      "p periods are measured. Stops count sticks of non-zero duration, not direct reversals.\n"
      "Output: 'name: value' lines, or --json (keys in docs/cli.md); figures that do not\n"
      "apply are null ('n/a' in text).\n"
      "Exit codes: 0 ok, 2 bad input (one line on stderr).\n"
      "Examples:\n"
      "  frictionref classify --lambda 0.7\n"
      "  frictionref classify --amplitude 2 --friction 1.2 --json\n"
      "  frictionref classify --lambda 0.3 --stiffness 1 --omega 2\n"
      "  frictionref classify --lambda 0.4 --static-lambda 0.6 --stiffness 1 --damping 0.1");
  return {command, [options](const Invocation& invocation) {
            run_classify(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
