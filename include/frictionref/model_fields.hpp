// The model as one line of "name=value" fields, the spelling of every
// "# model:" line and report (docs/cli.md "Output formats").
#pragma once

#include <string>

#include "frictionref/model.hpp"

namespace frictionref {

// "mass=1 amplitude=1 omega=1 friction=0.3 lambda=0.3 x0=0 v0=0 t0=0", with
// static_friction=, stiffness=, damping=, force_offset= and one
// harmonic=B,W,PHI per extra harmonic before x0 where the model has them (the
// seed's model keeps the line it always had). `number` spells each value; the
// default is the shortest text that reads back to the same double.
std::string model_fields(const Model& model, std::string (*number)(double) = nullptr);

}  // namespace frictionref
