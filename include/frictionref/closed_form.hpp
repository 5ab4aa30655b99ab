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
    using std::cos;
    return v_a_ + b_ * (cos_a_ - cos(tau)) - Work(s_) * r_ * (tau - tau_a_);
  }

  // s * v: positive while the slip lasts; the function whose root ends it.
  Work speed_along_slip(const Work& tau) const {
    using std::cos;
    return Work(s_) * (v_a_ + b_ * (cos_a_ - cos(tau))) - r_ * (tau - tau_a_);
  }

  // d(s * v) / d tau = s b sin tau - r.
  Work speed_slope(const Work& tau) const {
    using std::sin;
    return Work(s_) * b_ * sin(tau) - r_;
  }

  Work position(const Work& tau) const {
    if (s_ == 0) return x_a_;
    using std::sin;
    const Work h = tau - tau_a_;
    return x_a_ + ((v_a_ + b_ * cos_a_) * h - b_ * (sin(tau) - sin_a_) -
                   Work(s_) * r_ * h * h / 2) /
                      omega_;
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
