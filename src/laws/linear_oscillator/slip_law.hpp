// A slip of the linear oscillator in closed form (docs/theory.md 7.2, 7.3).
//
// From (y_a, v_a) at tau_a, with y_p the steady response to the harmonics
// (oscillator.hpp) and the homogeneous transition functions (transition.hpp):
//
//   y(tau) = y_p(tau) + Phi11 (y_a - y_p(tau_a)) + G (v_a - v_p(tau_a)) + g0 G1
//   v(tau) = v_p(tau) - rho^2 G (y_a - y_p(tau_a)) + G' (v_a - v_p(tau_a)) + g0 G
//
// with g0 = f0 - s r and G, G', Phi11, G1 at u = tau - tau_a. Higher
// derivatives follow from the ODE. For the event search (first_zero.hpp) the
// law also gives a rigorous bound of |v'''| on [tau, tau + h]: v''' = v_p'''
// + z_h', where z_h = v'' - v_p'' solves the homogeneous equation (the
// constant forcing drops out after two derivatives), whose energy
// rho^2 z_h^2 + z_h'^2 never grows (d/dtau = -4 sigma z_h'^2 <= 0); so
// |z_h'| <= sqrt(rho^2 z_h(tau)^2 + z_h'(tau)^2) for all later times.
#pragma once

#include <cmath>
#include <limits>

#include "laws/linear_oscillator/oscillator.hpp"
#include "numeric/first_zero.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Work>
class LinearSlipLaw {
 public:
  // Everything at one time of the slip.
  struct Point {
    Work tau = 0;
    Work y = 0, v = 0;            // y = w x, v
    Work d1 = 0, d2 = 0, d3 = 0;  // dv/dtau, d2v/dtau2, d3v/dtau3
    Work e_y = 0, e_v = 0, e_d1 = 0, e_d2 = 0, e_d3 = 0;  // rounding-error bounds
    Work tail = 0;  // sup over later times of |v''' - v_p'''| (homogeneous part)
  };

  LinearSlipLaw(const Oscillator<Work>& oscillator, int sign, const Work& tau_a, const Work& y_a,
                const Work& v_a)
      : o_(&oscillator), s_(sign), tau_a_(tau_a), y_a_(y_a), v_a_(v_a) {
    using std::fabs;
    g0_ = o_->forcing().constant() - Work(s_) * o_->r();
    Steady at_start = steady(tau_a);
    dy_ = y_a - at_start.y;
    dv_ = v_a - at_start.v;
    mag_dy_ = fabs(y_a) + at_start.mag_y;
    mag_dv_ = fabs(v_a) + at_start.mag_v;
  }

  int sign() const { return s_; }
  const Work& tau_begin() const { return tau_a_; }

  // The state and derivatives at tau; with_bounds: also the rounding-error
  // bounds and the tail, which only the event search needs.
  Point point(const Work& tau, bool with_bounds = true) const {
    return with_bounds ? evaluate<true>(tau) : evaluate<false>(tau);
  }

 private:
  template <bool kBounds>
  Point evaluate(const Work& tau) const {
    using std::fabs;
    using std::sqrt;
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work rho2 = o_->rho2();
    const Work sigma = o_->sigma();
    const Transition<Work> t = o_->transition().at(tau - tau_a_);
    const Steady p = steady<kBounds>(tau);
    Point q;
    q.tau = tau;
    q.y = p.y + t.phi11 * dy_ + t.g * dv_ + g0_ * t.g1;
    q.v = p.v - rho2 * t.g * dy_ + t.dg * dv_ + g0_ * t.g;
    q.d1 = p.g - Work(s_) * o_->r() - 2 * sigma * q.v - rho2 * q.y;
    q.d2 = p.dg - 2 * sigma * q.d1 - rho2 * q.v;
    q.d3 = p.d2g - 2 * sigma * q.d2 - rho2 * q.d1;
    if constexpr (!kBounds) return q;
    // Rounding: kUlps ulps of the sum of the terms' magnitudes, plus the
    // rounding of the harmonics' arguments q tau + phi (p.phase_*).
    const Work mag_y =
        p.mag_y + t.mag_phi11 * mag_dy_ + t.mag_g * mag_dv_ + fabs(g0_) * t.mag_g1;
    const Work mag_v =
        p.mag_v + rho2 * t.mag_g * mag_dy_ + t.mag_dg * mag_dv_ + fabs(g0_) * t.mag_g;
    const Work mag_d1 = p.mag_g + o_->r() + 2 * sigma * mag_v + rho2 * mag_y;
    const Work mag_d2 = p.mag_dg + 2 * sigma * mag_d1 + rho2 * mag_v;
    const Work mag_d3 = p.mag_d2g + 2 * sigma * mag_d2 + rho2 * mag_d1;
    const Work k = kUlps * eps;
    q.e_y = k * mag_y + eps * p.phase_y;
    q.e_v = k * mag_v + eps * p.phase_v;
    q.e_d1 = k * mag_d1 + eps * (p.phase_g + 2 * sigma * p.phase_v + rho2 * p.phase_y);
    q.e_d2 = k * mag_d2 + eps * (p.phase_dg + 2 * sigma * p.phase_g + rho2 * p.phase_v);
    q.e_d3 = k * mag_d3 + eps * (p.phase_d2g + 2 * sigma * p.phase_dg + rho2 * p.phase_g);
    // The homogeneous part of v'' (z_h) and v''' (z_h'), with their errors.
    const Work z = fabs(q.d2 - p.d2v) + q.e_d2 + k * p.mag_d2v;
    const Work dz = fabs(q.d3 - p.d3v) + q.e_d3 + k * p.mag_d3v;
    q.tail = sqrt(rho2 * z * z + dz * dz) * (1 + 16 * eps);
    return q;
  }

