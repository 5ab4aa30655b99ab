// The model as a person gives it - options on the command line (src/cli),
// keyword arguments in Python (src/python) - checked by one set of rules with
// one set of messages. Every number is kept as the text it was given as, so
// a message quotes it as typed: "--mass = -1: must be > 0". Messages name the
// option as the command line spells it; the Python keyword is that name
// without the dashes, '-' read as '_' (docs/cli.md "Model options",
// docs/python.md).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frictionref/error.hpp"
#include "frictionref/model.hpp"

namespace frictionref {

// One number as the user gave it: the option that carried it and its text.
struct TypedNumber {
  std::string option;  // "--mass"
  std::string text;    // "-1"
};

// Library field name (InvalidInput::parameter(): "mass", "t_end",
// "harmonics[0].omega", ...) -> the option and text the user gave for it.
using TypedInputs = std::map<std::string, TypedNumber>;

// The whole text as a double, correctly rounded (strtod; "nan" and "inf" are
// numbers, refused later by the finite rules). Throws InvalidInput(option,
// text, "must be a number") for anything else, including empty text.
double number_from_text(const TypedNumber& number);

// A choice the user did not make, so there is no value to quote:
// "--friction/--lambda: exactly one is required (R = lambda * B)".
class MissingInput : public InvalidInput {
 public:
  MissingInput(std::string parameter, std::string rule)
      : InvalidInput(std::move(parameter), "", std::move(rule)) {}
};

// The one line shown for bad input: "--mass = -1: must be > 0", the rule of
// `error` with the option and text typed for its parameter (looked up in
// `inputs`), else with the parameter and value as they are; "parameter: rule"
// for a MissingInput.
std::string input_message(const InvalidInput& error, const TypedInputs& inputs = {});

// --mass --amplitude --omega (--friction | --lambda) [--static-friction |
// --static-lambda] --stiffness --damping --force-offset --harmonic B,W[,PHI]...
// --x0 --v0 --t0, as text. An unset optional means "not given".
struct ModelInput {
  std::string mass = "1";
  std::string amplitude = "1";
  std::string omega = "1";
  std::optional<std::string> friction;         // R
  std::optional<std::string> lambda;           // L, R = L * B; never together with friction
  std::optional<std::string> static_friction;  // Rs
  std::optional<std::string> static_lambda;    // LS, Rs = LS * B; never with static_friction
  std::string stiffness = "0";
  std::string damping = "0";
  std::string force_offset = "0";
  std::vector<std::string> harmonics;  // each "B,W" or "B,W,PHI"
  std::string x0 = "0";
  std::string v0 = "0";
  std::string t0 = "0";
  // Neither friction nor lambda: refused when true, R = 0 when false (map, sweep).
  bool friction_required = true;

  // A ground motion (ground_motion.hpp, docs/cli.md "Ground-motion records"):
  // the record's file and how to read it. The options after ground_accel
  // need it, except gravity (also the unit of --yield-accel).
  std::optional<std::string> ground_accel;  // --ground-accel FILE
  std::optional<std::string> record_dt;     // --record-dt H: one column at this step [s]
  std::optional<std::string> accel_units;   // --accel-units g|m/s2|cm/s2|ft/s2|in/s2
  std::string gravity = "9.80665";          // --gravity G [length/s^2]: the output's length unit
  std::optional<std::string> scale;         // --scale S
  std::optional<std::string> target_pga;    // --target-pga P [g]
  bool inverse = false;                     // --inverse: the record negated
  bool one_way = false;                     // --one-way: no motion towards negative x
  // --yield-accel KY [g]: R = m KY G, instead of --friction / --lambda.
  std::optional<std::string> yield_accel;
  // The option that named the record's file, for messages about the file
  // (`newmark` reads its records with --record).
  std::string record_option = "--ground-accel";

  // --gravity as a number: finite, > 0; throws InvalidInput naming it.
  double gravity_value() const;
  // The record of ground_accel, read with the options above (null without
  // one). Throws InvalidInput naming the option (record_option for the file
  // itself) or the file and line.
  std::shared_ptr<const GroundMotion> record() const;

  // The typed model fields by library field name (friction -> --lambda if
  // given; harmonics[i].amplitude/omega/phase -> the i-th --harmonic), for
  // naming errors the library raises later (the engine refusing a model).
  TypedInputs typed_inputs() const;

  // The model, parsed and validated. Throws InvalidInput whose parameter is
  // the option ("--mass") and whose value is the text as typed, or
  // MissingInput("--friction/--lambda"), so input_message(error) is the line
  // to show. Both friction and
  // lambda (or both static forms) given is refused by whoever parses them.
  Model model() const;
};

}  // namespace frictionref
