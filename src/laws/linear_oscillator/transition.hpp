// The homogeneous part of a slip of the linear oscillator (docs/theory.md 7.2):
//
//   y'' + 2 sigma y' + rho^2 y = p0     (derivatives in tau = w t; y = w x, y' = v)
//
// from a state (y_a, v_a) at u = tau - tau_a = 0 reaches
//
//   y(u) = Phi11 y_a + G  v_a + p0 G1,      v(u) = -rho^2 G y_a + G' v_a + p0 G,
//
// with G the impulse response (G(0) = 0, G'(0) = 1), Phi11 = G' + 2 sigma G and
// G1 = integral of G. A forcing ramp p1 u (a ground record, linear between
// its samples) adds p1 G2 to y and p1 G1 to v, G2 = integral of G1
// = (u - G - 2 sigma G1) / rho^2. One set of formulas would lose digits somewhere (near
// critical damping the over- and underdamped forms divide by ~0; for short
// times 1 - Phi11 cancels; a slow overdamped root makes 1 - Phi11 tiny), so:
//
//   * u max(2 sigma, rho) <= 1/2: the Taylor series of G from the ODE's
//     recurrence, valid for every damping ratio (no division by the root
//     separation); its coefficients depend on the model only, so they are
//     computed once and each evaluation is three Horner sums;
//   * otherwise underdamped (sigma < rho): exp(-sigma u) with cos, sin(nu u)/nu;
//     critically and overdamped: the two decay rates k1 = rho^2/(sigma + mu)
//     (no cancellation), k2 = sigma + mu, and -expm1(-2 mu u)/(2 mu) for
//     sinh(mu u)/mu (smooth as mu -> 0); G1 = (1 - Phi11)/rho^2 where Phi11
//     <= 1/2, else (slow overdamped root) from the rates with
//     phi1(z) = expm1(z)/z.
//
// Each value comes with the magnitude its rounding error is a few ulps of
// (`mag_*`), for the certified event search; at<false> leaves the
// magnitudes and G'''' out (dense output and the search's plain points read
// neither), its values those of at<true> bit for bit.
#pragma once

#include <boost/math/special_functions/expm1.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "numeric/complex.hpp"
#include "numeric/series_reach.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Work>
struct Transition {
  Work g = 0;                   // G(u): y per unit initial velocity; v per unit constant forcing
  Work dg = 1;                  // G'(u): v per unit initial velocity
  Work phi11 = 1;               // y per unit initial position
  Work g1 = 0;                  // integral of G: y per unit constant forcing
  Work ramp = 0;                // integral of G1: y per unit slope of the forcing
  Work g2 = 0, g3 = 0, g4 = 0;  // G'', G''', G''''
  // Magnitudes: each value's rounding error is a few ulps of these.
  Work mag_g = 0, mag_dg = 1, mag_phi11 = 1, mag_g1 = 0, mag_ramp = 0;
  Work mag_g2 = 0, mag_g3 = 0, mag_g4 = 0;
  // e^{p u} of the near root where the closed form computed it (beyond the
  // series): the harmonics' responses reuse it instead of a second exp and
  // sin_cos of the same arguments.
  bool has_root_exp = false;
  Work root_decay = 1, root_cos = 1, root_sin = 0;  // e^{p u} = decay (cos + i sin)
};

// e^{p u} for the near root, with its modulus.
template <class Work>
struct RootExp {
  Complex<Work> value;
  Work modulus = 1;
};

// The characteristic roots of p^2 + 2 sigma p + rho^2: `near` is the one
// nearer the positive imaginary axis (-sigma + i nu, or the slow -k1).
template <class Work>
struct RootPair {
  Complex<Work> near, far;
};

