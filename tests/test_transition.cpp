// The homogeneous transition functions of the general slip law
// (laws/linear_oscillator/transition.hpp) where their forms compete for
// digits, against closed forms evaluated in 50 digits.
#include <gtest/gtest.h>

#include <cmath>

#include "frictionref/multiprecision.hpp"
#include "laws/linear_oscillator/transition.hpp"

namespace frictionref {
namespace {

// A damper whose rate dwarfs the spring's (sigma^2 / rho^2 = 1e297, the fuzz
// finding general-finding-overdamped-tiny-spring-cancellation): beyond the
// series (u 2 sigma > 1/2) but with 2 mu u < 1, G1 = (1 - Phi11) / rho^2
// took 1 - Phi11 ~ rho^2 from rounding, and G1 came out ~1e275. Here rho^2
// is negligible (its terms are ~rho^2 u^2 relative), so G1 and G2 are those
// of rho = 0: G = (1 - e^{-2 sigma u}) / (2 sigma) integrated once and twice.
TEST(TransitionFunctions, TinySpringUnderAHeavyDamperKeepsG1AndG2) {
  using Wide = HighPrecision;
  const long double sigma = 20.8330078125L, rho2 = 3.48e-295L;
  const detail::TransitionFunctions<long double> transition(sigma, rho2);
  for (const long double u : {0.013L, 0.0165L, 0.02L, 0.024L, 0.05L, 0.5L}) {
    SCOPED_TRACE(static_cast<double>(u));
    const detail::Transition<long double> t = transition.at(u);
    const Wide s(sigma), w(u);
    const Wide decay = 1 - exp(-2 * s * w);
    const Wide g1 = w / (2 * s) - decay / (4 * s * s);
    const Wide g2 = w * w / (4 * s) - w / (4 * s * s) + decay / (8 * s * s * s);
    const auto relative = [](long double value, const Wide& exact) {
      return static_cast<double>(abs((Wide(value) - exact) / exact));
    };
    EXPECT_LT(relative(t.g1, g1), 1e-17);
    EXPECT_LT(relative(t.ramp, g2), 1e-17);
    // The error bounds stay those of a few ulps of values of that size.
    EXPECT_GE(t.mag_g1, std::fabs(t.g1));
    EXPECT_LT(t.mag_g1, 100 * std::fabs(t.g1));
  }
}

}  // namespace
}  // namespace frictionref
