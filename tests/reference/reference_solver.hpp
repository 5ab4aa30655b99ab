// An independent, deliberately simple, 50-digit recomputation of the exact
// motion, used as the oracle for the engine's event times (docs/accuracy.md).
//
// Independence from the engine, on purpose:
//   * no frictionref header is included: the model is this file's own struct
//     and the closed forms below are written again from THEORY.md;
//   * every computation is in boost::multiprecision::cpp_bin_float_50
//     (168-bit mantissa, ~50 decimal digits), from double inputs converted
//     exactly;
//   * a different root-finding method. The engine splits each slip at the
//     closed-form times where B sin(w t) = +-R (where the velocity can turn)
//     and sign-tests the pieces. This solver never uses those times: it scans
//     the slip in forcing phase tau = w t at a fixed step h and decides, from
//     the rigorous bound |d^2 v / d tau^2| = |b cos tau| <= b = B / (m w),
//     whether a step can hold a zero of s v (s = slip sign; s v > 0 during
//     the slip). If both end values exceed b h^2 / 8 it cannot (a function
//     with |f''| <= b lies above its chord minus b h^2 / 8). Otherwise the
//     step is halved, left half first, which is at the same time a bisection
//     of a bracketed root and a proof that no earlier root exists. Bisection
//     runs to the last bit of the 50-digit type.
//
// Model (user units), slip sign s = +1 (v > 0) or -1 (v < 0):
//   m dv/dt = B sin(w t) - s R;     stuck (v = 0) while |B sin(w t)| <= R.
// In a slip of sign s starting at tau = a with (x_a, v_a), with b = B/(m w),
// r = R/(m w):
//   v(tau) = v_a + b (cos a - cos tau) - s r (tau - a)
//   x(tau) = x_a + [ v_a (tau - a) + b ((tau - a) cos a - (sin tau - sin a))
//                    - s r (tau - a)^2 / 2 ] / w
// At v = 0 at tau_s: B sin tau_s > R slips forward, B sin tau_s < -R slips
// backward (a reversal), otherwise the mass sticks until the next breakaway
// (within 1e-20 rad of a closed-form crossing of |F| = R, the crossing
// decides; see at_rest in the .cpp),
// tau = asin(R/B) + 2 pi k (forward) or pi + asin(R/B) + 2 pi k (backward),
// the first one >= tau_s; none if B <= R.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace frictionref_reference {

using Real = boost::multiprecision::cpp_bin_float_50;

// The model with double inputs (what the engine is given).
struct Input {
  double mass = 1;       // m > 0
  double amplitude = 1;  // B >= 0
  double omega = 1;      // w > 0
  double friction = 0;   // R >= 0
  double x0 = 0;
  double v0 = 0;
  double t0 = 0;

  std::string describe() const;  // "m=1 B=1 w=1 R=0.3 x0=0 v0=0 t0=0" (17 digits)
};

// The same in 50 digits. from_double converts every field exactly.
struct RealInput {
  Real mass = 1, amplitude = 1, omega = 1, friction = 0, x0 = 0, v0 = 0, t0 = 0;
  static RealInput from_double(const Input& in);
};

enum class Kind { stick, slip_forward, slip_backward };
const char* to_string(Kind kind);
inline int sign_of(Kind kind) {
  return kind == Kind::slip_forward ? 1 : kind == Kind::slip_backward ? -1 : 0;
}

// How a phase began.
enum class Start {
  initial,    // at t0 with the given v0
  breakaway,  // a stick ended at a closed-form breakaway time (v = 0, |F| = R)
  from_stop,  // a slip ended with v = 0 and the force exceeded R at once (a reversal)
  stop,       // a stick beginning at a slip's stop
};

struct Phase {
  Kind kind = Kind::stick;
  Start start = Start::initial;
  Real t_begin = 0, t_end = 0;      // user time
  Real tau_begin = 0, tau_end = 0;  // forcing phase w t
  Real x_begin = 0, x_end = 0;
  Real v_begin = 0, v_end = 0;
  bool at_horizon = false;  // cut at the horizon (v_end is the state there)
  // Accelerations (user units) just after t_begin and just before t_end.
  Real accel_begin = 0, accel_end = 0;
  // For a slip that ends in a stop: d(accel)/dt just before the stop, the
  // curvature of v there (user units), for conditioning estimates.
  Real jerk_end = 0;
  // The slip ended within 1e-20 rad of a closed-form crossing of |F| = R and
  // what followed was decided by that crossing rather than by the sign of
  // B sin(w t) -+ R (a touch at a breakaway time, a marginal reversal).
  bool decided_by_crossing = false;

  Real duration() const { return t_end - t_begin; }
};

struct Options {
  Real step = Real(1) / 4;             // scan step h in tau [rad]
  std::size_t max_phases = 100000000;  // safety limit
};

struct Result {
  RealInput model;
  Real t_end = 0;
  std::vector<Phase> phases;
  std::uint64_t velocity_evaluations = 0;  // closed-form s v evaluations
  std::uint64_t refinements = 0;           // step halvings (scan + bisection)
  bool phase_limit = false;
};

// Runs from t0 to t_end (> t0). Throws std::invalid_argument on bad input and
// std::runtime_error if a zero could not be resolved at 50 digits (a tangency
// to within ~1e-100, which double inputs do not produce).
Result solve(const RealInput& model, const Real& t_end, const Options& options = {});
inline Result solve(const Input& model, double t_end, const Options& options = {}) {
  return solve(RealInput::from_double(model), Real(t_end), options);
}

// The closed-form state inside `phase` at user time t, plus the acceleration.
struct StateR {
  Real x = 0, v = 0, a = 0;
};
StateR evaluate(const RealInput& model, const Phase& phase, const Real& t);

// lambda* = 2 / sqrt(4 + pi^2) in 50 digits.
Real regime_threshold();

}  // namespace frictionref_reference
