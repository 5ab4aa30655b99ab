// The general model in the engine's units (docs/theory.md 7.1): with
// tau = w t, y = w x (so y' = v) and forces as velocity changes per radian,
//
//   slip of sign s:  y'' + 2 sigma y' + rho^2 y = g(tau) - s r,
//   at rest:         n(tau) = g(tau) - rho^2 y,  stuck while |n| <= rs,
//
// sigma = c / (2 m w), rho^2 = k / (m w^2), r = R / (m w), rs = Rs / (m w),
// g from forcing.hpp. Also the steady response of each harmonic:
// y_p = a Im(H e^{i theta}), H = 1 / (rho^2 - q^2 + 2 i sigma q), or, at
// resonance (sigma = 0, q^2 = rho^2, where H is infinite), the secular
// y_p = -a u cos(theta) / (2 q) with u the time since the phase began.
#pragma once

#include <cmath>
#include <vector>

#include "frictionref/model.hpp"
#include "laws/linear_oscillator/forcing.hpp"
#include "laws/linear_oscillator/transition.hpp"

namespace frictionref::detail {

template <class Work>
struct HarmonicResponse {
  Work re = 0, im = 0;  // H = re + i im (0 at resonance)
  Work size = 0;        // |H| (0 at resonance)
  bool resonant = false;
};

template <class Work>
class Oscillator {
 public:
  template <class Real>
  explicit Oscillator(const BasicModel<Real>& model)
      : omega_(model.omega),
        sigma_(Work(model.damping) / (2 * Work(model.mass) * Work(model.omega))),
        rho2_(Work(model.stiffness) / (Work(model.mass) * Work(model.omega) * Work(model.omega))),
        r_(Work(model.friction) / (Work(model.mass) * Work(model.omega))),
        rs_(Work(model.static_limit()) / (Work(model.mass) * Work(model.omega))),
        forcing_(model),
        transition_(sigma_, rho2_) {
    using std::sqrt;
    for (const auto& term : forcing_.terms()) {
      HarmonicResponse<Work> h;
      const Work real = rho2_ - term.q * term.q;
      const Work imag = 2 * sigma_ * term.q;
      const Work d = real * real + imag * imag;
      if (d == 0) {
        h.resonant = true;
      } else {
        h.re = real / d;
        h.im = -imag / d;
        h.size = 1 / sqrt(d);
      }
      responses_.push_back(h);
      using std::fabs;
      using std::pow;
      if (!h.resonant) steady_bound4_ += fabs(term.a) * h.size * Work(pow(term.q, 4));
    }
  }

  const Work& omega() const { return omega_; }
  const Work& sigma() const { return sigma_; }
  const Work& rho2() const { return rho2_; }
  const Work& r() const { return r_; }
  const Work& rs() const { return rs_; }
  const Forcing<Work>& forcing() const { return forcing_; }
  const std::vector<HarmonicResponse<Work>>& responses() const { return responses_; }
  const TransitionFunctions<Work>& transition() const { return transition_; }
  // sum over non-resonant terms of |a| |H| q^4: bounds |v_p'''| of their steady response.
  const Work& steady_bound4() const { return steady_bound4_; }

 private:
  Work omega_, sigma_, rho2_, r_, rs_;
  Forcing<Work> forcing_;
  std::vector<HarmonicResponse<Work>> responses_;
  TransitionFunctions<Work> transition_;
  Work steady_bound4_ = 0;
};

}  // namespace frictionref::detail
