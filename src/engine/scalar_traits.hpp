// Everything that depends on the scalar type of the engine, in one place:
// the type it computes in, the time resolution of its output, the range of
// models it accepts and the root solver. The algorithms (event loop, phase
// laws) are written once against this interface and never test the type.
//
//   double        computes in x87 long double (64-bit mantissa), so event
//                 times chained over 10^5 periods keep full double accuracy;
//                 roots by GSL Brent + a long double Newton polish.
//   anything else (Boost.Multiprecision) computes in itself; roots by
//                 Boost.Math TOMS 748.
#pragma once

#include <cmath>
#include <limits>

#include "engine/root_finding.hpp"

namespace frictionref::detail {

// The range of motions every engine accepts (docs/theory.md 4.12): where it is
// not zero, the size of the motion (positions, velocities, accelerations and
// the force scales that drive them) must lie within [smallest, largest].
// Above, the closed forms overflow double; below, the output values become
// subnormal doubles that have lost their relative precision.
struct MotionLimits {
  static constexpr double largest_motion = 1e300;
  static constexpr double smallest_motion = 0x1p-969;  // 2^53 times the smallest normal double

  // Beyond this forcing phase a double cannot resolve w t well enough for the
  // event logic (its ulp there is 2e-6 rad); about 1.6e9 forcing periods.
  static constexpr double max_forcing_phase = 1e10;
};

template <class Real>
struct ScalarTraits : MotionLimits {
  using Work = Real;
  // The general laws polish event times by certified Halley steps first
  // (halley_polish.hpp); false: by the bracketing solver alone (the 50-digit
  // engine keeps Boost.Math TOMS 748 as its one root finder).
  static constexpr bool halley_polish = false;

  // Phases shorter than this (8 ulps of the output type at the time scale
  // max(1, |tau|), tau = w t) cannot be told apart from zero length in the
  // output: a stick that short is merged into the slip around it, as at a
  // grazing stop.
  static Work time_resolution(const Work& tau) {
    using std::fabs;
    const Work scale = fabs(tau) > Work(1) ? Work(fabs(tau)) : Work(1);
    return Work(8) * Work(std::numeric_limits<Real>::epsilon()) * scale;
  }

  // The zero of a decreasing f on a bracket [lo, hi] (f(lo) > 0 >= f(hi)).
  template <class F, class DF>
  static RootResult<Work> decreasing_root(const F& f, const DF& slope, const Work& lo,
                                          const Work& hi, std::uint64_t& calls) {
    return detail::decreasing_root<Work>(
        [](const F& g, const DF&, const Work& a, const Work& b) { return toms748_root(g, a, b); },
        f, slope, lo, hi, calls);
  }
};

template <>
struct ScalarTraits<double> : MotionLimits {
  using Work = long double;
  static constexpr bool halley_polish = true;

  static Work time_resolution(const Work& tau) {
    const Work scale = std::fabs(tau) > 1 ? std::fabs(tau) : Work(1);
    return Work(8) * Work(std::numeric_limits<double>::epsilon()) * scale;
  }

  template <class F, class DF>
  static RootResult<Work> decreasing_root(const F& f, const DF& slope, const Work& lo,
                                          const Work& hi, std::uint64_t& calls) {
    return detail::decreasing_root<Work>(
        [](const F& g, const DF& d, const Work& a, const Work& b) {
          return brent_then_newton(g, d, a, b);
        },
        f, slope, lo, hi, calls);
  }
};

template <class Real>
using work_t = typename ScalarTraits<Real>::Work;

}  // namespace frictionref::detail
