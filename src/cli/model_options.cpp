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

void ModelOptions::add_to(CLI::App& command, bool friction_required) {
  add_to(command, friction_required, Selection{});
}

void ModelOptions::add_to(CLI::App& command, bool friction_required, const Selection& selection) {
  friction_required_ = friction_required && selection.friction;
  const char* group = "Model (any consistent units; force = mass * length / time^2)";
  const auto add = [&](const char* name, std::string& text, const char* help, const char* type) {
    return numeric(command.add_option(name, text, help))->type_name(type)->group(group);
  };
  add("--mass", mass_, "mass m [mass]; > 0", "M")->capture_default_str();
  add("--amplitude", amplitude_, "amplitude B of the force B sin(w t) [force]; >= 0", "B")
      ->capture_default_str();
  add("--omega", omega_, "angular frequency w of the force [rad/time]; > 0", "W")
      ->capture_default_str();
  if (selection.friction) {
    friction_option_ =
        add("--friction", friction_, "Coulomb friction force R [force]; >= 0 (or --lambda)", "R");
    lambda_option_ = add("--lambda", lambda_,
                         "friction ratio lambda = R / B [1]; >= 0, needs B > 0 (or --friction)",
                         "L");
    friction_option_->excludes(lambda_option_);
  }
  if (selection.static_friction) {
    static_friction_option_ =
        add("--static-friction", static_friction_,
            "static friction force Rs [force]; >= R (default R; or --static-lambda)", "RS");
    static_lambda_option_ = add("--static-lambda", static_lambda_,
                                "static friction as Rs = LS * B [1]; needs B > 0", "LS");
    static_friction_option_->excludes(static_lambda_option_);
  }
  add("--stiffness", stiffness_, "restoring spring k [force/length]; >= 0", "K")
      ->capture_default_str();
  add("--damping", damping_, "viscous damper c [force*time/length]; >= 0", "C")
      ->capture_default_str();
  add("--force-offset", force_offset_, "constant force F0 added to F(t) [force]", "F0")
      ->capture_default_str();
  command
      .add_option("--harmonic", harmonics_,
                  "adds B sin(W t + PHI) to F(t) (repeatable): amplitude [force], angular "
                  "frequency W > 0 [rad/time], phase [rad], default 0")
      ->type_name("B,W[,PHI]")
      ->group(group)
      ->allow_extra_args(false);
  add("--x0", x0_, "initial position [length]", "X")->capture_default_str();
  add("--v0", v0_, "initial velocity [length/time]", "V")->capture_default_str();
  if (selection.t0)
    add("--t0", t0_, "initial time [time]; the force is B sin(w t), not B sin(w (t - t0))", "T0")
        ->capture_default_str();
}

bool ModelOptions::lambda_given() const { return lambda_option_ && lambda_option_->count() > 0; }

bool ModelOptions::static_lambda_given() const {
  return static_lambda_option_ && static_lambda_option_->count() > 0;
}

Harmonic ModelOptions::harmonic(std::size_t i) const {
  const std::string& text = harmonics_[i];
  const auto fail = [&](const std::string& rule) {
    return bad_input(fmt::format("--harmonic = {}: {}", text, rule));
  };
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    fields.push_back(text.substr(begin, comma == std::string::npos ? comma : comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (fields.size() < 2 || fields.size() > 3)
    throw fail(fmt::format("must be B,W or B,W,PHI (amplitude, angular frequency, phase in "
                           "radians), found {} field{}",
                           fields.size(), fields.size() == 1 ? "" : "s"));
  double values[3] = {0, 0, 0};
  const char* names[3] = {"B", "W", "PHI"};
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const char* begin_text = fields[k].c_str();
    char* end = nullptr;
    values[k] = std::strtod(begin_text, &end);
    if (fields[k].empty() || end != begin_text + fields[k].size())
      throw fail(fmt::format("{} = '{}' must be a number", names[k], fields[k]));
    if (!std::isfinite(values[k])) throw fail(fmt::format("{} must be a finite number", names[k]));
  }
  if (!(values[1] > 0)) throw fail("the angular frequency W must be > 0");
  return Harmonic{values[0], values[1], values[2]};
}

TypedInputs ModelOptions::typed_inputs() const {
  TypedInputs inputs{
      {"mass", {"--mass", mass_}},    {"amplitude", {"--amplitude", amplitude_}},
      {"omega", {"--omega", omega_}}, {"x0", {"--x0", x0_}},
      {"v0", {"--v0", v0_}},          {"t0", {"--t0", t0_}},
  };
  inputs["friction"] = lambda_given() ? TypedNumber{"--lambda", lambda_}
                                      : TypedNumber{"--friction", friction_.empty() ? "0" : friction_};
  if (static_lambda_given()) {
    inputs["static_friction"] = {"--static-lambda", static_lambda_};
  } else if (static_friction_option_ && static_friction_option_->count() > 0) {
    inputs["static_friction"] = {"--static-friction", static_friction_};
  }
  inputs["stiffness"] = {"--stiffness", stiffness_};
  inputs["damping"] = {"--damping", damping_};
  inputs["force_offset"] = {"--force-offset", force_offset_};
  for (std::size_t i = 0; i < harmonics_.size(); ++i) {
    const std::string prefix = "harmonics[" + std::to_string(i) + "].";
    for (const char* field : {"amplitude", "omega", "phase"})
      inputs[prefix + field] = {"--harmonic", harmonics_[i]};
  }
  return inputs;
}

Model ModelOptions::model() const {
  // CLI11 refuses both (excludes); neither cannot be said in CLI11 without an
  // option group, whose help text is much harder to read.
  const bool friction_given = friction_option_ && friction_option_->count() > 0;
  if (!friction_given && !lambda_given()) {
    if (friction_required_)
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
  model.stiffness = parse_number(inputs.at("stiffness"));
  model.damping = parse_number(inputs.at("damping"));
  model.force_offset = parse_number(inputs.at("force_offset"));
  for (std::size_t i = 0; i < harmonics_.size(); ++i) model.harmonics.push_back(harmonic(i));
  const auto static_input = inputs.find("static_friction");
  const double static_value =
      static_input != inputs.end() ? parse_number(static_input->second) : 0.0;
  // --static-lambda is Rs / B: checked as itself before it becomes Rs.
  if (static_lambda_given()) {
    const auto fail = [&](const char* rule) {
      return bad_input(fmt::format("--static-lambda = {}: {}", static_lambda_, rule));
    };
    if (!std::isfinite(static_value)) throw fail("must be a finite number");
    if (!(static_value >= 0)) throw fail("must be >= 0");
    if (!(model.amplitude > 0) && std::isfinite(model.amplitude) && model.amplitude >= 0)
      throw fail("needs --amplitude > 0 (Rs = LS * B)");
    model.static_friction = static_value * model.amplitude;
    if (std::isfinite(model.amplitude) && !std::isfinite(*model.static_friction))
      throw fail("Rs = LS * B must be a finite number");
  } else if (static_input != inputs.end()) {
    model.static_friction = static_value;
  }

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