 public:
  // The jet of f = s v at a point, for the event search.
  Jet<Work> jet(const Point& q) const {
    const Work s(s_);
    return {s * q.v, s * q.d1, s * q.d2, q.e_v, q.e_d1, q.e_d2, q.tail};
  }

  // >= sup |f'''| on [tau, tau + h], given the point at tau.
  Work third_bound(const Work& tau, const Jet<Work>& at, const Work& h) const {
    using std::fabs;
    Work bound = o_->steady_bound4() + at.tail;
    const Work u_end = tau + h - tau_a_;
    const auto& terms = o_->forcing().terms();
    for (std::size_t i = 0; i < terms.size(); ++i) {
      if (!o_->responses()[i].resonant) continue;
      const Work q = terms[i].q;
      bound += fabs(terms[i].a) * (2 * q * q + q * q * q * fabs(u_end) / 2);
    }
    return bound * (1 + 64 * std::numeric_limits<Work>::epsilon());
  }

  // Acceleration dv/dt = w dv/dtau.
  Work acceleration(const Point& q) const { return o_->omega() * q.d1; }

 private:
  static constexpr int kUlps = 64;

  // The steady response to the harmonics at tau, the forcing g and its first
  // two derivatives, v_p'' and v_p''' (for the tail), with magnitudes.
  struct Steady {
    Work y = 0, v = 0, d2v = 0, d3v = 0;
    Work g = 0, dg = 0, d2g = 0;
    Work mag_y = 0, mag_v = 0, mag_d2v = 0, mag_d3v = 0;
    Work mag_g = 0, mag_dg = 0, mag_d2g = 0;
    // Errors from the argument rounding, per ulp (|q tau| + |phi| times the slope).
    Work phase_y = 0, phase_v = 0, phase_g = 0, phase_dg = 0, phase_d2g = 0;
  };

  template <bool kBounds = true>
  Steady steady(const Work& tau) const {
    using std::fabs;
    Steady p;
    p.g = o_->forcing().constant();
    if constexpr (kBounds) p.mag_g = fabs(p.g);
    const Work u = tau - tau_a_;
    const auto& terms = o_->forcing().terms();
    const auto& responses = o_->responses();
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const ForcingTerm<Work>& f = terms[i];
      const HarmonicResponse<Work>& h = responses[i];
      const Work theta = f.q * tau + f.phase;
      const SinCos<Work> sc = sin_cos(theta);
      const Work a = f.a, q = f.q, abs_a = fabs(a);
      const Work q2 = q * q, q3 = q2 * q, q4 = q2 * q2;
      p.g += a * sc.sin;
      p.dg += a * q * sc.cos;
      p.d2g -= a * q2 * sc.sin;
      if constexpr (!kBounds) {
        if (!h.resonant) {
          const Work sin_part = a * h.re * sc.sin + a * h.im * sc.cos;
          const Work cos_part = a * h.re * sc.cos - a * h.im * sc.sin;
          p.y += sin_part;
          p.v += q * cos_part;
        } else {
          const Work c = a / (2 * q);
          p.y -= c * u * sc.cos;
          p.v -= c * (sc.cos - u * q * sc.sin);
        }
        continue;
      }
      p.mag_g += abs_a;
      p.mag_dg += abs_a * q;
      p.mag_d2g += abs_a * q2;
      // The argument q tau + phi is rounded by up to |theta| ulps (radians per
      // ulp): each value moves by its derivative in theta times that.
      const Work arg = fabs(theta) + fabs(f.phase);
      p.phase_g += abs_a * arg;
      p.phase_dg += abs_a * q * arg;
      p.phase_d2g += abs_a * q2 * arg;
      if (!h.resonant) {
        const Work in_phase = a * h.re, quadrature = a * h.im;  // y_p = A sin + C cos
        const Work sin_part = in_phase * sc.sin + quadrature * sc.cos;
        const Work cos_part = in_phase * sc.cos - quadrature * sc.sin;
        p.y += sin_part;
        p.v += q * cos_part;
        p.d2v -= q3 * cos_part;
        p.d3v += q4 * sin_part;
        const Work size = abs_a * h.size;
        p.mag_y += size;
        p.mag_v += size * q;
        p.mag_d2v += size * q3;
        p.mag_d3v += size * q4;
        p.phase_y += size * arg;
        p.phase_v += size * q * arg;
      } else {
        // Y = -(a / 2q) u cos(theta), from the start of this slip.
        const Work c = a / (2 * q);
        p.y -= c * u * sc.cos;
        p.v -= c * (sc.cos - u * q * sc.sin);
        p.d2v += Work(3) / 2 * a * q * sc.cos - a * q2 * u / 2 * sc.sin;
        p.d3v += -2 * a * q2 * sc.sin - a * q3 * u / 2 * sc.cos;
        const Work au = abs_a * fabs(u);
        p.mag_y += au / (2 * q);
        p.mag_v += abs_a / (2 * q) + au / 2;
        p.mag_d2v += Work(3) / 2 * abs_a * q + au * q2 / 2;
        p.mag_d3v += 2 * abs_a * q2 + au * q3 / 2;
        p.phase_y += au / 2 * arg;
        p.phase_v += (abs_a / 2 + au * q / 2) * arg;
      }
    }
    return p;
  }

  const Oscillator<Work>* o_;
  int s_;
  Work tau_a_, y_a_, v_a_;
  Work g0_ = 0;             // f0 - s r
  Work dy_ = 0, dv_ = 0;    // the homogeneous part of the start state
  Work mag_dy_ = 0, mag_dv_ = 0;
};

}  // namespace frictionref::detail
