// The fast path of the seed's dense output (docs/theory.md 10): a slip's x, v
// and a at many times, four (or eight) at once, in double-double arithmetic with a
// rigorous error bound. Where the bound shows which double the exact closed
// form rounds to, that double is the answer (it is the correctly rounded
// value, so it equals the long double path's answer wherever that one is
// correctly rounded); elsewhere the lane is left undecided and the caller
// evaluates it in long double (Ziv's strategy).
//
// The exact closed form is that of phase_law.hpp at exact arguments:
// tau = w t and a = w t_a exactly, b = B / (m w), r = R / (m w):
//   v = (v_a + b cos a + s r a) - b cos tau - s r tau
//   a = w b sin tau - w s r
//   x = (x_a + b sin a / w) + h ((v_a + b cos a) / w - s r / (2 w) h) - b / w sin tau,
// h = tau - a. A constant force F0 (the general model without spring, damper,
// harmonics or record: static friction above R, an offset) enters as
// s r - f0 in place of s r, f0 = F0 / (m w): the same law.
#pragma once

#include <cstddef>

#include "numeric/double_double_constant.hpp"
#include "numeric/double_double_table.hpp"

namespace frictionref::detail {

// A slip of m x'' = B sin(w t) + F0 - s R from (t_begin, x_begin, v_begin).
struct SeedSlipStart {
  double omega, amplitude, mass, friction;
  int sign;  // +1 forward, -1 backward
  double t_begin, x_begin, v_begin;
  double force_offset = 0;  // F0: 0 in the seed's model
};

// The fast path's sin and cos of y = hi + lo (|hi| <= 512), each as a
// double-double pair with its error bound: out = {sin hi, sin lo, cos hi,
// cos lo, bound}. For tests of the bound; only where
// double_double_lanes_available().
void double_double_sin_cos(double hi, double lo, double out[5]);

class DoubleDoubleSlip {
 public:
  // Only where double_double_lanes_available(). Not usable() for starts
  // outside its ranges (|w t_a| > 2^24, non-finite constants).
  explicit DoubleDoubleSlip(const SeedSlipStart& start);

  bool usable() const { return usable_; }

  // For i < n: x[i], v[i], a[i] and in decided[i] the bits
  // (decided_values.hpp) of those that are the correctly rounded doubles of
  // the closed form at t[i] (the others are unspecified). Times beyond about
  // 500 radians of forcing phase from the start are undecided. Whether a
  // time is decided depends on the start and that time only (not on the
  // other times, nor on the phase's end).
  void evaluate(const double* t, std::size_t n, double* x, double* v, double* a,
                unsigned char* decided) const;

 private:
  // evaluate() on lanes of kWidth (4: AVX2, 8: AVX-512), the same answers
  // (double_double_slip_rows.hpp).
  template <int kWidth>
  void evaluate_lanes(const double* t, std::size_t n, double* x, double* v, double* a,
                      unsigned char* decided) const;

  using Constant = DoubleDoubleConstant;

  bool usable_ = false;
  double omega_ = 0;
  double a_hi_ = 0, a_lo_ = 0;  // w t_a exactly
  int base_index_ = 0;          // j_a mod 256: w t_a = j_a pi/128 + small
  Constant base_angle_;         // j_a pi/128
  Constant v0_, b_, sr_, wb_, wsr_, x0_, w_over_omega_, b_over_omega_, half_sr_over_omega_;
  // The largest |w t - j_a pi/128| a lane accepts (the reduction's range).
  static constexpr double kLargestAngle = 512;
  // Bounds on the errors of v, a and x for |h| up to 2, 8, 64 and 513 rad
  // (every accepted time has |h| <= 513): one range per lane.
  static constexpr int kRanges = 4;
  double velocity_error_[kRanges] = {}, acceleration_error_[kRanges] = {},
         position_error_[kRanges] = {};
};

}  // namespace frictionref::detail
