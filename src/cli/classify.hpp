// `frictionref classify`: the steady-state regime and its closed-form figures.
#pragma once

#include <nlohmann/json.hpp>

#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"

namespace frictionref::cli {

// Every SteadyState field by its name (regimes as strings, NaN as null), the
// model as an object, and the version. Keys keep this order.
nlohmann::ordered_json classify_json(const Model& model, const SteadyState& steady);

}  // namespace frictionref::cli