template <class Work>
class TransitionFunctions {
 public:
  // sigma = c / (2 m w) >= 0, rho2 = k / (m w^2) >= 0.
  TransitionFunctions(const Work& sigma, const Work& rho2) : sigma_(sigma), rho2_(rho2) {
    using std::sqrt;
    rho_ = sqrt(rho2);
    // max(2 sigma, rho) bounds |p| u for both characteristic roots p.
    rate_ = 2 * sigma > rho_ ? Work(2 * sigma) : rho_;
    underdamped_ = sigma < rho_;
    if (underdamped_) {
      nu_ = sqrt((rho_ - sigma) * (rho_ + sigma));
    } else {
      mu_ = sqrt((sigma - rho_) * (sigma + rho_));
      k1_ = sigma + mu_ > 0 ? Work(rho2 / (sigma + mu_)) : Work(0);
      k2_ = sigma + mu_;
    }
    // G = sum c_n u^n, c_0 = 0, c_1 = 1,
    // c_{n+2} = -(2 sigma (n+1) c_{n+1} + rho^2 c_n) / ((n+1)(n+2)).
    // |c_n| <= rate^(n-1) / (n-1)!, so with x = u rate <= kSeriesLimit the
    // terms after c_N u^N are below eps |G| / 64 once x^N / N! <= eps / 64;
    // (series_reach.hpp).
    if (rate_ > 0) {
      const int terms = static_cast<int>(reach_.max_terms());
      std::vector<Work> c(static_cast<std::size_t>(terms) + 2, Work(0));
      c[1] = 1;
      for (int n = 0; n + 2 <= terms; ++n)
        c[n + 2] = -(2 * sigma * Work(n + 1) * c[n + 1] + rho2 * c[n]) / Work((n + 1) * (n + 2));
      for (int n = 1; n <= terms; ++n) {
        g_.push_back(c[n]);                               // of u^n
        dg_.push_back(Work(n) * c[n]);                    // of u^(n-1)
        g1_.push_back(c[n] / Work(n + 1));                // of u^(n+1)
        ramp_.push_back(c[n] / Work((n + 1) * (n + 2)));  // of u^(n+2)
      }
    }
  }

  // Largest |characteristic root|: the time scale of the transient.
  const Work& rate() const { return rate_; }
  const Work& sigma() const { return sigma_; }
  const Work& rho2() const { return rho2_; }

  RootPair<Work> roots() const {
    if (underdamped_) return {{-sigma_, nu_}, {-sigma_, -nu_}};
    return {{-k1_, 0}, {-k2_, 0}};
  }

  // e^{p u} for the near root (forced_response.hpp), from the transition
  // functions at the same u where they hold it.
  RootExp<Work> root_exp(const Work& u, const Transition<Work>& at_u) const {
    using std::exp;
    Work decay, c = 1, s = 0;
    if (at_u.has_root_exp) {
      decay = at_u.root_decay;
      c = at_u.root_cos;
      s = at_u.root_sin;
    } else if (underdamped_) {
      decay = exp(-sigma_ * u);
      const SinCos<Work> sc = sin_cos(nu_ * u);
      c = sc.cos;
      s = sc.sin;
    } else {
      decay = k1_ == 0 ? Work(1) : Work(exp(-k1_ * u));  // k = 0: the root p = 0
    }
    return {{decay * c, decay * s}, decay};
  }

  // At u = tau - tau_a >= 0.
  template <bool kBounds = true>
  Transition<Work> at(const Work& u) const {
    if (u == 0) {  // G = 0, G' = 1 and the higher derivatives from the ODE
      Transition<Work> t;
      higher_by_ode<kBounds>(t);
      return t;
    }
    if (u * rate_ <= kSeriesLimit) return series<kBounds>(u);
    return underdamped_ ? underdamped<kBounds>(u) : overdamped<kBounds>(u);
  }

 private:
  static constexpr double kSeriesLimit = 0.5;

  template <bool kBounds>
  Transition<Work> series(const Work& u) const {
    using std::fabs;
    Transition<Work> t;
    if (rate_ == 0) {  // k = c = 0: G = u exactly
      t.g = u;
      t.dg = 1;
      t.phi11 = 1;
      t.g1 = u * u / 2;
      t.ramp = u * u * u / 6;
      t.mag_g = u;
      t.mag_dg = 1;
      t.mag_phi11 = 1;
      t.mag_g1 = t.g1;
      t.mag_ramp = t.ramp;
      return t;  // G'' = G''' = G'''' = 0
    }
    // Horner sums of the first N precomputed coefficients (c_n u^(n-1),
    // n >= 1), N the fewest this u needs.
    const std::size_t n = reach_.index_for(u * rate_);
    Work g = 0, dg = 0, g1 = 0, ramp = 0;
    for (std::size_t i = n + 1; i-- > 0;) {
      g = g * u + g_[i];
      dg = dg * u + dg_[i];
      g1 = g1 * u + g1_[i];
      ramp = ramp * u + ramp_[i];
    }
    t.g = g * u;
    t.dg = dg;
    t.g1 = g1 * u * u;
    t.ramp = ramp * u * u * u;
    t.phi11 = t.dg + 2 * sigma_ * t.g;
    if constexpr (kBounds) {
      // |c_n| <= rate^(n-1) / (n-1)! bounds the sums of |terms| with u rate <= 1
      // by e u, 2 e, e u^2 / 2 and e u^3 / 6.
      t.mag_g = 3 * u;
      t.mag_dg = 6;
      t.mag_phi11 = 6 + 6 * sigma_ * u;
      t.mag_g1 = 3 * u * u / 2;
      t.mag_ramp = u * u * u / 2;
    }
    higher_by_ode<kBounds>(t);
    return t;
  }

