// The model options' rules and messages, shared by the command line and the
// Python module (model_input.hpp). The order of the checks decides which
// message a model with several faults gets; tests/cli pins it down.
#include "frictionref/model_input.hpp"

#include <cmath>
#include <cstdlib>

namespace frictionref {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& text,
                         const std::string& rule) {
  throw InvalidInput(option, text, rule);
}

// The i-th --harmonic "B,W[,PHI]" as numbers.
Harmonic parse_harmonic(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    fields.push_back(text.substr(begin, comma == std::string::npos ? comma : comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (fields.size() < 2 || fields.size() > 3)
    refuse("--harmonic", text,
           "must be B,W or B,W,PHI (amplitude, angular frequency, phase in radians), found " +
               std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields"));
  double values[3] = {0, 0, 0};
  const char* names[3] = {"B", "W", "PHI"};
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const char* begin_text = fields[k].c_str();
    char* end = nullptr;
    values[k] = std::strtod(begin_text, &end);
    if (fields[k].empty() || end != begin_text + fields[k].size())
      refuse("--harmonic", text, std::string(names[k]) + " = '" + fields[k] + "' must be a number");
    if (!std::isfinite(values[k]))
      refuse("--harmonic", text, std::string(names[k]) + " must be a finite number");
  }
  if (!(values[1] > 0)) refuse("--harmonic", text, "the angular frequency W must be > 0");
  return Harmonic{values[0], values[1], values[2]};
}

// model.validate() with the library's field name swapped for the option.
void validate_naming(const Model& model, const TypedInputs& inputs) {
  try {
    model.validate();
  } catch (const InvalidInput& error) {
    const auto typed = inputs.find(error.parameter());
    if (typed == inputs.end()) throw;
    refuse(typed->second.option, typed->second.text, error.rule());
  }
}

}  // namespace

double number_from_text(const TypedNumber& number) {
  const char* begin = number.text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  // Overflow gives +-inf and underflow a correctly rounded tiny value; both
  // are numbers, and inf is then refused by the finite rule like "inf" itself.
  if (number.text.empty() || end != begin + number.text.size())
    refuse(number.option, number.text, "must be a number");
  return value;
}

std::string input_message(const InvalidInput& error, const TypedInputs& inputs) {
  const auto typed = inputs.find(error.parameter());
  if (typed != inputs.end())
    return typed->second.option + " = " + typed->second.text + ": " + error.rule();
  if (dynamic_cast<const MissingInput*>(&error)) return error.parameter() + ": " + error.rule();
  return error.parameter() + " = " + error.value() + ": " + error.rule();
}

TypedInputs ModelInput::typed_inputs() const {
  TypedInputs inputs{
      {"mass", {"--mass", mass}},    {"amplitude", {"--amplitude", amplitude}},
      {"omega", {"--omega", omega}}, {"x0", {"--x0", x0}},
      {"v0", {"--v0", v0}},          {"t0", {"--t0", t0}},
  };
  inputs["friction"] = lambda ? TypedNumber{"--lambda", *lambda}
                              : TypedNumber{"--friction", friction.value_or("0")};
  if (static_lambda) {
    inputs["static_friction"] = {"--static-lambda", *static_lambda};
  } else if (static_friction) {
    inputs["static_friction"] = {"--static-friction", *static_friction};
  }
  inputs["stiffness"] = {"--stiffness", stiffness};
  inputs["damping"] = {"--damping", damping};
  inputs["force_offset"] = {"--force-offset", force_offset};
  for (std::size_t i = 0; i < harmonics.size(); ++i) {
    const std::string prefix = "harmonics[" + std::to_string(i) + "].";
    for (const char* field : {"amplitude", "omega", "phase"})
      inputs[prefix + field] = {"--harmonic", harmonics[i]};
  }
  return inputs;
}

Model ModelInput::model() const {
  if (!friction && !lambda && friction_required)
    throw MissingInput("--friction/--lambda", "exactly one is required (R = lambda * B)");
  const TypedInputs inputs = typed_inputs();
  Model model;
  model.mass = number_from_text(inputs.at("mass"));
  model.amplitude = number_from_text(inputs.at("amplitude"));
  model.omega = number_from_text(inputs.at("omega"));
  const double friction_or_lambda = number_from_text(inputs.at("friction"));
  model.x0 = number_from_text(inputs.at("x0"));
  model.v0 = number_from_text(inputs.at("v0"));
  model.t0 = number_from_text(inputs.at("t0"));
  model.stiffness = number_from_text(inputs.at("stiffness"));
  model.damping = number_from_text(inputs.at("damping"));
  model.force_offset = number_from_text(inputs.at("force_offset"));
  for (const std::string& text : harmonics) model.harmonics.push_back(parse_harmonic(text));
  const auto static_input = inputs.find("static_friction");
  const double static_value =
      static_input != inputs.end() ? number_from_text(static_input->second) : 0.0;
  // LS is Rs / B: checked as itself before it becomes Rs.
  if (static_lambda) {
    const auto fail = [&](const std::string& rule) { refuse("--static-lambda", *static_lambda, rule); };
    if (!std::isfinite(static_value)) fail("must be a finite number");
    if (!(static_value >= 0)) fail("must be >= 0");
    if (!(model.amplitude > 0) && std::isfinite(model.amplitude) && model.amplitude >= 0)
      fail("needs --amplitude > 0 (Rs = LS * B)");
    model.static_friction = static_value * model.amplitude;
    if (std::isfinite(model.amplitude) && !std::isfinite(*model.static_friction))
      fail("Rs = LS * B must be a finite number");
  } else if (static_input != inputs.end()) {
    model.static_friction = static_value;
  }

  if (!lambda) {
    model.friction = friction_or_lambda;
    validate_naming(model, inputs);
    return model;
  }
  // lambda is R / B: checked as itself before it becomes R, so the message
  // talks about what the user typed.
  const double value = friction_or_lambda;
  const auto fail = [&](const std::string& rule) { refuse("--lambda", *lambda, rule); };
  if (!std::isfinite(value)) fail("must be a finite number");
  if (!(value >= 0)) fail("must be >= 0");
  model.friction = value * model.amplitude;
  if (std::isfinite(model.amplitude) && !std::isfinite(model.friction))
    fail("R = lambda * B must be a finite number");
  validate_naming(model, inputs);
  if (!(model.amplitude > 0)) fail("needs --amplitude > 0 (R = lambda * B)");
  return model;
}

}  // namespace frictionref
