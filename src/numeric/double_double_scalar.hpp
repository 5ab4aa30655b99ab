// Scalar double-double sums and Ziv's rounding test, for the replays of the
// seed's cycles (docs/theory.md 3.9, 3.10): a value hi + lo with |lo| <=
// ulp(hi) / 2 (Dekker, Knuth). The replays bound their errors by 2^-100
// times the sum of the terms' magnitudes, some 50 times the few u^2 these
// operations lose.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace frictionref::detail {

struct DoubleDouble {
  double hi = 0, lo = 0;
};

namespace double_double {

inline constexpr double kErrorPerMagnitude = 0x1p-100;

inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

inline DoubleDouble fast_two_sum(double a, double b) {  // |a| >= |b| or a == 0
  const double s = a + b;
  return {s, b - (s - a)};
}

// The low parts summed in plain double: an error of at most about
// 4 u^2 (|a| + |b|), within the bound's 2^-100 = 64 u^2 per magnitude. The
// last step is a two-sum, not a fast one: with cancellation in the leading
// parts the low parts may be the larger.
inline DoubleDouble add(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble s = two_sum(a.hi, b.hi);
  return two_sum(s.hi, s.lo + (a.lo + b.lo));
}

// k a for an integer k (exact in a double).
inline DoubleDouble scaled(double k, const DoubleDouble& a) {
  const double hi = k * a.hi;
  const double error = std::fma(k, a.hi, -hi);
  return fast_two_sum(hi, error + k * a.lo);
}

// A value of any wider type (50 digits: error at most u^2 of it; long
// double: exact, 64 bits fit in 106).
template <class Wide>
DoubleDouble split(const Wide& value) {
  const double hi = static_cast<double>(value);
  return {hi, static_cast<double>(value - Wide(hi))};
}

// The double nearest to a value within `error` of hi + lo (normalized), if
// the bound decides it: the value is then closer to hi than half the
// smaller of the two gaps around hi.
inline bool decided(const DoubleDouble& value, double error, double& rounded) {
  if (value.lo == 0 && error == 0) {
    rounded = value.hi;
    return true;
  }
  const double size = std::fabs(value.hi);
  if (size == 0 || !std::isfinite(size) || !std::isfinite(error)) return false;
  // The double below size (one less in the bit pattern of a positive
  // double): the gap is the smaller one at a power of two.
  std::uint64_t bits;
  std::memcpy(&bits, &size, sizeof bits);
  --bits;
  double below;
  std::memcpy(&below, &bits, sizeof below);
  const double gap = size - below;
  if ((std::fabs(value.lo) + error) * (1 + 0x1p-50) < gap / 2) {
    rounded = value.hi;
    return true;
  }
  return false;
}

// The double nearest to every value within `error` of `value` (a wider
// type), if they all round alike: rounding is monotone, so the two ends of
// the interval decide.
template <class Wide>
bool decided(const Wide& value, const Wide& error, double& rounded) {
  const double low = static_cast<double>(value - error), high = static_cast<double>(value + error);
  if (low != high || !std::isfinite(low)) return false;
  rounded = low;
  return true;
}

}  // namespace double_double
}  // namespace frictionref::detail
