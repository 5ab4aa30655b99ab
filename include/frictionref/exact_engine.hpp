// The exact, event-driven engine (docs/theory.md).
//
// Each phase is integrated in closed form (closed_form.hpp). A slip ends at
// the first zero of v after its start; v is monotone between the closed-form
// times where B sin(w t) = +-R, so each such piece holds at most one zero and
// a sign test at its end brackets it exactly. The zero is found inside that
// bracket by Halley steps from a prediction (the stop of an earlier slip from
// the same forcing phase; one evaluation per stop in a steady state), else by
// GSL's Brent solver (double) or Boost.Math TOMS 748 (other scalar types),
// polished in the wider work type. Breakaway times are closed form. No time
// stepping and no tolerance-dependent event detection (docs/theory.md 3.5).
//
// The engine is a stream: next() produces one phase at a time, so memory does
// not grow with the horizon.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

struct SolveOptions {
  // Stop with Termination::phase_limit after this many phases; >= 1.
  std::uint64_t max_phases = std::numeric_limits<std::uint64_t>::max();

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

  BasicState<Real> final_state;  // at the last phase end (t_end unless terminated early)

  std::uint64_t count(PhaseKind kind) const { return phases_by_kind[static_cast<int>(kind)]; }
  // One line: termination, counts, root-function calls per stop, final state.
  std::string brief_report() const;
};

template <class Real>
class BasicExactEngine {
 public:
  using Work = work_t<Real>;

  // Validates model, t_end (finite, > t0), |w t0| and |w t_end| <= 1e10 rad,
  // and options; throws InvalidInput.
  BasicExactEngine(const BasicModel<Real>& model, const Real& t_end,
                   const SolveOptions& options = {});

  // Writes the next phase and returns true, or returns false once the horizon
  // (or the phase limit) has been reached. The last phase is cut at t_end.
  bool next(BasicPhase<Real>& phase);

  const BasicModel<Real>& model() const { return model_; }
  const Real& t_end() const { return t_end_; }
  const BasicSummary<Real>& summary() const { return summary_; }

 private:
  enum class Mode { stick, slip };

  using Law = PhaseLaw<Work>;
  using Point = typename Law::Point;

  // At v = 0 at forcing phase tau (sin tau given): returns the slip direction
  // (+1/-1) if the force beats friction (or a breakaway is within the time
  // resolution), 0 to stick.
  int direction_at_rest(const Work& tau, const Work& sin_tau, bool& merged) const;
  // Earliest stop of the current slip in (tau_, tau_end_]; false if none.
  // On a stop, `end` is the point there and `direction` what follows it
  // (direction_at_rest).
  bool find_slip_end(const Law& law, Point& end, int& direction);
  // s v at a critical time (sin, cos there in closed form), trusted only when
  // clear of zero by its rounding bound; otherwise the full evaluation.
  Work speed_at_critical(const Law& law, const Work& tau, bool minimum);
  // The root of s v on [lo, hi] (s v(lo) > 0 >= s v(hi), s v decreasing):
  // predicted Halley steps when a prediction applies, else GSL Brent + polish.
  void slip_root(const Law& law, Work lo, Work hi, Point& root);
  // Halley's method from `guess`, kept inside [lo, hi]; false if it does not
  // settle within a few steps (the caller then takes the bracketing solver).
  bool halley_root(const Law& law, const Work& guess, Work lo, Work hi, Point& root);
  // Fills `phase` unless it is shorter than the resolution of Real.
  bool emit(BasicPhase<Real>& phase, PhaseKind kind, const Work& tau_end, const Work& x_end,
            const Work& v_end, const Work& acceleration, bool at_horizon);

  // A slip from rest that starts at the same forcing phase (mod 2 pi, and mod
  // pi with the sign flipped: the motion is odd under t -> t + pi / w) as an
  // earlier one stops at nearly the same time after its start; in a steady
  // state, exactly. Kept for a few start phases; dh_da is the derivative of
  // the slip's length with respect to its start, for a first-order guess.
  struct StopPrediction {
    bool valid = false;
    Work phase = 0;  // start phase mod 2 pi (in [-pi, pi]) of the equivalent forward slip
    Work length = 0;
    Work dlength_dstart = 0;
  };
  Work normalised_phase(const Work& tau, int s) const;
  int prediction_for(const Work& phase) const;  // the slot within the window, or -1
  void remember_stop(const Law& law, const Work& phase, const Point& root);

  BasicModel<Real> model_;
  Real t_end_;
  SolveOptions options_;
  BasicSummary<Real> summary_;

  Work omega_, b_, r_;  // b = B/(m w), r = R/(m w)
  bool crosses_ = false;  // lambda < 1: the force crosses +-R and breakaways exist
  Work alpha_ = 0;        // asin(lambda) when crosses_
  // |F| > R only on windows pi - 2 alpha wide; beyond |w t| = this the window
  // is under 4 time resolutions and no slip it starts is representable.
  Work resolvable_phase_ = 0;
  Work tau_end_;
  Real t_current_;      // user time of tau_ as emitted (t0 exactly at the start)
  Work tau_, x_, v_;    // current phase start
  SinCos<Work> start_trig_;  // sin, cos of tau_
  // Slip starts whose sin, cos came from the previous slip by the sum formulas
  // (cheap, but rounding accumulates); recomputed fresh every 64.
  int carried_starts_ = 0;
  Work cos_alpha_ = 0;  // cos alpha = sqrt(1 - lambda^2): cos of the critical times, +-
                        // (sin there is +-lambda; speed_at_critical)
  std::array<StopPrediction, 4> predictions_{};
  int next_prediction_slot_ = 0;
  Mode mode_ = Mode::stick;
  int sign_ = 0;        // slip direction when mode_ == slip
  bool done_ = false;
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
