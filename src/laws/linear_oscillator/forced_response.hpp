// The response of a slip to one harmonic, from rest (docs/theory.md 7.2):
//
//   R'' + 2 sigma R' + rho^2 R = exp(i q u),   R(0) = R'(0) = 0,
//
// so that the term a sin(theta_a + q u) of the forcing moves the mass by
// Im(a e^{i theta_a} R(u)). R is the divided difference of z -> exp(z u) at
// the three points i q, p1, p2 (p1, p2 the characteristic roots, p1 the one
// nearer i q), and R' = i q R + G with G = exp(z u)[p1, p2] the impulse
// response (transition.hpp):
//
//   R = (E - G) / (i q - p2),   E = exp(z u)[i q, p1] = u e^{p1 u} phi1((i q - p1) u),
//
// phi1(z) = expm1(z) / z. The textbook split into the steady response
// H e^{i q u} (H = 1 / P(i q)) and a transient cancelling it at u = 0 loses
// everything near resonance, where |H| is huge while R stays of size u^2 ... u
// (a lightly damped spring driven at its own frequency: found by fuzzing).
// The divided difference has no such cancellation: |i q - p2| >= max(q, |p2|)
// is never small, and at exact resonance (sigma = 0, q = rho) E = u e^{i q u},
// the secular growth, with no special case.
//
// For u D <= 1/2 (D = max(q, |p1|, |p2|)) R is the Taylor series from the
// ODE's recurrence, coefficients precomputed; beyond, the formula above with
// E - G not cancelling by more than a small factor (u |i q - p2| >= 1/4).
#pragma once

#include <boost/math/special_functions/expm1.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "laws/linear_oscillator/transition.hpp"
#include "numeric/complex.hpp"
#include "numeric/series_reach.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

// R(u), R'(u) of one harmonic, each with the magnitude its rounding error is
// a few ulps of.
template <class Work>
struct HarmonicResponseAt {
  Complex<Work> r, dr;
  Work mag_r = 0, mag_dr = 0;
};

template <class Work>
class ForcedResponse {
 public:
  // q > 0: the harmonic's frequency; transition: the same oscillator's.
  ForcedResponse(const Work& q, const TransitionFunctions<Work>& transition) : q_(q) {
    const Work sigma = transition.sigma(), rho2 = transition.rho2();
    const Complex<Work> iq{0, q};
    const RootPair<Work> roots = transition.roots();
    p1_ = roots.near;
    to_p1_ = iq - p1_;
    to_p2_ = iq - roots.far;
    abs_to_p1_ = to_p1_.abs();
    abs_to_p2_ = to_p2_.abs();
    reach_limit_ = transition.rate() > q ? transition.rate() : q;
    // R = sum r_n u^n, r_0 = r_1 = 0,
    // r_{n+2} = ((i q)^n / n! - 2 sigma (n+1) r_{n+1} - rho^2 r_n) / ((n+1)(n+2)),
    // |r_n| <= D^(n-2) / (2 (n-2)!) (the divided difference of z^n at three
    // points in the disc |z| <= D is a sum of C(n, 2) monomials of degree n-2),
    // so with x = u D <= 1/2 the tail after m = n - 2 = M is below
    // eps u^2 / 64 once x^M / M! <= eps / 64 (series_reach.hpp).
    const int terms = static_cast<int>(reach_.max_terms());
    std::vector<Complex<Work>> r(static_cast<std::size_t>(terms) + 3);
    Complex<Work> forcing{1, 0};  // (i q)^n / n!
    for (int n = 0; n + 2 < static_cast<int>(r.size()); ++n) {
      const Complex<Work> next = forcing - r[n + 1] * Work(2 * sigma * Work(n + 1)) - r[n] * rho2;
      r[n + 2] = next * Work(Work(1) / Work((n + 1) * (n + 2)));
      forcing = forcing * iq * Work(Work(1) / Work(n + 1));
    }
    series_.assign(r.begin() + 2, r.end());
  }

  // At u >= 0, given the transition functions there and e^{p1 u}
  // (transition.root_exp(u); only read beyond the series range).
  bool needs_root_exp(const Work& u) const { return u * reach_limit_ > Work(kSeriesLimit); }

