// An independent 50-digit recomputation of the GENERAL friction oscillator
// (docs/theory.md 7), the oracle for the engine's event times on those models
// (docs/accuracy.md, "The general model").
//
//   m x'' + c x' + k x = F(t) - f,
//   F(t) = F0 + B sin(w t) + sum_i B_i sin(w_i t + phi_i) - m a_g(t),
//   a_g: an optional recorded ground acceleration, samples (t_i, a_i), i < n,
//        linear between samples, 0 before t_0 and from t_{n-1} on (at a sample
//        time the segment to its right applies: a_g(t_0) = a_0, a_g(t_{n-1}) = 0,
//        so F jumps at t_0 and at t_{n-1}; it is continuous in between).
//   slipping (v != 0):  f = R sign(v)
//   at rest (v = 0):    N(t) = F(t) - k x; stays while |N| <= Rs (Rs >= R),
//                       breaks away in the direction of N the first time |N| > Rs.
//   a slip reaching v = 0 at ts sticks if |N(ts)| <= Rs, otherwise goes on at
//   once in the direction of N(ts) (a reversal, or a touch that does not stop it).
//   v0 != 0 at t0 starts a slip in its direction.
//
// Independence from the engine, on purpose:
//   * no frictionref header is included and nothing of the library is linked;
//     every computation is in cpp_bin_float_50 from double inputs converted
//     exactly;
//   * no closed form of the motion is used. The engine evaluates each slip in
//     closed form (exponentials, divided differences of the characteristic
//     roots) and isolates zeros by a certified Taylor-cubic exclusion search.
//     This solver integrates the ODE by Taylor series in user time t: on a
//     step [t_a, t_a + h] the coefficients of x come from the ODE's recurrence
//     (the forcing's Taylor coefficients are those of sin/cos), and the
//     truncation error is bounded rigorously by a geometric majorant of the
//     recurrence (the solution is entire). The step is re-expanded at its end;
//   * the event scan is the reference_solver.cpp chord test, not the engine's:
//     a function with |g''| <= M on [u, w] lies above its chord minus
//     M (w - u)^2 / 8, so if both end values (less the truncation bound) exceed
//     that, the interval holds no zero; otherwise it is halved, left half
//     first, which is at once a proof that no earlier zero exists and, once a
//     sign change is bracketed, a bisection to the last bit of the 50-digit
//     type. M comes from the series' coefficients plus the tail bound for a
//     slip (g = s v) and from M = sum |B_j| w_j^2 for a stick (g = Rs - |N|).
//   * slips that start from rest begin with a zone proven free of zeros by a
//     Taylor lower bound (f(0) = 0: f'(0) d + f''(0) d^2 / 2 - M3 d^3 / 6 > 0).
//   * the record (a_g) is taken segment by segment, never through a closed
//     form: a Taylor step never crosses a sample time (h is cut at the next
//     one), and on the segment holding [t_a, t_a + h) a_g is a line, which
//     adds -m a_g(t_a) to F's Taylor coefficient F_0 and -m a_g' to F_1 and
//     nothing else; the tail majorant only involves F_n for n >= D - 1 >= 11,
//     so it is unchanged and still rigorous. A stick is scanned segment by
//     segment: on each, g = Rs - |N| is evaluated with that segment's line
//     (up to the left limit at its end), and a line has no curvature, so
//     |g''| <= sum |B_j| w_j^2 still certifies the chord test there; at the
//     start of each new segment the right limit is checked first, and a jump
//     (at t_0 or t_{n-1}) that takes |N| past Rs is a breakaway at exactly
//     that sample time, in the direction of N (Phase::at_record_jump).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace frictionref_general_reference {

using Real = boost::multiprecision::cpp_bin_float_50;

// One extra term B_i sin(w_i t + phi_i) of the force.
struct Harmonic {
  double amplitude = 0;  // B_i, either sign
  double omega = 1;      // w_i > 0
  double phase = 0;      // phi_i [rad]
};

// The model with double inputs (what the engine is given).
struct Input {
  double mass = 1;       // m > 0
  double amplitude = 1;  // B >= 0 of B sin(w t)
  double omega = 1;      // w > 0
  double friction = 0;   // R >= 0 (sliding)
  std::optional<double> static_friction;  // Rs >= R; unset: Rs = R
  double stiffness = 0;     // k >= 0
  double damping = 0;       // c >= 0
  double force_offset = 0;  // F0
  std::vector<Harmonic> harmonics;
  // The ground acceleration record (both empty: none): times strictly
  // increasing, n >= 2 samples; F gets -m a_g(t) (see the model above).
  std::vector<double> record_t, record_a;
  double x0 = 0, v0 = 0, t0 = 0;

