// The exact, event-driven engine (docs/theory.md).
//
// Each phase is integrated in closed form. One event loop (src/engine) runs
// every model; the model's family of phase laws says where each phase ends:
//   * the seed's model (BasicModel::is_harmonic_coulomb()): a slip ends at the
//     first zero of v, and v is monotone between the closed-form times where
//     B sin(w t) = +-R, so each such piece holds at most one zero, bracketed
//     by a sign test (docs/theory.md 3); breakaways are closed form;
//   * every other model (static friction, spring, damper, offset, several
//     harmonics): the zeros of v, and of |N| - Rs in a stick, are isolated by
//     a certified exclusion test built from rigorous bounds of the closed
//     form's derivatives, extrema included (docs/theory.md 7).
// Roots are then found inside their bracket by GSL's Brent solver polished
// in the wider work type (double), or Boost.Math TOMS 748 (other scalar
// types). No time stepping and no tolerance-dependent event detection.
//
// The engine is a stream: next() produces one phase at a time, so memory does
// not grow with the horizon.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

struct SolveOptions {
  // Stop with Termination::phase_limit after this many phases; >= 1.
  std::uint64_t max_phases = std::numeric_limits<std::uint64_t>::max();

  // The seed's model with dead bands repeats exactly from its first breakaway
  // on (docs/theory.md 3.9). Once a whole cycle from one breakaway to the
  // next has been computed and at least this many cycles remain before
  // t_end, the engine computes the cycle once in 50 digits and emits every
  // later phase from it, to the horizon, each number correctly rounded,
  // instead of event by event. Sliding continuously, its reversals converge
  // to a fixed point (docs/theory.md 3.10): once one lies within 2^-44 rad of
  // it and at least this many forcing periods remain, every later phase is
  // emitted from the fixed cycle and its linear transient, with certified
  // bounds, each number correctly rounded. 0 turns both off. The default
  // keeps the 50-digit work (about 0.25 ms) below a tenth of the time it
  // saves.
  std::uint64_t replay_min_cycles = 1024;

  // Throws InvalidInput naming the field and the rule.
  void validate() const;
};

template <class Real>
struct BasicSummary {
  Termination termination = Termination::reached_end;
  std::string message;  // why it terminated, in words

  std::uint64_t phases = 0;
  std::array<std::uint64_t, 3> phases_by_kind{};  // indexed by PhaseKind
  std::uint64_t stops = 0;            // slips that ended with v = 0 before the horizon,
                                      // including direct reversals (no rest)
  std::uint64_t reversals = 0;        // stops followed at once by a slip the other way
  std::uint64_t breakaways = 0;       // sticks that ended in a slip
  std::uint64_t merged_sticks = 0;    // sticks shorter than the time resolution, not emitted
  std::uint64_t touches = 0;          // v = 0 at an instant, slip goes on the same way (grazing)
  std::uint64_t sign_tests = 0;       // velocity evaluations at piece ends (bracketing)
  std::uint64_t root_function_calls = 0;  // velocity evaluations inside root finding
  std::uint64_t predicted_stops = 0;      // stops found by Halley steps from a prediction
                                          // (the rest by GSL Brent + polish)
  // Phases emitted from the replayed steady motion (SolveOptions::
  // replay_min_cycles), and of their end times and positions those that the
  // double-double error bound could not round (then rounded from 50 digits).
  std::uint64_t replayed_phases = 0;
  std::uint64_t replay_values_in_50_digits = 0;

  BasicState<Real> final_state;  // at the last phase end (t_end unless terminated early)

  std::uint64_t count(PhaseKind kind) const { return phases_by_kind[static_cast<int>(kind)]; }
  // One line: termination, counts, root-function calls per stop, final state.
  std::string brief_report() const;
};

namespace detail {
template <class Real>
class EngineCore;  // the event loop and the model's phase laws (src/engine)
}  // namespace detail

template <class Real>
class BasicExactEngine {
 public:
  // Validates model, t_end (finite, > t0), |w t0| and |w t_end| <= 1e10 rad,
  // the range of the motion (docs/theory.md 4.12) and options; throws
  // InvalidInput.
  BasicExactEngine(const BasicModel<Real>& model, const Real& t_end,
                   const SolveOptions& options = {});
  ~BasicExactEngine();
  BasicExactEngine(BasicExactEngine&&) noexcept;
  BasicExactEngine& operator=(BasicExactEngine&&) noexcept;

  // Writes the next phase and returns true, or returns false once the horizon
  // (or the phase limit) has been reached. The last phase is cut at t_end.
  bool next(BasicPhase<Real>& phase);

  const BasicModel<Real>& model() const;
  const Real& t_end() const;
  const BasicSummary<Real>& summary() const;

 private:
  std::unique_ptr<detail::EngineCore<Real>> core_;
};

template <class Real>
struct BasicSolution {
  BasicModel<Real> model;
  std::vector<BasicPhase<Real>> phases;
  BasicSummary<Real> summary;

  // The phase containing t (t_begin <= t < t_end; the last phase also owns its
  // t_end). Requires model.t0 <= t <= the horizon.
  const BasicPhase<Real>& phase_at(const Real& t) const;
  BasicState<Real> state_at(const Real& t) const;
};

// Runs the engine to t_end and keeps every phase.
template <class Real>
BasicSolution<Real> solve(const BasicModel<Real>& model, const Real& t_end,
                          const SolveOptions& options = {});

// The engine's time resolution near time t, 8 eps max(1, |w t|) / w: phases
// shorter than this are not resolved (merged or refused as a horizon).
double time_resolution(const Model& model, double t);

using ExactEngine = BasicExactEngine<double>;
using Summary = BasicSummary<double>;
using Solution = BasicSolution<double>;

extern template class BasicExactEngine<double>;
extern template struct BasicSummary<double>;
extern template struct BasicSolution<double>;
extern template BasicSolution<double> solve(const BasicModel<double>&, const double&,
                                            const SolveOptions&);

}  // namespace frictionref
