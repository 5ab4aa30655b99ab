// The exact side of a comparison, from one pass of the engine: its phases
// over the record and the exact state at each candidate time. The phases
// stay available, so other times (a shifted record, the diagnosis) are
// evaluated from their closed forms without running the engine again.
#pragma once

#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::comparison {

struct ExactMotion {
  Model model;
  std::vector<Phase> phases;  // the engine's phases that begin before the record's end
  std::vector<State> states;  // the exact state at each candidate time

  // The exact state at time t, clamped into [first phase's start, last phase's end].
  State at(double t) const;
  // The velocities and positions of `states`.
  std::vector<double> v() const;
  std::vector<double> x() const;
};

// `t`: the candidate's times, non-decreasing, t.front() >= model.t0 (checked
// by compare()). Throws std::runtime_error if the engine stops early.
ExactMotion exact_motion(const Model& model, const std::vector<double>& t);

}  // namespace frictionref::comparison
