#include "model_options.hpp"

#include <CLI/CLI.hpp>

namespace frictionref::cli {

double parse_number(const TypedNumber& number) {
  try {
    return number_from_text(number);
  } catch (const InvalidInput& error) {
    throw bad_input(input_message(error));
  }
}

CLI::Option* numeric(CLI::Option* option) {
  // parse_number throws our own error, which CLI11 lets through unchanged.
  return option->check([name = option->get_name()](const std::string& text) {
    parse_number({name, text});
    return std::string();
  });
}

void refuse_ground_motion(const Model& model, const std::string& command, const std::string& why) {
  if (model.ground_motion)
    throw bad_input("--ground-accel = " + model.ground_motion->file + ": is not taken by " +
                    command + ": " + why);
}

CliError to_bad_input(const InvalidInput& error, const TypedInputs& inputs) {
  return bad_input(input_message(error, inputs));
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
  amplitude_option_ =
      add("--amplitude", amplitude_,
          "amplitude B of the force B sin(w t) [force]; >= 0 (0 by default with --ground-accel)",
          "B")
          ->capture_default_str();
  add("--omega", omega_, "angular frequency w of the force [rad/time]; > 0", "W")
      ->capture_default_str();
  if (selection.friction) {
    friction_option_ =
        add("--friction", friction_, "Coulomb friction force R [force]; >= 0 (or --lambda)", "R");
    lambda_option_ =
        add("--lambda", lambda_,
            "friction ratio lambda = R / B [1]; >= 0, needs B > 0 (or --friction)", "L");
    friction_option_->excludes(lambda_option_);
    yield_accel_option_ = add(
        "--yield-accel", yield_accel_,
        "friction as a yield acceleration KY [g]: R = m KY G (G = --gravity; or --friction)", "KY");
    yield_accel_option_->excludes(friction_option_)->excludes(lambda_option_);
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

  const char* ground =
      "Ground motion (docs/cli.md: x is then relative to the ground, in s and "
      "the length unit of --gravity)";
  ground_accel_option_ =
      command
          .add_option("--ground-accel", ground_accel_,
                      "a record of the ground's acceleration a_g(t), linear between samples, 0 "
                      "outside; enters as -m a_g(t): PEER .AT2, a time-acceleration table, or one "
                      "column with --record-dt")
          ->type_name("FILE")
          ->group(ground);
  const auto add_ground = [&](const char* name, std::string& text, const char* help,
                              const char* type) {
    return numeric(command.add_option(name, text, help))->type_name(type)->group(ground);
  };
  record_dt_option_ =
      add_ground("--record-dt", record_dt_, "step of a one-column record [s]; > 0", "H");
  accel_units_option_ = command
                            .add_option("--accel-units", accel_units_,
                                        "units of the record's accelerations (default g; an .AT2 "
                                        "file says G itself)")
                            ->type_name("g|m/s2|cm/s2|ft/s2|in/s2")
                            ->group(ground);
  add_ground("--gravity", gravity_,
             "standard gravity in the output's length unit per s^2: 9.80665 (metres), 980.665 "
             "(cm), 32.174 (ft)...; also the unit of --yield-accel",
             "G")
      ->capture_default_str();
  scale_option_ = add_ground("--scale", scale_, "factor on the record's accelerations; > 0", "S");
  target_pga_option_ =
      add_ground("--target-pga", target_pga_, "scale the record to this peak [g]; > 0", "P");
  scale_option_->excludes(target_pga_option_);
  command.add_flag("--inverse", inverse_, "the record negated (the inverse polarity)")
      ->group(ground);
  command
      .add_flag("--one-way", one_way_,
                "the block never moves towards negative x (Newmark's downslope block)")
      ->group(ground);
}

bool ModelOptions::lambda_given() const { return lambda_option_ && lambda_option_->count() > 0; }

bool ModelOptions::static_lambda_given() const {
  return static_lambda_option_ && static_lambda_option_->count() > 0;
}

ModelInput ModelOptions::input() const {
  ModelInput input;
  input.mass = mass_;
  input.amplitude = amplitude_;
  input.omega = omega_;
  // CLI11 refuses both of a pair (excludes) while parsing.
  if (friction_option_ && friction_option_->count() > 0) input.friction = friction_;
  if (lambda_given()) input.lambda = lambda_;
  if (static_friction_option_ && static_friction_option_->count() > 0)
    input.static_friction = static_friction_;
  if (static_lambda_given()) input.static_lambda = static_lambda_;
  input.stiffness = stiffness_;
  input.damping = damping_;
  input.force_offset = force_offset_;
  input.harmonics = harmonics_;
  input.x0 = x0_;
  input.v0 = v0_;
  input.t0 = t0_;
  input.friction_required = friction_required_;
  const auto given = [](const CLI::Option* option) { return option && option->count() > 0; };
  if (given(ground_accel_option_)) {
    input.ground_accel = ground_accel_;
    // A record drives the block by itself unless a harmonic is asked for.
    if (!given(amplitude_option_)) input.amplitude = "0";
  }
  if (given(record_dt_option_)) input.record_dt = record_dt_;
  if (given(accel_units_option_)) input.accel_units = accel_units_;
  input.gravity = gravity_;
  if (given(scale_option_)) input.scale = scale_;
  if (given(target_pga_option_)) input.target_pga = target_pga_;
  input.inverse = inverse_;
  input.one_way = one_way_;
  if (given(yield_accel_option_)) input.yield_accel = yield_accel_;
  return input;
}

TypedInputs ModelOptions::typed_inputs() const { return input().typed_inputs(); }

Model ModelOptions::model() const {
  try {
    return input().model();
  } catch (const InvalidInput& error) {
    throw bad_input(input_message(error));
  }
}

}  // namespace frictionref::cli
