// The physical model: a mass m on a Coulomb-friction surface, driven by
// F(t) = B sin(w t), starting from (x0, v0) at t0. All values in user units
// (any consistent set: force = mass * length / time^2).
//
//   v > 0:  m x'' = B sin(w t) - R
//   v < 0:  m x'' = B sin(w t) + R
//   v = 0:  stays at rest while |B sin(w t)| <= R (static friction = sliding friction)
//
// Generic over the scalar type so the same engine runs in double and in a
// Boost.Multiprecision type (see multiprecision.hpp).
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

#include "frictionref/error.hpp"

namespace frictionref {

template <class Real>
struct BasicModel {
  Real mass = 1;       // m: mass; finite, > 0
  Real amplitude = 1;  // B: amplitude of the driving force B sin(w t); finite, >= 0
  Real omega = 1;      // w: angular frequency of the force [rad / time unit]; finite, > 0
  Real friction = 0;   // R: Coulomb friction force magnitude (static = sliding); finite, >= 0
  Real x0 = 0;         // initial position; finite
  Real v0 = 0;         // initial velocity; finite, either sign
  Real t0 = 0;         // initial time; finite, any sign (the force phase is w t, not w (t - t0))

  // lambda = R / B, the one dimensionless parameter of the steady state.
  // +infinity when B = 0 < R; NaN when B = R = 0.
  Real lambda() const { return friction / amplitude; }

  // The driving force B sin(w t).
  Real force(const Real& t) const {
    using std::sin;
    return amplitude * sin(omega * t);
  }

  // Throws InvalidInput naming the first field that breaks its rule.
  void validate() const {
    require_finite("mass", mass);
    require_finite("amplitude", amplitude);
    require_finite("omega", omega);
    require_finite("friction", friction);
    require_finite("x0", x0);
    require_finite("v0", v0);
    require_finite("t0", t0);
    if (!(mass > 0)) fail("mass", mass, "must be > 0");
    if (!(amplitude >= 0)) fail("amplitude", amplitude, "must be >= 0");
    if (!(omega > 0)) fail("omega", omega, "must be > 0");
    if (!(friction >= 0)) fail("friction", friction, "must be >= 0");
  }

 private:
  static void require_finite(const char* name, const Real& value) {
    using std::isfinite;
    if (!isfinite(value)) fail(name, value, "must be a finite number");
  }
  [[noreturn]] static void fail(const char* name, const Real& value, const char* rule) {
    if constexpr (std::is_same_v<Real, double>) {  // shortest round-trip form
      char buffer[32];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
      throw InvalidInput(name, std::string(buffer, end), rule);
    }
    std::ostringstream text;
    text.precision(std::numeric_limits<Real>::max_digits10);
    text << value;
    throw InvalidInput(name, text.str(), rule);
  }
};

using Model = BasicModel<double>;

// The same model in another scalar type (exact for double -> wider types).
template <class To, class From>
BasicModel<To> model_cast(const BasicModel<From>& m) {
  BasicModel<To> r;
  r.mass = To(m.mass);
  r.amplitude = To(m.amplitude);
  r.omega = To(m.omega);
  r.friction = To(m.friction);
  r.x0 = To(m.x0);
  r.v0 = To(m.v0);
  r.t0 = To(m.t0);
  return r;
}

}  // namespace frictionref
