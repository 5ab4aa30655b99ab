// The general model in the engine's units (docs/theory.md 7.1): with
// tau = w t, y = w x (so y' = v) and forces as velocity changes per radian,
//
//   slip of sign s:  y'' + 2 sigma y' + rho^2 y = g(tau) + r_g(tau) - s r,
//   at rest:         n(tau) = g(tau) + r_g(tau) - rho^2 y,  stuck while |n| <= rs,
//
// sigma = c / (2 m w), rho^2 = k / (m w^2), r = R / (m w), rs = Rs / (m w),
// g from forcing.hpp, r_g the ground record's part (record_forcing.hpp, linear
// on each segment), and each harmonic's response from rest
// (forced_response.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "frictionref/model.hpp"
#include "laws/linear_oscillator/forced_response.hpp"
#include "laws/linear_oscillator/forcing.hpp"
#include "laws/linear_oscillator/record_forcing.hpp"
#include "laws/linear_oscillator/transition.hpp"
#include "numeric/integer_power.hpp"

namespace frictionref::detail {

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
        record_(model.ground_motion, Work(model.omega)),
        transition_(sigma_, rho2_) {
    using std::fabs;
    for (const auto& term : forcing_.terms()) {
      responses_.emplace_back(term.q, transition_);
      // H = 1 / (rho^2 - q^2 + 2 i sigma q); infinite at resonance.
      const Complex<Work> p{rho2_ - term.q * term.q, 2 * sigma_ * term.q};
      const bool resonant = p.re == 0 && p.im == 0;
      steady_.push_back(resonant ? Complex<Work>{} : Complex<Work>{1, 0} / p);
      steady_abs_.push_back(steady_.back().abs());
      if (resonant)
        steady_bound4_ = std::numeric_limits<Work>::infinity();
      else
        steady_bound4_ += fabs(term.a) * steady_.back().abs() * integer_power(term.q, 4);
    }
  }

  const Work& omega() const { return omega_; }
  const Work& sigma() const { return sigma_; }
  const Work& rho2() const { return rho2_; }
  const Work& r() const { return r_; }
  const Work& rs() const { return rs_; }
  const Forcing<Work>& forcing() const { return forcing_; }
  // The ground record's part of the forcing (none: r_g = 0).
  const RecordForcing<Work>& record() const { return record_; }
  // One per forcing term, in the same order.
  const std::vector<ForcedResponse<Work>>& responses() const { return responses_; }
  const TransitionFunctions<Work>& transition() const { return transition_; }
  // Each harmonic's steady response H (0 at resonance), and
  // sum |a| |H| q^4 >= |v_p'''| (infinite at resonance): only for bounds,
  // the motion itself is computed without H (forced_response.hpp).
  const std::vector<Complex<Work>>& steady() const { return steady_; }
  const Work& steady_bound4() const { return steady_bound4_; }
  const std::vector<Work>& steady_abs() const { return steady_abs_; }  // |H|
  // The fastest rate at which the motion can turn, per radian of tau: the
  // natural frequency rho, the damping's 2 sigma, the forcing frequencies
  // (1 for the first harmonic). It sizes the event search's work.
  Work fastest_rate() const {
    // The transient's rate max(2 sigma, rho) is the transition functions'.
    Work rate = transition_.rate() > 1 ? transition_.rate() : Work(1);
    for (const auto& term : forcing_.terms())
      if (term.q > rate) rate = term.q;
    return rate;
  }

 private:
  Work omega_, sigma_, rho2_, r_, rs_;
  Forcing<Work> forcing_;
  RecordForcing<Work> record_;
  TransitionFunctions<Work> transition_;
  std::vector<ForcedResponse<Work>> responses_;
  std::vector<Complex<Work>> steady_;
  std::vector<Work> steady_abs_;
  Work steady_bound4_ = 0;
};

}  // namespace frictionref::detail
