// The model options' rules and messages, shared by the command line and the
// Python module (model_input.hpp). The order of the checks decides which
// message a model with several faults gets; tests/cli pins it down.
#include "frictionref/model_input.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>

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

// --yield-accel (R = m KY g) and the record of --ground-accel, attached to
// `model`. Errors name the option as typed.
void add_ground_motion(const ModelInput& input, Model& model) {
  const double gravity = input.gravity_value();
  if (input.yield_accel) {
    const double ky = number_from_text({"--yield-accel", *input.yield_accel});
    if (!std::isfinite(ky) || !(ky >= 0))
      refuse("--yield-accel", *input.yield_accel, "must be a finite number >= 0 (in g)");
    model.friction = model.mass * ky * gravity;
    if (std::isfinite(model.mass) && !std::isfinite(model.friction))
      refuse("--yield-accel", *input.yield_accel, "R = m KY g must be a finite number");
  }
  if (input.one_way && !input.ground_accel)
    throw MissingInput("--one-way", "applies to a ground motion: give --ground-accel FILE");
  model.ground_motion = input.record();
  model.one_way = input.one_way;
}

}  // namespace

double ModelInput::gravity_value() const {
  const double value = number_from_text({"--gravity", gravity});
  if (!std::isfinite(value) || !(value > 0))
    refuse("--gravity", gravity,
           "must be a finite number > 0 (standard gravity in the output's length unit per s^2)");
  return value;
}

std::shared_ptr<const GroundMotion> ModelInput::record() const {
  const auto needs_record = [&](const char* option, bool given) {
    if (given && !ground_accel)
      throw MissingInput(option, "applies to a ground motion: give " + record_option + " FILE");
  };
  needs_record("--record-dt", record_dt.has_value());
  needs_record("--accel-units", accel_units.has_value());
  needs_record("--scale", scale.has_value());
  needs_record("--target-pga", target_pga.has_value());
  needs_record("--inverse", inverse);
  GroundMotionReadOptions read;
  read.gravity = gravity_value();
  if (!ground_accel) return nullptr;
  read.inverse = inverse;
  const auto positive = [](const char* option, const std::string& text, const char* what) {
    const double value = number_from_text({option, text});
    if (!std::isfinite(value) || !(value > 0))
      refuse(option, text, std::string("must be a finite number > 0 (") + what + ")");
    return value;
  };
  if (record_dt) read.record_dt = positive("--record-dt", *record_dt, "seconds");
  if (scale) read.scale = positive("--scale", *scale, "a factor; --inverse negates");
  if (target_pga)
    read.target_pga = positive("--target-pga", *target_pga, "the PGA to scale to, in g");
  if (read.scale && read.target_pga)
    refuse("--target-pga", *target_pga,
           "cannot be given with --scale: choose one way of scaling the record");
  if (accel_units) {
    read.units = accel_units_from_string(*accel_units);
    if (!read.units)
      refuse("--accel-units", *accel_units, "must be g, m/s2, cm/s2, ft/s2 or in/s2");
  }
  try {
    return std::make_shared<const GroundMotion>(read_ground_motion(*ground_accel, read));
  } catch (const InvalidInput& error) {
    if (error.parameter() == "file") refuse(record_option, error.value(), error.rule());
    if (error.parameter() == "accel_units")
      refuse("--accel-units", accel_units.value_or("g"), error.rule());
    if (error.parameter() == "record_dt")
      refuse("--record-dt", record_dt.value_or(""), error.rule());
    if (error.parameter() == "target_pga")
      refuse("--target-pga", target_pga.value_or(""), error.rule());
    if (error.parameter() == "scale") refuse("--scale", scale.value_or(""), error.rule());
    throw;
  }
}

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
  if (ground_accel) inputs["ground_motion"] = {record_option, *ground_accel};
  if (one_way) inputs["one_way"] = {"--one-way", "given"};
  inputs["friction"] = lambda        ? TypedNumber{"--lambda", *lambda}
                       : yield_accel ? TypedNumber{"--yield-accel", *yield_accel}
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
  if (yield_accel && (friction || lambda))
    throw MissingInput("--yield-accel", "cannot be given with --friction or --lambda (R = m KY g)");
  if (!friction && !lambda && !yield_accel && friction_required)
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
    const auto fail = [&](const std::string& rule) {
      refuse("--static-lambda", *static_lambda, rule);
    };
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
    add_ground_motion(*this, model);
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
  add_ground_motion(*this, model);
  validate_naming(model, inputs);
  if (!(model.amplitude > 0)) fail("needs --amplitude > 0 (R = lambda * B)");
  return model;
}

}  // namespace frictionref
