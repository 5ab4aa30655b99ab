// The slips of an engine run, for the floor benchmarks (docs/benchmarks.md,
// "Floors, measured"), which time the least work of the general laws on the
// phases of the real run, the run itself outside the timing.
#pragma once

#include <cstdint>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"

namespace frictionref::bench {

struct EngineSlips {
  std::vector<Phase> slips;
  std::uint64_t phases = 0;  // every phase of the run, sticks included
};

inline EngineSlips engine_slips(const Model& model, double t_end) {
  EngineSlips run;
  ExactEngine engine(model, t_end);
  Phase phase;
  while (engine.next(phase)) {
    ++run.phases;
    if (phase.kind != PhaseKind::stick) run.slips.push_back(phase);
  }
  return run;
}

// The general law of a slip from its start, as the engine builds it (y = w x).
using GeneralWork = long double;
inline detail::LinearSlipLaw<GeneralWork> general_law_at_start(
    const detail::Oscillator<GeneralWork>& oscillator, const Phase& slip) {
  const GeneralWork omega = oscillator.omega();
  return detail::LinearSlipLaw<GeneralWork>(
      oscillator, slip.kind == PhaseKind::slip_forward ? 1 : -1, omega * GeneralWork(slip.t_begin),
      omega * GeneralWork(slip.x_begin), GeneralWork(slip.v_begin));
}

}  // namespace frictionref::bench
