// The steady state as JSON: the document `frictionref classify --json` writes
// and the dict `frictionref.classify()` returns in Python (docs/cli.md lists
// every key). Figures that do not apply (NaN) are null; numbers are written
// in their shortest form that reads back exactly.
#pragma once

#include <string>

#include "frictionref/classification.hpp"
#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"

namespace frictionref {

// The seed's closed form: every SteadyState field by its name (regimes as
// strings) after regime and method, the model (model_json.hpp) and the
// version. Compact (no indentation).
std::string steady_state_json(const Model& model, const SteadyState& steady);

// Any classification: the seed's keys above where its closed form is used;
// otherwise regime, method, forcing_period, multiplicity, transient_periods,
// stops_per_period, reversals_per_period, stuck_fraction, drift_per_period,
// peak_velocity, den_hartog (an object, or null where it does not apply),
// model and version. Compact.
std::string classification_json(const Model& model, const Classification& classification);

}  // namespace frictionref
