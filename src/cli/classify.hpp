// `frictionref classify`: the steady state of any model, from a closed form
// where one holds, else by simulation.
#pragma once

#include <nlohmann/json.hpp>

#include "frictionref/classification.hpp"
#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"

namespace frictionref::cli {

// The seed's closed form: every SteadyState field by its name (regimes as
// strings, NaN as null) after regime and method, the model as an object, and
// the version. Keys keep this order.
nlohmann::ordered_json classify_json(const Model& model, const SteadyState& steady);

// Any classification: the seed's keys above where its closed form is used;
// otherwise regime, method, forcing_period, multiplicity, transient_periods,
// stops_per_period, reversals_per_period, stuck_fraction, drift_per_period,
// peak_velocity, den_hartog (an object, or null where it does not apply),
// model and version.
nlohmann::ordered_json classify_json(const Model& model, const Classification& classification);

}  // namespace frictionref::cli