  template <bool kBounds>
  Transition<Work> underdamped(const Work& u) const {
    using std::exp;
    using std::fabs;
    Transition<Work> t;
    const Work e = exp(-sigma_ * u);
    const SinCos<Work> sc = sin_cos(nu_ * u);
    const Work s = sc.sin / nu_;  // sin(nu u) / nu: relative accuracy kept as nu -> 0
    t.g = e * s;
    t.dg = e * (sc.cos - sigma_ * s);
    t.phi11 = e * (sc.cos + sigma_ * s);
    t.g1 = (1 - t.phi11) / rho2_;
    if constexpr (kBounds) {
      // The arguments sigma u and nu u are rounded by up to their size in ulps:
      // exp and sin(nu u) / nu move by sigma u |value| and u.
      const Work arg = sigma_ * u + nu_ * u;
      t.mag_g = (fabs(t.g) + e * fabs(s)) * (1 + sigma_ * u) + e * u;
      t.mag_dg = e * (fabs(sc.cos) + sigma_ * fabs(s)) * (1 + arg) + e * sigma_ * u;
      t.mag_phi11 = t.mag_dg;
      t.mag_g1 = (1 + t.mag_phi11) / rho2_;
    }
    ramp_from_g1<kBounds>(u, t);
    t.has_root_exp = true;
    t.root_decay = e;
    t.root_cos = sc.cos;
    t.root_sin = sc.sin;
    higher_by_ode<kBounds>(t);
    return t;
  }

  // G'' = -2 sigma G' - rho^2 G and so on: no cancellation beyond a small
  // factor where the roots are complex (|p| = rho) or u |p| is small.
  template <bool kBounds>
  void higher_by_ode(Transition<Work>& t) const {
    t.g2 = -2 * sigma_ * t.dg - rho2_ * t.g;
    t.g3 = -2 * sigma_ * t.g2 - rho2_ * t.dg;
    if constexpr (!kBounds) return;
    t.g4 = -2 * sigma_ * t.g3 - rho2_ * t.g2;
    t.mag_g2 = 2 * sigma_ * t.mag_dg + rho2_ * t.mag_g;
    t.mag_g3 = 2 * sigma_ * t.mag_g2 + rho2_ * t.mag_dg;
    t.mag_g4 = 2 * sigma_ * t.mag_g3 + rho2_ * t.mag_g2;
  }

