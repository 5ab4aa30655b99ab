// Enumerations shared by the library, the command line and the writers.
// Every enum has to_string / from_string so the CLI and the CSV/JSON writers
// spell them one way only (pattern: Ceres Solver types.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace frictionref {

// What the mass is doing during a phase.
enum class PhaseKind {
  stick,          // v = 0, |F| <= R: friction balances the force
  slip_forward,   // v > 0 inside the phase: m a = F - R      ("slip+")
  slip_backward,  // v < 0 inside the phase: m a = F + R      ("slip-")
};

// How a simulation ended.
enum class Termination {
  reached_end,        // the horizon t_end was reached
  phase_limit,        // SolveOptions::max_phases phases were produced first
  numerical_failure,  // a root bracket was lost (an internal invariant; please report)
};

// Steady-state behaviour. For the seed's model it follows from lambda = R / B
// alone (steady_state.hpp); for any model, from a closed form or a simulation
// (classification.hpp).
enum class Regime {
  continuous,  // moves throughout: reversals without stops (seed: lambda < lambda*)
  dead_bands,  // sticks of non-zero duration in every repetition (seed: lambda* <= lambda < 1)
  stops,       // at rest after the transient (seed: lambda >= 1)
  aperiodic,   // moving, but no repetition found within the simulated periods
};

// "stick", "slip+", "slip-"
std::string_view to_string(PhaseKind kind);
// "reached_end", "phase_limit", "numerical_failure"
std::string_view to_string(Termination termination);
// "continuous", "dead-bands", "stops", "aperiodic"
std::string_view to_string(Regime regime);

std::optional<PhaseKind> phase_kind_from_string(std::string_view text);
std::optional<Termination> termination_from_string(std::string_view text);
std::optional<Regime> regime_from_string(std::string_view text);

// +1 for slip_forward, -1 for slip_backward, 0 for stick.
constexpr int slip_sign(PhaseKind kind) {
  return kind == PhaseKind::slip_forward ? 1 : kind == PhaseKind::slip_backward ? -1 : 0;
}

}  // namespace frictionref
