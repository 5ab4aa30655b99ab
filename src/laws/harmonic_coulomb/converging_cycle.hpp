// The seed's continuous sliding, replayed from a reversal near its fixed
// point (docs/theory.md 3.10).
//
// Without dead bands the mass reverses every half period and never rests, so
// nothing repeats exactly: the reversal times converge to their fixed point
// by the factor kappa of the reversal map per reversal. But the motion from
// a reversal depends on nothing but its time (v = 0, no spring), so the
// reversal phases u_k (the time minus the nearest n pi of the fixed point
// u*) follow a map u_{k+1} = G(u_k). From a base reversal whose deviation
// e0 = u_0 - u* is tiny, every later reversal is the fixed cycle plus the
// linear transient kappa^k e0 in time and its geometric sum in position, up
// to a rest of order e0^2 that a certified bound covers.
//
// This class holds those constants in 50 digits and gives the end of each
// slip after the base: each time, position and acceleration is a
// double-double sum with an error bound (the sums' rounding plus the bound on
// the transient's rest), rounded to double where the bound decides (Ziv);
// else the same sum in 50 digits, rounded where its bound decides; else the
// reversal map iterated from the base in 50 digits. Either way the double is
// the correctly rounded value of the exact motion from the base.
#pragma once

#include <cstdint>
#include <optional>

#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "frictionref/types.hpp"
#include "numeric/double_double_scalar.hpp"

namespace frictionref::detail {

class ConvergingCycle {
 public:
  // The constants of the seed's model (is_harmonic_coulomb()) when it slides
  // continuously with margin: the force at the fixed reversal beats friction
  // by at least 2^-20 b and the map contracts by at most 0.995 per reversal.
  // None otherwise.
  static std::optional<ConvergingCycle> compute(const Model& model);

  // The fixed reversal phase u* = acos(r pi / (2 b)) in long double, for a
  // cheap test at each reversal; NaN if there is no continuous sliding.
  static long double fixed_phase(long double b, long double r);

  // The largest deviation |e0| of a base reversal from the fixed point.
  static constexpr double kMaxDeviation = 0x1p-44;

  // Starts the replay at a reversal at forcing phase tau (the work type's
  // value, taken as exact) with x there, the next slip in `direction`: false
  // (and nothing changed) if it is not within kMaxDeviation of the fixed
  // point, or on its other side.
  bool start(const long double& tau, const long double& x, int direction);

  // Reversal k of the replay (k = 0 the base): the end of slip k - 1.
  struct End {
    PhaseKind kind;       // of the slip that ends there
    double t, x;          // v = 0
    double acceleration;  // left limit
    int rounded_in_50_digits;  // 0, 1 or 2 of t and x
  };
  // The end of the slip from the current reversal (the next reversal).
  End next_end();
  // Moves on to that reversal.
  void advance();

  // The state at t_end inside the slip from the current reversal (t_end
  // before that slip's end, as doubles), as the event loop gives it at its
  // horizon: stopped at its exact end if that is at or before t_end, else x,
  // v and a at t_end.
  struct Horizon {
    double x, v, acceleration;
  };
  Horizon horizon(double t_end);

  // For tests: 1 takes every value past the double-double sums to the
  // 50-digit linear transient, 2 also past that to the exact iteration.
  void force_fallback(int level) { fallback_ = level; }

 private:
  ConvergingCycle() = default;

  // Reversal k's transient and the bound on its rest (docs/theory.md 3.10).
  struct Cursor {
    std::int64_t k = 0;
    double p = 1;   // kappa^k (double, relative error <= (2k + 2) u), 0 once below 2^-400
    double lk = 1;  // >= L^k (held at 2^-400 from there)
    double r = 0;   // >= |e_k - kappa^k e0| = (K e0^2 / (2 (1 - L) L)) L^k for k >= 1
  };
  Cursor step(const Cursor& c) const;

  // Reversal k's values from the linear transient, and the bounds on their
  // errors, in 50 digits.
  struct Linear {
    HighPrecision tau;  // (n0 + k) pi + u* + kappa^k e0, off by at most r_k
    HighPrecision t, x, a, t_error, x_error, a_error;
  };
  Linear linear(const Cursor& c) const;
  // Reversal k exactly: the map iterated from the base in 50 digits.
  struct Exact {
    HighPrecision u, x;  // phase and position at reversal k
  };
  Exact exact(std::int64_t k);
  HighPrecision time_of(std::int64_t k, const HighPrecision& u) const;
  HighPrecision acceleration_of(std::int64_t k, const HighPrecision& u) const;
  PhaseKind kind_of_slip(std::int64_t k) const;  // the slip from reversal k
  End end_at(const Cursor& c);
  struct HighState {
    HighPrecision x, v, a;
  };
  // The slip from reversal k at tau_start, x_start, at t_end.
  HighState state_at(std::int64_t k, const HighPrecision& tau_start, const HighPrecision& x_start,
                     const HighPrecision& t_end) const;

  // The model in 50 digits: b = B / (m w), r = R / (m w).
  HighPrecision omega_, b_, r_, pi_;
  // The fixed point and the transient's first-order coefficients.
  HighPrecision u_star_, sin_star_, cos_star_, kappa_;
  HighPrecision phi1_;  // d(slide) / de at the fixed point: pi (r - b sin u*)
  // Bounds on a ball of radius kMaxDeviation around u*: L >= |G'|, K the
  // Lipschitz constant of G' at u*, M that of the slide's derivative.
  HighPrecision l_, k_lip_, m_lip_;
  double l_up_ = 0;

  // The replay's base and the terms of its sums, in double-double.
  std::int64_t n0_ = 0;
  long double x0_ = 0;
  HighPrecision u0_, e0_;
  double e0_abs_ = 0;
  double rest_per_lk_ = 0;  // r_k <= this L^k (k >= 1)
  double x_rest_ = 0;       // the positions' rest, for every k
  DoubleDouble half_period_;  // pi / w
  DoubleDouble fixed_time_;   // u* / w
  DoubleDouble x0_pair_;
  DoubleDouble slide_;  // the fixed slide 2 b sin u* / w
  DoubleDouble fixed_acceleration_;  // w (b sin u* + r)
  double kappa_d_ = 0;
  double time_transient_ = 0;          // e0 / w
  double slide_transient_ = 0;         // phi1 e0 / ((1 + kappa) w)
  double acceleration_transient_ = 0;  // w b cos u* e0
  double inverse_omega_up_ = 0, omega_b_up_ = 0, cos_star_up_ = 0;

  Cursor current_;  // the reversal the current slip starts from
  Cursor next_;     // and the one it ends at
  // Once kappa^k is dropped: x at even and odd reversals, and |a|.
  double steady_x_[2] = {0, 0}, steady_a_ = 0;
  bool steady_x_known_[2] = {false, false}, steady_a_known_ = false;
  int fallback_ = 0;
  // The exact iteration's cursor (advanced only where no bound decides).
  std::int64_t exact_k_ = 0;
  HighPrecision exact_u_, exact_x_;
};

}  // namespace frictionref::detail
