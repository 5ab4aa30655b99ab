// Closed-form motion inside one phase (THEORY.md, docs/theory.md section 2).
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

namespace frictionref {

// The type the engine computes in: wider than the output type where the
// hardware has one, so event times chained over 10^5 periods keep full double
// accuracy (x86-64 long double: 64-bit mantissa). Multiprecision types compute
// in themselves.
template <class Real>
struct WorkType {
  using type = Real;
};
template <>
struct WorkType<double> {
  using type = long double;
};
template <class Real>
using work_t = typename WorkType<Real>::type;

template <class Work>
class PhaseLaw {
 public:
  // The law of a phase of kind `kind` starting at forcing phase tau_a = w t_a.
  template <class Real>
  PhaseLaw(const BasicModel<Real>& model, PhaseKind kind, const Work& tau_a, const Work& x_a,
           const Work& v_a)
      : omega_(model.omega),
        b_(Work(model.amplitude) / (Work(model.mass) * Work(model.omega))),
        r_(Work(model.friction) / (Work(model.mass) * Work(model.omega))),
        s_(slip_sign(kind)),
        tau_a_(tau_a),
        x_a_(x_a),
        v_a_(v_a) {
    using std::cos;
    using std::sin;
    cos_a_ = cos(tau_a);
    sin_a_ = sin(tau_a);
  }

  int sign() const { return s_; }
  const Work& tau_begin() const { return tau_a_; }
  const Work& cos_begin() const { return cos_a_; }

  Work velocity(const Work& tau) const {
    if (s_ == 0) return Work(0);
    return v_a_ + b_ * cos_difference(tau - tau_a_) - Work(s_) * r_ * (tau - tau_a_);
  }

  // s * v: positive while the slip lasts; the function whose root ends it.
  Work speed_along_slip(const Work& tau) const {
    return Work(s_) * (v_a_ + b_ * cos_difference(tau - tau_a_)) - r_ * (tau - tau_a_);
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
    using std::sin;
    const Work h = tau - tau_a_;
    const Work half = sin(h / 2);
    const Work forced = cos_a_ * h_minus_sin_h(h) + 2 * sin_a_ * half * half;
    return x_a_ + (v_a_ * h + b_ * forced - Work(s_) * r_ * h * h / 2) / omega_;
  }

  // cos a - cos(a + h) = 2 cos a sin^2(h/2) + sin a sin h: no cancellation
  // where cos a and cos(a + h) are both near +-1, so a stop there stays
  // resolvable to the last bits (a plain cos a - cos tau loses them).
  Work cos_difference(const Work& h) const {
    using std::sin;
    const Work half = sin(h / 2);
    return 2 * cos_a_ * half * half + sin_a_ * sin(h);
  }

  // h - sin h, by its Taylor series where the difference would cancel.
  static Work h_minus_sin_h(const Work& h) {
    using std::fabs;
    using std::sin;
    if (fabs(h) > Work(1) / 2) return h - sin(h);
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

 private:
  Work omega_, b_, r_;
  int s_;
  Work tau_a_, x_a_, v_a_;
  Work cos_a_, sin_a_;
};

}  // namespace frictionref
