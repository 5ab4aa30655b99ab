// The fast path of the general model's dense output for a slip with a spring
// and damper (not critically damped), a damper alone, or neither, and forcing
// terms, without a record (docs/theory.md 10.6): a slip's x, v and a at many times,
// four (or eight) at once, in double-double arithmetic with a rigorous error bound.
// Where the bound shows which double the exact closed form rounds to, that
// double is the answer; elsewhere the lane is left undecided and the caller
// evaluates it in long double (Ziv's strategy), as double_double_slip.hpp
// does for the seed's slips.
//
// The exact closed form at exact arguments: tau = w t and a = w t_a exactly,
// h = tau - a, y = w x, v = dy/dtau, and the forcing terms j (the main one
// b_0 = B / (m w), q_0 = 1, phi_0 = 0; each harmonic b_j = B_j / (m w),
// q_j = w_j / w, phi_j), theta_j = q_j tau + phi_j:
//   y'' + 2 sigma y' + rho^2 y = f0 - s r + sum_j b_j sin theta_j,
//   sigma = c / (2 m w), rho^2 = k / (m w^2), g0 = f0 - s r,
//   y = sum_j b_j Im(H_j e^{i theta_j}) + (the free motion),
// H_j = 1 / (rho^2 - q_j^2 + 2 i sigma q_j). The free motion, with C1 and D1
// from (y_a, v_a) at h = 0:
//   a spring, under-damped, nu^2 = rho^2 - sigma^2 > 0:
//     P + e^{-sigma h} (C1 cos nu h + C2 sin nu h), P = g0 / rho^2;
//   a spring, over-damped, mu^2 = sigma^2 - rho^2 > 0:
//     P + A e^{-kappa1 h} + B e^{-kappa2 h}, kappa2 = sigma + mu,
//     kappa1 = rho^2 / kappa2;
//   a damper alone: A + (g0 / 2 sigma) h + B e^{-2 sigma h};
//   neither spring nor damper (H_j = -1 / q_j^2):
//     C1 + D1 h + g0 h^2 / 2.
// v and dv/dtau are its derivatives.
#pragma once

#include <cstddef>

#include "numeric/double_double_constant.hpp"

namespace frictionref::detail {

// A slip of m x'' + c x' + k x = B sin(w t) + sum_j B_j sin(w_j t + phi_j)
// + F0 - s R from (t_begin, x_begin, v_begin). Plain doubles only: the file
// that computes with it is compiled for AVX2 and includes no library header
// with inline functions (double_double_slip.cpp).
struct OscillatorSlipStart {
  static constexpr int kMaxHarmonics = 8;
  double omega, amplitude, mass, friction, stiffness, damping, force_offset;
  int harmonics;  // how many of the arrays below are used
  double harmonic_amplitude[kMaxHarmonics], harmonic_omega[kMaxHarmonics],
      harmonic_phase[kMaxHarmonics];
  int sign;  // +1 forward, -1 backward
  double t_begin, x_begin, v_begin;
};

// The double-double exponential of hi + lo (-708 <= hi <= 0) as a pair and
// its relative error bound: out = {hi, lo, bound}. For tests of the bound;
// only where double_double_lanes_available().
void double_double_exp(double hi, double lo, double out[3]);

// The sum of products (numeric/double_double_sum.hpp) start + sum_j c_j f_j
// of n normalized pairs (start[0..1], c[2j..2j+1], f[2j..2j+1]) taken as
// exact, and its error bound: out = {hi, lo, bound}. For tests of the bound;
// only where double_double_lanes_available().
void double_double_sum(const double* start, const double* c, const double* f, int n, double out[3]);

class DoubleDoubleOscillator {
 public:
  // Only where double_double_lanes_available(). Not usable() for what it
  // does not cover: a critically damped spring (one whose nu^2 the bounds
  // cannot tell from 0), more than kMaxHarmonics
  // harmonics, a harmonic's |phi_j| beyond 2^20, |w t_a| or a harmonic's
  // phase at t_a beyond 2^24, parameters beyond 2^+-500, non-finite constants.
  explicit DoubleDoubleOscillator(const OscillatorSlipStart& start);

  bool usable() const { return usable_; }

  // As DoubleDoubleSlip::evaluate: x[i], v[i], a[i] and in decided[i] the
  // bits (decided_values.hpp) of those that are the correctly rounded
  // doubles of the closed form at t[i]. Undecided besides the rows near
  // rounding boundaries: times before the start or beyond 513 rad of forcing
  // phase from it, rows where a term's phase (q_j h, nu h) leaves 512 rad or
  // a decay's sigma h or kappa h exceeds 708. Whether a time is decided
  // depends on the start and that time only.
  void evaluate(const double* t, std::size_t n, double* x, double* v, double* a,
                unsigned char* decided) const;

 private:
  using Constant = DoubleDoubleConstant;
  static constexpr int kMaxTerms = OscillatorSlipStart::kMaxHarmonics + 1;
  // One forcing term: q_j, theta_j(a) - base_j pi/128, the table index of
  // base_j, and its coefficients on sin theta_j and cos theta_j in x, v, a.
  struct Term {
    Constant q, offset;
    int base = 0;
    Constant x_sin, x_cos, v_sin, v_cos, a_sin, a_cos;
  };
  static constexpr int kRanges = 4;

  // The free motion's kind: a damped oscillation (under-damped spring), a
  // parabola (neither spring nor damper), or one or two decays (over-damped
  // spring, damper alone).
  enum class FreeMotion { oscillation, parabola, decays };
  // The degree of the free motion's polynomial part in h: 2 for a parabola,
  // 1 for a damper alone (one decay and a drift), 0 otherwise.
  static int degree(FreeMotion free, int decays) {
    return free == FreeMotion::parabola ? 2 : free == FreeMotion::decays && decays == 1 ? 1 : 0;
  }
  // evaluate() on lanes of kWidth (4: AVX2, 8: AVX-512), the same answers,
  // and its rows of one kind of free motion (double_double_oscillator_rows.hpp).
  template <int kWidth>
  void evaluate_lanes(const double* t, std::size_t n, double* x, double* v, double* a,
                      unsigned char* decided) const;
  template <FreeMotion kFree, int kWidth>
  void evaluate_rows(const double* t, std::size_t n, double* x, double* v, double* a,
                     unsigned char* decided) const;

  bool usable_ = false;
  FreeMotion free_ = FreeMotion::oscillation;
  int terms_ = 0;
  double omega_ = 0;
  double a_hi_ = 0, a_lo_ = 0;  // w t_a exactly
  Term term_[kMaxTerms];
  Constant sigma_, nu_;
  // The polynomial part: x = x_constant + h (x_linear + x_square h),
  // v = v_constant + v_linear h, a = a_constant. With a spring, P / w alone.
  Constant x_constant_, x_linear_, x_square_, v_constant_, v_linear_, a_constant_;
  // A decay: its rate kappa and its coefficients on e^{-kappa h} in x, v, a.
  struct Decay {
    Constant rate, x, v, a;
  };
  Decay decay_[2];
  int decays_ = 0;
  // The free oscillation's coefficients on e^{-sigma h} cos nu h and
  // e^{-sigma h} sin nu h in x, v and a (an under-damped spring's).
  Constant x_cos_, x_sin_, v_cos_, v_sin_, a_cos_, a_sin_;
  double velocity_error_[kRanges] = {}, acceleration_error_[kRanges] = {},
         position_error_[kRanges] = {};
};

}  // namespace frictionref::detail
