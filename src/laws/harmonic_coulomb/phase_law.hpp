// The seed's phase law: closed-form motion inside one phase of the harmonically
// forced Coulomb oscillator (docs/theory.md section 2).
//
// With tau = w t and the force and friction expressed as velocity changes per
// radian of forcing phase, b = B / (m w) and r = R / (m w), a slip of sign s
// (+1 forward, -1 backward) that starts at tau = a with (x_a, v_a) follows
//
//   v(tau) = v_a + b (cos a - cos tau) - s r (tau - a)
//   x(tau) = x_a + [ (v_a + b cos a)(tau - a) - b (sin tau - sin a) - s r (tau - a)^2 / 2 ] / w
//   a(tau) = w (b sin tau - s r)            (= (B sin(w t) - s R) / m)
//
// and a stick keeps x = x_a, v = a = 0. Working in velocity units rather than
// the B-scaled form keeps B = 0 (no forcing) an ordinary case.
#pragma once

#include <cmath>

#include "frictionref/model.hpp"
#include "frictionref/types.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Work>
class PhaseLaw {
 public:
  // The law of a phase of kind `kind` starting at forcing phase tau_a = w t_a.
  template <class Real>
  PhaseLaw(const BasicModel<Real>& model, PhaseKind kind, const Work& tau_a, const Work& x_a,
           const Work& v_a)
      : PhaseLaw(model, kind, tau_a, x_a, v_a, sin_cos(tau_a)) {}

  // The same with sin and cos of tau_a already known (the engine carries them
  // from event to event instead of recomputing them).
  template <class Real>
  PhaseLaw(const BasicModel<Real>& model, PhaseKind kind, const Work& tau_a, const Work& x_a,
           const Work& v_a, const SinCos<Work>& at_start)
      : PhaseLaw(Work(model.omega), Work(model.amplitude) / (Work(model.mass) * Work(model.omega)),
                 Work(model.friction) / (Work(model.mass) * Work(model.omega)), kind, tau_a, x_a,
                 v_a, at_start) {}

  // From w, b = B / (m w) and r = R / (m w) directly (the engine's own).
  PhaseLaw(const Work& omega, const Work& b, const Work& r, PhaseKind kind, const Work& tau_a,
           const Work& x_a, const Work& v_a, const SinCos<Work>& at_start)
      : omega_(omega),
        b_(b),
        r_(r),
        s_(slip_sign(kind)),
        tau_a_(tau_a),
        x_a_(x_a),
        v_a_(v_a),
        cos_a_(at_start.cos),
        sin_a_(at_start.sin) {}

  // Everything known at one forcing phase tau = tau_a + h of a slip, from a
  // single sin_cos(h / 2): the engine's root finder needs s v, its first two
  // derivatives and (at the root) the position and sin, cos of tau.
  struct Point {
    Work tau;
    Work h;             // tau - tau_a
    SinCos<Work> half;  // of h / 2
    Work speed;         // s v
    Work slope;         // d(s v) / d tau = s b sin tau - r
    Work curvature;     // d^2(s v) / d tau^2 = s b cos tau
    SinCos<Work> at;    // of tau
  };

  Point point(const Work& tau) const {
    const Work h = tau - tau_a_;
    return assemble(tau, h, sin_cos(h / 2));
  }

  // The point `delta` further on, for |delta| <= 1e-3 (a final Newton step):
  // the half angle is rotated by delta / 2 with sin and cos from their Taylor
  // series (the terms left out are below 1e-22), so no new sin_cos is needed.
  Point shifted(const Point& p, const Work& delta) const {
    const Work e = delta / 2;
    const Work e2 = e * e;
    const Work sin_e = e * (1 - e2 / 6 * (1 - e2 / 20));
    const Work cos_e = 1 - e2 / 2 * (1 - e2 / 12);
    const SinCos<Work> half{p.half.sin * cos_e + p.half.cos * sin_e,
                            p.half.cos * cos_e - p.half.sin * sin_e};
    return assemble(p.tau + delta, p.h + delta, half);
  }

  // x at a point of this slip (see position()).
  Work position(const Point& p) const {
    if (s_ == 0) return x_a_;
    const Work& h = p.h;
    const Work sin_h = 2 * p.half.sin * p.half.cos;
    const Work forced = cos_a_ * h_minus_sin_h(h, sin_h) + 2 * sin_a_ * p.half.sin * p.half.sin;
    return x_a_ + (v_a_ * h + b_ * forced - Work(s_) * r_ * h * h / 2) / omega_;
  }

