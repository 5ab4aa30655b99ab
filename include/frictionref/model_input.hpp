// The model as a person gives it - options on the command line (src/cli),
// keyword arguments in Python (src/python) - checked by one set of rules with
// one set of messages. Every number is kept as the text it was given as, so
// a message quotes it as typed: "--mass = -1: must be > 0". Messages name the
// option as the command line spells it; the Python keyword is that name
// without the dashes, '-' read as '_' (docs/cli.md "Model options",
// docs/python.md).
#pragma once

#include <map>
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
