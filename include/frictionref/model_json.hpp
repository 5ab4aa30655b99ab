// The model as the JSON object every JSON output carries under "model"
// (docs/cli.md "Output formats"): mass, amplitude, omega, friction, lambda,
// static_friction (null when it equals the sliding friction by default),
// stiffness, damping, force_offset, harmonics ([B, W, PHI] each), x0, v0, t0.
// Numbers are written in their shortest form that reads back exactly.
#pragma once

#include <string>

#include "frictionref/model.hpp"

namespace frictionref {

std::string model_json_text(const Model& model);

}  // namespace frictionref