  // at<false>: R alone (dense output, the search's plain points), the same
  // value bit for bit, without R' and the magnitudes.
  template <bool kBounds = true>
  HarmonicResponseAt<Work> at(const Work& u, const Transition<Work>& t,
                              const Complex<Work>& exp_iqu, const RootExp<Work>& root_exp) const {
    using boost::math::expm1;
    using std::fabs;
    using std::sqrt;
    HarmonicResponseAt<Work> out;
    if (u == 0) return out;
    const Work x = u * reach_limit_;
    if (x <= Work(kSeriesLimit)) {
      const std::size_t n = reach_.index_for(x);
      Complex<Work> sum;
      for (std::size_t i = n + 1; i-- > 0;) sum = sum * u + series_[i];
      out.r = sum * Work(u * u);
      // sum |r_n| u^n <= u^2 e^x / 2 <= 0.83 u^2.
      if constexpr (kBounds) out.mag_r = u * u;
    } else {
      const Complex<Work>& exp_p1u = root_exp.value;
      const Complex<Work> z = to_p1_ * u;
      const Work abs_z = abs_to_p1_ * u;
      const Work abs_p1u = root_exp.modulus;
      Complex<Work> e;
      Work mag_e = 0;
      if (abs_z <= 1) {
        // phi1(z) = expm1(z) / z; Re expm1(x + i y) = expm1(x) cos y - 2 sin^2(y / 2),
        // with 2 sin^2(y / 2) = sin^2 y / (1 + cos y): |y| <= |z| <= 1 keeps
        // cos y >= 0.54, so the quotient has a few ulps of relative error and
        // costs no second sin_cos. x = Re z = -Re(p1) u >= 0, so e^x = 1 +
        // expm1(x) loses nothing either (one expl less).
        const SinCos<Work> sc = sin_cos(z.im);
        const Work versine = sc.sin * sc.sin / (1 + sc.cos);
        // (z.re = 0 without damping: expm1 is 0 exactly.)
        const Work em1_re = z.re == 0 ? Work(0) : Work(expm1(z.re));
        const Complex<Work> em1{em1_re * sc.cos - versine, (1 + em1_re) * sc.sin};
        const Complex<Work> phi1 = abs_z > 0 ? em1 / z : Complex<Work>{1, 0};
        e = exp_p1u * phi1 * u;
        if constexpr (kBounds) {
          // |phi1| only sizes the error bound, and |z| <= 1 keeps it near 1:
          // no overflow for hypot to guard against.
          const Work abs_phi1 = sqrt(phi1.re * phi1.re + phi1.im * phi1.im);
          // e^{p1 u}'s arguments are rounded by up to their size in ulps.
          mag_e = abs_p1u * u * (abs_phi1 > 1 ? abs_phi1 : Work(1)) *
                  (1 + fabs(p1_.im) * u - p1_.re * u);
        }
      } else {
        e = (exp_iqu - exp_p1u) / to_p1_;
        // The arguments q u and Im(p1) u are rounded by up to their size in ulps.
        if constexpr (kBounds)
          mag_e = (1 + q_ * u + abs_p1u * (1 + fabs(p1_.im) * u - p1_.re * u)) / abs_to_p1_;
      }
      out.r = (e - Complex<Work>{t.g, 0}) / to_p2_;
      if constexpr (kBounds) out.mag_r = (mag_e + t.mag_g) / abs_to_p2_;
    }
    if constexpr (!kBounds) return out;
    out.dr = Complex<Work>{0, q_} * out.r + Complex<Work>{t.g, 0};
    out.mag_dr = q_ * out.mag_r + t.mag_g;
    return out;
  }

 private:
  static constexpr double kSeriesLimit = 0.5;
  Work q_;
  Complex<Work> p1_, to_p1_, to_p2_;  // p1, i q - p1, i q - p2
  Work abs_to_p1_ = 0, abs_to_p2_ = 0;
  Work reach_limit_ = 0;                   // D = max(q, |p1|, |p2|) (an upper bound of it)
  std::vector<Complex<Work>> series_;      // r_{m+2}, m = 0..M
  SeriesReach<Work> reach_{kSeriesLimit};  // how many terms u D needs
};

}  // namespace frictionref::detail
