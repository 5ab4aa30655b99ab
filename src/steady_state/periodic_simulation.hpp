// The steady state of any model by simulation with the exact engine
// (classification.hpp).
#pragma once

#include "frictionref/classification.hpp"

namespace frictionref::detail {

// Requires a valid model and options.
Classification simulate_steady_state(const Model& model, const ClassifyOptions& options);

}  // namespace frictionref::detail
