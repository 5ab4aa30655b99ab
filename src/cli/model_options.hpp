// The options every model-based command shares (--mass ... --t0), and the
// translation of the library's InvalidInput into a message naming the option
// as the user typed it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli_error.hpp"
#include "frictionref/error.hpp"
#include "frictionref/model.hpp"
#include "frictionref/model_input.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace frictionref::cli {

// TypedNumber (a number as typed, with its option) and TypedInputs (library
// field name -> what the user typed for it) are the library's
// (frictionref/model_input.hpp), shared with the Python module.

// The whole text as a double, correctly rounded (strtod). CLI11 converts via
// strtold and then to double, and that double rounding breaks the round trip of
// numbers we print ourselves (e.g. 1.678986648677672 comes back one ulp off),
// so numeric options are bound as text and converted here.
// Throws bad input "--mass = abc: must be a number" (the library's
// number_from_text, as a CLI error).
double parse_number(const TypedNumber& number);

// Makes CLI11 check, while parsing, that the option's text is a number: a
// missing value (`--mass --lambda 0.3`, where CLI11 takes "--lambda" as the
// mass) is then reported against --mass, not as an unexpected "0.3".
CLI::Option* numeric(CLI::Option* option);

// "--mass = -1: must be > 0": the library's rule with the option and the text
// the user typed (the library's own field name and value if it was not typed).
CliError to_bad_input(const InvalidInput& error, const TypedInputs& inputs);

// Calls f(); an InvalidInput it throws becomes bad input naming the option.
template <class F>
decltype(auto) naming_options(const TypedInputs& inputs, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InvalidInput& error) {
    throw to_bad_input(error, inputs);
  }
}

// "--ground-accel = FILE: is not taken by <command>: <why>" (bad input) if
// the model has a record: for the commands that need what a transient
// record does not have (a steady state, the velocity scale B/(m w)).
void refuse_ground_motion(const Model& model, const std::string& command, const std::string& why);

// --mass --amplitude --omega (--friction | --lambda | --yield-accel)
// [--static-friction | --static-lambda] --stiffness --damping --force-offset
// --harmonic B,W[,PHI]... --x0 --v0 --t0, and a ground motion: --ground-accel
// FILE [--record-dt H] [--accel-units U] [--gravity G] [--scale S |
// --target-pga P] [--inverse] [--one-way]; bound as text. Register once per command with add_to();
// the object must outlive parsing.
class ModelOptions {
 public:
  // Which options add_to registers (all by default). A command that sets the
  // friction itself for every run (sweep) leaves out --friction/--lambda and
  // --static-friction/--static-lambda, and one whose runs all start at t = 0
  // leaves out --t0; model() then takes R = 0, no Rs and t0 = 0.
  struct Selection {
    bool friction = true;         // --friction, --lambda
    bool static_friction = true;  // --static-friction, --static-lambda
    bool t0 = true;               // --t0
  };

  // friction_required = false: neither --friction nor --lambda means R = 0
  // (for commands where an axis or sweep sets the friction).
  void add_to(CLI::App& command, bool friction_required = true);
  void add_to(CLI::App& command, bool friction_required, const Selection& selection);

  // The model, parsed and validated by the library's rules
  // (ModelInput::model()); throws bad input naming the option.
  Model model() const;
  // The options as typed, for the library.
  ModelInput input() const;
  // The typed model options by library field name (friction -> --lambda if
  // given; harmonics[i].amplitude/omega/phase -> the i-th --harmonic).
  TypedInputs typed_inputs() const;

 private:
  bool lambda_given() const;
  bool static_lambda_given() const;
  std::string mass_ = "1";
  std::string amplitude_ = "1";
  std::string omega_ = "1";
  std::string friction_;
  std::string lambda_;
  std::string static_friction_;
  std::string static_lambda_;
  std::string stiffness_ = "0";
  std::string damping_ = "0";
  std::string force_offset_ = "0";
  std::vector<std::string> harmonics_;
  std::string x0_ = "0";
  std::string v0_ = "0";
  std::string t0_ = "0";
  std::string ground_accel_, record_dt_, accel_units_, gravity_ = "9.80665", scale_, target_pga_,
                                                       yield_accel_;
  bool inverse_ = false, one_way_ = false;
  CLI::Option* amplitude_option_ = nullptr;
  CLI::Option* ground_accel_option_ = nullptr;
  CLI::Option* record_dt_option_ = nullptr;
  CLI::Option* accel_units_option_ = nullptr;
  CLI::Option* scale_option_ = nullptr;
  CLI::Option* target_pga_option_ = nullptr;
  CLI::Option* yield_accel_option_ = nullptr;
  CLI::Option* friction_option_ = nullptr;
  CLI::Option* lambda_option_ = nullptr;
  CLI::Option* static_friction_option_ = nullptr;
  CLI::Option* static_lambda_option_ = nullptr;
  bool friction_required_ = true;
};

}  // namespace frictionref::cli
