// What the dense fast paths' tests compare rows with: the double nearest a
// 50-digit value, and rows equal bit for bit.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstring>

#include "frictionref/phase.hpp"

namespace frictionref::testing {

using Fifty = boost::multiprecision::cpp_bin_float_50;

// The double nearest x (ties cannot occur at 50 digits for these values).
inline double nearest(const Fifty& x) {
  const double d = static_cast<double>(x);
  double best = d;
  for (double n : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)})
    if (abs(Fifty(n) - x) < abs(Fifty(best) - x)) best = n;
  return best;
}

// Bitwise, so that -0 and +0 or NaNs would count as different.
inline bool same_row(const State& s, const State& r) {
  return std::memcmp(&s.x, &r.x, sizeof(double)) == 0 &&
         std::memcmp(&s.v, &r.v, sizeof(double)) == 0 &&
         std::memcmp(&s.a, &r.a, sizeof(double)) == 0 && s.t == r.t && s.phase == r.phase;
}

}  // namespace frictionref::testing
