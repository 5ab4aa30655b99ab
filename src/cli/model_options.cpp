#include "model_options.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>

namespace frictionref::cli {

double parse_number(const TypedNumber& number) {
  const char* begin = number.text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  // Overflow gives +-inf and underflow a correctly rounded tiny value; both
  // are numbers, and inf is then refused by the finite rule like "inf" itself.
  if (number.text.empty() || end != begin + number.text.size()) {
    throw bad_input(fmt::format("{} = {}: must be a number", number.option, number.text));
  }
  return value;
}

CLI::Option* numeric(CLI::Option* option) {
  // parse_number throws our own error, which CLI11 lets through unchanged.
  return option->check([name = option->get_name()](const std::string& text) {
    parse_number({name, text});
    return std::string();
  });
}

CliError to_bad_input(const InvalidInput& error, const TypedInputs& inputs) {
  const auto typed = inputs.find(error.parameter());
  if (typed == inputs.end()) {
    return bad_input(fmt::format("{} = {}: {}", error.parameter(), error.value(), error.rule()));
  }
  return bad_input(
      fmt::format("{} = {}: {}", typed->second.option, typed->second.text, error.rule()));
}

void ModelOptions::add_to(CLI::App& command) {
  const char* group = "Model (any consistent units; force = mass * length / time^2)";
  const auto add = [&](const char* name, std::string& text, const char* help, const char* type) {
    return numeric(command.add_option(name, text, help))->type_name(type)->group(group);
  };
  add("--mass", mass_, "mass m [mass]; > 0", "M")->capture_default_str();
  add("--amplitude", amplitude_, "amplitude B of the force B sin(w t) [force]; >= 0", "B")
      ->capture_default_str();
  add("--omega", omega_, "angular frequency w of the force [rad/time]; > 0", "W")
      ->capture_default_str();
  friction_option_ =
      add("--friction", friction_, "Coulomb friction force R [force]; >= 0 (or --lambda)", "R");
  lambda_option_ = add("--lambda", lambda_,
                       "friction ratio lambda = R / B [1]; >= 0, needs B > 0 (or --friction)", "L");
  friction_option_->excludes(lambda_option_);
  add("--x0", x0_, "initial position [length]", "X")->capture_default_str();
  add("--v0", v0_, "initial velocity [length/time]", "V")->capture_default_str();
  add("--t0", t0_, "initial time [time]; the force is B sin(w t), not B sin(w (t - t0))", "T0")
      ->capture_default_str();
}

bool ModelOptions::lambda_given() const { return lambda_option_ && lambda_option_->count() > 0; }

TypedInputs ModelOptions::typed_inputs() const {
  TypedInputs inputs{
      {"mass", {"--mass", mass_}},    {"amplitude", {"--amplitude", amplitude_}},
      {"omega", {"--omega", omega_}}, {"x0", {"--x0", x0_}},
      {"v0", {"--v0", v0_}},          {"t0", {"--t0", t0_}},
  };
  inputs["friction"] =
      lambda_given() ? TypedNumber{"--lambda", lambda_} : TypedNumber{"--friction", friction_};
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
