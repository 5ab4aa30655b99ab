#include "numeric/sin_cos.hpp"

#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

namespace frictionref {
namespace {

constexpr int kStepsPerPeriod = 256;  // table step pi/128

// pi/128 = kStep1 + kStep2 + kStep3 (to 1e-38). kStep1 and kStep2 have at most
// 25 significant bits, so j * kStep1 and j * kStep2 are exact in long double
// for |j| < 2^39, and x - j * kStep1 - j * kStep2 loses nothing (Cody & Waite).
// Split from 150 digits of pi; tests/test_sin_cos.cpp checks the sum against
// Boost's 50-digit pi.
constexpr long double kStep1 = 0x1921fb5p-30L;
constexpr long double kStep2 = 0x8885a3p-55L;
constexpr long double kStep3 = 0x8d313198a2e03707p-123L;
constexpr long double kStepsPerRadian = 40.743665431525205956834243423363677L;  // 128 / pi
constexpr long double kReducibleLimit = 0x1p38L;  // keeps |j| < 2^39

struct Table {
  std::array<long double, kStepsPerPeriod> sin;
  std::array<long double, kStepsPerPeriod> cos;
};

// sin and cos of j pi/128, rounded once from 50 digits. Only the first
// quadrant is computed (64 angles, ~2 ms); the others follow exactly from
// sin(q pi/2 + t) = sin t, cos t, -sin t, -cos t for q = 0..3 (and likewise
// cos), so the table is exactly symmetric.
Table make_table() {
  using Fifty = boost::multiprecision::cpp_bin_float_50;
  constexpr int kQuadrant = kStepsPerPeriod / 4;
  std::array<long double, kQuadrant> s{}, c{};
  const Fifty step = boost::math::constants::pi<Fifty>() / 128;
  for (int j = 0; j < kQuadrant; ++j) {
    const Fifty angle = step * j;
    s[j] = static_cast<long double>(sin(angle));
    c[j] = static_cast<long double>(cos(angle));
  }
  Table table{};
  for (int j = 0; j < kStepsPerPeriod; ++j) {
    const int r = j % kQuadrant;
    switch (j / kQuadrant) {
      case 0: table.sin[j] = s[r]; table.cos[j] = c[r]; break;
      case 1: table.sin[j] = c[r]; table.cos[j] = -s[r]; break;
      case 2: table.sin[j] = -s[r]; table.cos[j] = -c[r]; break;
      default: table.sin[j] = -c[r]; table.cos[j] = s[r]; break;
    }
  }
  return table;
}

const Table& table() {
  static const Table instance = make_table();
  return instance;
}

}  // namespace

SinCos<long double> sin_cos(long double x) {
  if (!(std::fabs(x) <= kReducibleLimit)) return {sinl(x), cosl(x)};
  const long long j = std::llrint(x * kStepsPerRadian);
  const long double jl = static_cast<long double>(j);
  // |d| <= pi/256 (+ rounding of the quotient), exact to the last bits.
  const long double d = ((x - jl * kStep1) - jl * kStep2) - jl * kStep3;
  // sin d = d (1 + p), cos d = 1 + q. p and q are below 1e-4, so double
  // (relative error 1e-16) gives them to ~1e-21 absolute, under an ulp of
  // long double; the terms left out are below 1e-22.
  const double dd = static_cast<double>(d);
  const double d2 = dd * dd;
  const double p = d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880))));
  const double q =
      d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320))));
  const Table& t = table();
  const int index = static_cast<int>(j & (kStepsPerPeriod - 1));
  const long double s = t.sin[index];
  const long double c = t.cos[index];
  const long double sin_d = d + d * p;
  // sin(x) = s cos d + c sin d, cos(x) = c cos d - s sin d; the table value
  // is added last so the small terms keep their bits.
  return {s + (s * q + c * sin_d), c + (c * q - s * sin_d)};
}

}  // namespace frictionref
