// sin_cos(long double) against 50-digit sin and cos (an independent
// computation: Boost.Multiprecision's own series), and the split of pi/128.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "numeric/sin_cos.hpp"

namespace frictionref {
namespace {

using Fifty = boost::multiprecision::cpp_bin_float_50;

// Largest error of sin and cos over `count` arguments drawn by `draw`, in
// ulps of long double at 1 (the values lie in [-1, 1]; that is the scale the
// engine's sums use).
template <class Draw>
double worst_error_in_ulps(Draw draw, int count) {
  std::mt19937_64 generator(20261121);
  const Fifty ulp = std::numeric_limits<long double>::epsilon();
  Fifty worst = 0;
  for (int i = 0; i < count; ++i) {
    const long double x = draw(generator);
    const SinCos<long double> value = sin_cos(x);
    const Fifty exact_sin = sin(Fifty(x));
    const Fifty exact_cos = cos(Fifty(x));
    worst = std::max(worst, abs(Fifty(value.sin) - exact_sin) / ulp);
    worst = std::max(worst, abs(Fifty(value.cos) - exact_cos) / ulp);
  }
  return static_cast<double>(worst);
}

TEST(SinCos, WithinFourUlpsOfLongDoubleNearZero) {
  const auto draw = [](std::mt19937_64& g) {
    return std::uniform_real_distribution<long double>(-10, 10)(g);
  };
  EXPECT_LE(worst_error_in_ulps(draw, 20000), 4.0);
}

TEST(SinCos, WithinFourUlpsOfLongDoubleOverTheEngineRange) {
  // Forcing phases up to the engine's limit |w t| <= 1e10, log-uniform.
  const auto draw = [](std::mt19937_64& g) {
    const long double magnitude = std::pow(10.0L, std::uniform_real_distribution<long double>(-3, 10)(g));
    return std::bernoulli_distribution(0.5)(g) ? magnitude : -magnitude;
  };
  EXPECT_LE(worst_error_in_ulps(draw, 20000), 4.0);
}

TEST(SinCos, TableBoundariesAndSpecialArguments) {
  // Multiples of pi/256 (the largest reduced arguments) and tiny arguments.
  const Fifty step = boost::math::constants::pi<Fifty>() / 256;
  int k = 0;
  const auto draw = [&](std::mt19937_64&) {
    ++k;
    return k % 2 ? static_cast<long double>(step * (k % 2000)) : std::ldexp(1.0L, -(k % 120));
  };
  EXPECT_LE(worst_error_in_ulps(draw, 4000), 4.0);
  EXPECT_EQ(sin_cos(0.0L).sin, 0.0L);
  EXPECT_EQ(sin_cos(0.0L).cos, 1.0L);
}

TEST(SinCos, BeyondTheReducibleRangeFallsBackToTheLibrary) {
  const long double x = 1e15L;
  EXPECT_EQ(sin_cos(x).sin, sinl(x));
  EXPECT_EQ(sin_cos(x).cos, cosl(x));
  EXPECT_TRUE(std::isnan(sin_cos(std::numeric_limits<long double>::quiet_NaN()).sin));
}

TEST(SinCos, OtherTypesUseTheirOwnFunctions) {
  const Fifty x("0.7");
  EXPECT_EQ(sin_cos(x).sin, sin(x));
  EXPECT_EQ(sin_cos(0.7).cos, std::cos(0.7));
}

}  // namespace
}  // namespace frictionref
