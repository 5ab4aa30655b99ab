#include "model_options.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace frictionref::cli {

double parse_number(const TypedNumber& number) {
  const char* begin = number.text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  // Overflow gives +-inf and underflow a correctly rounded tiny value; both
  // are numbers, and inf is then refused by the finite rule like "inf" itself.
  if (number.text.empty() || end != begin + number.text.size()) {
    throw bad_input(fmt::format("{} = {}: must be a number", number.option, number.text));
  }
  return value;
}

CliError to_bad_input(const InvalidInput& error, const TypedInputs& inputs) {
  const auto typed = inputs.find(error.parameter());
  if (typed == inputs.end()) {
    return bad_input(fmt::format("{} = {}: {}", error.parameter(), error.value(), error.rule()));
  }
  return bad_input(fmt::format("{} = {}: {}", typed->second.option, typed->second.text,
                               error.rule()));
}

void ModelOptions::add_to(CLI::App& command) {
  const char* group = "Model (any consistent units; force = mass * length / time^2)";
  command.add_option("--mass", mass_, "mass m; > 0")
      ->type_name("M")
      ->capture_default_str()
      ->group(group);
  command.add_option("--amplitude", amplitude_, "amplitude B of the force B sin(w t); >= 0")
      ->type_name("B")
      ->capture_default_str()
      ->group(group);
  command.add_option("--omega", omega_, "angular frequency w of the force [rad/time]; > 0")
      ->type_name("W")
      ->capture_default_str()
      ->group(group);
  friction_option_ =
      command.add_option("--friction", friction_, "Coulomb friction force R; >= 0 (or --lambda)")
          ->type_name("R")
          ->group(group);
  lambda_option_ = command
                       .add_option("--lambda", lambda_,
                                   "friction ratio lambda = R / B; >= 0, needs B > 0 (or --friction)")
                       ->type_name("L")
                       ->group(group);
  friction_option_->excludes(lambda_option_);
  command.add_option("--x0", x0_, "initial position [length]")
      ->type_name("X")
      ->capture_default_str()
      ->group(group);
  command.add_option("--v0", v0_, "initial velocity [length/time]")
      ->type_name("V")
      ->capture_default_str()
      ->group(group);
  command.add_option("--t0", t0_, "initial time [time]; the force is B sin(w t), not B sin(w (t - t0))")
      ->type_name("T0")
      ->capture_default_str()
      ->group(group);
}

bool ModelOptions::lambda_given() const { return lambda_option_ && lambda_option_->count() > 0; }

TypedInputs ModelOptions::typed_inputs() const {
  TypedInputs inputs{
      {"mass", {"--mass", mass_}}, {"amplitude", {"--amplitude", amplitude_}},
      {"omega", {"--omega", omega_}}, {"x0", {"--x0", x0_}},
      {"v0", {"--v0", v0_}},         {"t0", {"--t0", t0_}},
  };
  inputs["friction"] = lambda_given() ? TypedNumber{"--lambda", lambda_}
                                      : TypedNumber{"--friction", friction_};
  return inputs;
}

Model ModelOptions::model() const {
  // CLI11 refuses both (excludes); neither cannot be said in CLI11 without an
  // option group, whose help text is much harder to read.
  const bool friction_given = friction_option_ && friction_option_->count() > 0;
  if (!friction_given && !lambda_given()) {
    throw bad_input("--friction/--lambda: exactly one is required (R = lambda * B)");
  }
  const TypedInputs inputs = typed_inputs();
  Model model;
  model.mass = parse_number(inputs.at("mass"));
  model.amplitude = parse_number(inputs.at("amplitude"));
  model.omega = parse_number(inputs.at("omega"));
  const double friction_or_lambda = parse_number(inputs.at("friction"));
  model.x0 = parse_number(inputs.at("x0"));
  model.v0 = parse_number(inputs.at("v0"));
  model.t0 = parse_number(inputs.at("t0"));

  if (!lambda_given()) {
    model.friction = friction_or_lambda;
    naming_options(inputs, [&] { model.validate(); });
    return model;
  }
  // lambda is R / B: check it as itself before it becomes R, so the message
  // talks about what the user typed.
  const double lambda = friction_or_lambda;
  const auto fail = [&](const char* rule) {
    return bad_input(fmt::format("--lambda = {}: {}", lambda_, rule));
  };
  if (!std::isfinite(lambda)) throw fail("must be a finite number");
  if (!(lambda >= 0)) throw fail("must be >= 0");
  model.friction = lambda * model.amplitude;
  if (std::isfinite(model.amplitude) && !std::isfinite(model.friction)) {
    throw fail("R = lambda * B must be a finite number");
  }
  naming_options(inputs, [&] { model.validate(); });
  if (!(model.amplitude > 0)) throw fail("needs --amplitude > 0 (R = lambda * B)");
  return model;
}

}  // namespace frictionref::cli
