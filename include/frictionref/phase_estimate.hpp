// How many phases a run to t_end may have, before it is started: the guard of
// `events` (CLI and Python) against a request that would run for hours (a
// stiff spring k = 1.8e19 slides and sticks some 10^10 times in 30 time
// units). Four phases per period of the fastest rate in the model (two slips
// and two sticks per period in the dead-band regime), plus four per record
// sample interval, plus four for the start-up transient. An estimate, not a
// bound: it says what the run is likely to cost.
#pragma once

#include <string>

#include "frictionref/model.hpp"

namespace frictionref {

struct PhaseEstimate {
  double phases = 0;  // may be inf (k/m overflows)
  // What dominates, for messages: "4 per forcing period", "4 per natural
  // period 2 pi sqrt(m/k)", "4 per record sample".
  std::string basis;
};

// The model must be valid (Model::validate); t_end >= model.t0.
PhaseEstimate estimate_phases(const Model& model, double t_end);

}  // namespace frictionref