  template <bool kBounds>
  Transition<Work> overdamped(const Work& u) const {
    using boost::math::expm1;
    using std::exp;
    using std::fabs;
    Transition<Work> t;
    const Work e1 = exp(-k1_ * u);
    const Work e2 = exp(-k2_ * u);
    const Work x = 2 * mu_ * u;
    // sinh(mu u) / mu * exp(-sigma u) = e1 (1 - exp(-2 mu u)) / (2 mu).
    const Work shape = x > 0 ? Work(-expm1(-x) / x) : Work(1);
    t.g = e1 * u * shape;
    const Work even = (e1 + e2) / 2;  // cosh(mu u) exp(-sigma u)
    t.dg = even - sigma_ * t.g;
    t.phi11 = even + sigma_ * t.g;
    // exp(-k u) moves by k u |value| when its argument is rounded.
    const Work arg = k2_ * u;
    t.mag_g = fabs(t.g) * (1 + arg);
    t.mag_dg = even * (1 + arg) + sigma_ * t.mag_g;
    t.mag_phi11 = t.mag_dg;
    // (1 - Phi11) / rho^2 where 1 - Phi11 keeps its digits: Phi11 <= 1/2, or
    // 1 - Phi11 >= x / 2, the cancellation the rates' form below suffers
    // (its two phi1 differ by about x / 2 when x is small). Otherwise (a slow
    // overdamped root, or rho = 0) the rates' form. (With x < 1 alone as the
    // test, a damper with sigma^2 = 1e297 rho^2 (rho^2 = 3.5e-295) took 1 -
    // Phi11 ~ rho^2 from its rounding of 1e-19: G1 came out 1e275, the ramp's
    // G2 1e572, and a slip ended at x = -inf; found by fuzzing.)
    const bool rates_form = !(rho2_ > 0) || (t.phi11 > Work(0.5) && x > 0 && 1 - t.phi11 < x / 2);
    if (!rates_form) {
      t.g1 = (1 - t.phi11) / rho2_;
      t.mag_g1 = (1 + t.mag_phi11) / rho2_;
      ramp_from_g1<kBounds>(u, t);
    } else {
      // Slow root: G1 = u [phi1(-k1 u) - phi1(-k2 u)] / (k2 - k1), with
      // (k2 - k1) u = 2 mu u = x (>= 1, or below 1 where 1 - Phi11 cancels
      // worse), and likewise
      // G2 = u^2 [phi2(-k1 u) - phi2(-k2 u)] / (k2 - k1).
      const Work p1 = phi1(-k1_ * u);
      const Work p2 = phi1(-k2_ * u);
      t.g1 = u * (p1 - p2) / (2 * mu_);
      t.mag_g1 = u * (fabs(p1) + fabs(p2)) / (2 * mu_) * (1 + arg);
      const Work r1 = phi2(-k1_ * u);
      const Work r2 = phi2(-k2_ * u);
      t.ramp = u * u * (r1 - r2) / (2 * mu_);
      t.mag_ramp = u * u * (fabs(r1) + fabs(r2)) / (2 * mu_) * (1 + arg);
    }
    // G^(n+1) = -k1 G^(n) + (-k2)^n e2 (from G = (e1 - e2) / (k2 - k1)):
    // exact in relative terms on the slow tail, where the ODE's form
    // -2 sigma G' - rho^2 G would cancel (2 sigma k1 ~ rho^2 when heavily
    // overdamped) and lose everything to the fast root's scale.
    t.g2 = -k1_ * t.dg - k2_ * e2;
    t.g3 = -k1_ * t.g2 + k2_ * k2_ * e2;
    t.g4 = -k1_ * t.g3 - k2_ * k2_ * k2_ * e2;
    t.mag_g2 = (k1_ * t.mag_dg + k2_ * e2) * (1 + arg);
    t.mag_g3 = (k1_ * t.mag_g2 + k2_ * k2_ * e2) * (1 + arg);
    t.mag_g4 = (k1_ * t.mag_g3 + k2_ * k2_ * k2_ * e2) * (1 + arg);
    t.has_root_exp = true;
    t.root_decay = e1;
    return t;
  }

  // expm1(z) / z, 1 at z = 0.
  static Work phi1(const Work& z) {
    using boost::math::expm1;
    return z == 0 ? Work(1) : Work(expm1(z) / z);
  }

  // (e^z - 1 - z) / z^2 for z <= 0, 1/2 at z = 0: its Taylor series
  // sum z^n / (n + 2)! where e^z - 1 - z would cancel (|z| <= 1/2), else
  // directly (there the cancellation costs at most a factor 4).
  static Work phi2(const Work& z) {
    using boost::math::expm1;
    using std::fabs;
    if (fabs(z) > Work(0.5)) return (expm1(z) - z) / (z * z);
    const Work eps = std::numeric_limits<Work>::epsilon();
    Work term = Work(1) / 2, sum = term;
    for (int n = 1; n < 200 && fabs(term) > eps * fabs(sum) / 16; ++n) {
      term *= z / Work(n + 2);
      sum += term;
    }
    return sum;
  }

  // G2 = (u - G - 2 sigma G1) / rho^2 (the ODE integrated twice), beyond the
  // series: there u rate > 1/2, so u - G cancels by at most a small factor,
  // which the magnitude carries.
  template <bool kBounds>
  void ramp_from_g1(const Work& u, Transition<Work>& t) const {
    t.ramp = (u - t.g - 2 * sigma_ * t.g1) / rho2_;
    if constexpr (kBounds) t.mag_ramp = (u + t.mag_g + 2 * sigma_ * t.mag_g1) / rho2_;
  }

  Work sigma_, rho2_, rho_ = 0, rate_ = 0;
  bool underdamped_ = false;
  Work nu_ = 0;           // underdamped: sqrt(rho^2 - sigma^2)
  Work mu_ = 0;           // overdamped: sqrt(sigma^2 - rho^2)
  Work k1_ = 0, k2_ = 0;  // decay rates sigma -+ mu
  // Series coefficients, index i for n = i + 1: c_n, n c_n, c_n / (n + 1),
  // c_n / ((n + 1)(n + 2)); reach_: how many of them u rate needs.
  std::vector<Work> g_, dg_, g1_, ramp_;
  SeriesReach<Work> reach_{kSeriesLimit};
};

}  // namespace frictionref::detail