  double static_limit() const { return static_friction ? *static_friction : friction; }
  std::string describe() const;  // every field, 17 digits (the record: n, first and last time)
};

// One term a sin(q t + p) of the force in 50 digits (B sin(w t) is term 0).
struct RealTerm {
  Real amplitude = 0, omega = 1, phase = 0;
};

// The same model in 50 digits. from_double converts every field exactly.
struct RealInput {
  Real mass = 1, friction = 0, static_friction = 0, stiffness = 0, damping = 0,
       force_offset = 0;
  std::vector<RealTerm> terms;  // the oscillating terms of F, zero amplitudes included
  std::vector<Real> record_t, record_a;  // the record (empty: none)
  Real x0 = 0, v0 = 0, t0 = 0;
  static RealInput from_double(const Input& in);

  Real force(const Real& t) const;       // F(t), the record's term right-continuous
  Real force_rate(const Real& t) const;  // F'(t), the record's slope to the right of t

  // The record's segments, k = 0..n: k = 0 before t_0, [t_{k-1}, t_k) for
  // 1 <= k <= n - 1, and k = n from t_{n-1} on (a_g = 0 on the first and
  // last). segment(t) is the one holding t (right-continuous; 0 without a record).
  std::size_t segment(const Real& t) const;
  Real ground_acceleration(std::size_t k, const Real& t) const;  // segment k's line at t
  Real ground_slope(std::size_t k) const;                        // its slope
  Real ground_acceleration(const Real& t) const { return ground_acceleration(segment(t), t); }
};

enum class Kind { stick, slip_forward, slip_backward };
const char* to_string(Kind kind);
inline int sign_of(Kind kind) {
  return kind == Kind::slip_forward ? 1 : kind == Kind::slip_backward ? -1 : 0;
}

// How a phase began.
enum class Start {
  initial,    // at t0
  breakaway,  // a stick ended: |N| reached Rs
  from_stop,  // a slip ended with v = 0 and |N| > Rs there (a reversal or a touch)
  stop,       // a stick beginning at a slip's stop
};

struct Phase {
  Kind kind = Kind::stick;
  Start start = Start::initial;
  Real t_begin = 0, t_end = 0;
  Real x_begin = 0, x_end = 0;
  Real v_begin = 0, v_end = 0;
  bool at_horizon = false;  // cut at the horizon (v_end is the state there)
  // Slips: s dv/dt just after the start and just before the end, and
  // s d2v/dt2 just before the end (user units; s = slip sign). At a stop the
  // slope is <= 0 and its size is the conditioning of the stop time.
  Real slope_begin = 0, slope_end = 0, curvature_end = 0;
  // Sticks: N and dN/dt = F'(t) at the end (a breakaway: |N| = Rs there, or
  // at_record_jump: the record's jump at t_0 or t_{n-1} took |N| past Rs, and
  // N, dN/dt are the right limits there).
  Real net_force_end = 0, net_force_rate_end = 0, net_force_curvature_end = 0;
  bool at_record_jump = false;
  // Slips: the largest |v| met at the scan points (a scale for error bounds).
  Real speed_max = 0;

  Real duration() const { return t_end - t_begin; }
};

struct Options {
  // Taylor step h = step_fraction / Omega, Omega = max(w_j, sqrt(k/m), c/m),
  // shortened to end at the record's next sample; the majorant needs Omega h <= 1/2.
  Real step_fraction = Real(1) / 2;
  std::size_t max_phases = 100000;  // safety limit
};

struct Result {
  RealInput model;
  Real t_end = 0;
  std::vector<Phase> phases;
  std::uint64_t series_steps = 0;       // Taylor expansions built
  std::uint64_t evaluations = 0;        // evaluations of s v or of Rs - |N|
  std::size_t max_degree = 0;           // largest Taylor degree used
  Real max_truncation = 0;              // largest tail bound of v met, relative to its scale
  // Adjacent 50-digit points where the scanned function was positive but
  // within its truncation bound (next to a root): not events.
  std::uint64_t unresolved_points = 0;
  bool phase_limit = false;
};

// Runs from t0 to t_end (> t0). Throws std::invalid_argument on bad input and
// std::runtime_error where a zero cannot be resolved at 50 digits (an exact
// tangency, which the test models avoid).
Result solve(const RealInput& model, const Real& t_end, const Options& options = {});
inline Result solve(const Input& model, double t_end, const Options& options = {}) {
  return solve(RealInput::from_double(model), Real(t_end), options);
}

}  // namespace frictionref_general_reference