  int sign() const { return s_; }
  const Work& tau_begin() const { return tau_a_; }
  const Work& cos_begin() const { return cos_a_; }
  const Work& sin_begin() const { return sin_a_; }

  // v = s (s v): the sign is exact, so this is v_a + b (cos a - cos tau) - s r h.
  Work velocity(const Work& tau) const {
    if (s_ == 0) return Work(0);
    return Work(s_) * speed_along_slip(tau);
  }

  // s * v: positive while the slip lasts; the function whose root ends it.
  Work speed_along_slip(const Work& tau) const {
    const Work h = tau - tau_a_;
    return speed(h, sin_cos(h / 2));
  }

  // d(s * v) / d tau = s b sin tau - r.
  Work speed_slope(const Work& tau) const {
    using std::sin;
    return Work(s_) * b_ * sin(tau) - r_;
  }

  // Written as x_a + (v_a h + b [cos a (h - sin h) + 2 sin a sin^2(h/2)]
  // - s r h^2 / 2) / w, h = tau - a: the same closed form without the
  // cancellation of b h cos a against b (sin tau - sin a), so a short slide
  // keeps its relative accuracy.
  Work position(const Work& tau) const {
    if (s_ == 0) return x_a_;
    return position(point(tau));
  }

  // cos a - cos(a + h) = 2 cos a sin^2(h/2) + sin a sin h
  //                   = 2 sin(h/2) (cos a sin(h/2) + sin a cos(h/2)), from the
  // sin and cos of h/2: no cancellation
  // where cos a and cos(a + h) are both near +-1, so a stop there stays
  // resolvable to the last bits (a plain cos a - cos tau loses them).
  Work cos_difference(const SinCos<Work>& half) const {
    return 2 * half.sin * (cos_a_ * half.sin + sin_a_ * half.cos);
  }

  // h - sin h, by its Taylor series where the difference would cancel.
  static Work h_minus_sin_h(const Work& h, const Work& sin_h) {
    using std::fabs;
    if (fabs(h) > Work(1) / 2) return h - sin_h;
    const Work h2 = h * h;
    Work term = h * h2 / 6;  // h^3 / 3!
    Work sum = term;
    for (int k = 2; k < 40; ++k) {  // + h^5/5! - h^7/7! ...: |term| falls by h^2/20 or more
      term *= -h2 / Work((2 * k) * (2 * k + 1));
      const Work next = sum + term;
      if (next == sum) break;
      sum = next;
    }
    return sum;
  }

  Work acceleration(const Work& tau) const {
    if (s_ == 0) return Work(0);
    using std::sin;
    return omega_ * (b_ * sin(tau) - Work(s_) * r_);
  }

  // The acceleration where sin tau is known.
  Work acceleration_at(const SinCos<Work>& at) const {
    if (s_ == 0) return Work(0);
    return omega_ * (b_ * at.sin - Work(s_) * r_);
  }

 private:
  // s v at h = tau - tau_a, from sin and cos of h / 2.
  Work speed(const Work& h, const SinCos<Work>& half) const {
    return Work(s_) * (v_a_ + b_ * cos_difference(half)) - r_ * h;
  }

  Point assemble(const Work& tau, const Work& h, const SinCos<Work>& half) const {
    Point p;
    p.tau = tau;
    p.h = h;
    p.half = half;
    const Work sin_h = 2 * half.sin * half.cos;
    const Work one_minus_cos_h = 2 * half.sin * half.sin;
    p.speed = speed(h, half);
    // sin, cos of tau = a + h by the sum formulas (cos h = 1 - (1 - cos h)).
    p.at.sin = sin_a_ + (sin_h * cos_a_ - one_minus_cos_h * sin_a_);
    p.at.cos = cos_a_ - (sin_h * sin_a_ + one_minus_cos_h * cos_a_);
    p.slope = Work(s_) * b_ * p.at.sin - r_;
    p.curvature = Work(s_) * b_ * p.at.cos;
    return p;
  }

  Work omega_, b_, r_;
  int s_;
  Work tau_a_, x_a_, v_a_;
  Work cos_a_, sin_a_;
};

}  // namespace frictionref::detail
