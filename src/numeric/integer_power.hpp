// q^k for a small integer k >= 0, the value of pow(q, k), without pow's cost
// where that value is exact: k = 0 or q = 1 (1) and k = 1 (q). The general
// model's laws take bounds sum |a_j| q_j^k once per phase (forcing.hpp), and
// long double powl costs as much as a phase's rows on the fast path.
#pragma once

#include <cmath>

namespace frictionref::detail {

template <class Work>
Work integer_power(const Work& q, int k) {
  if (k == 0 || q == 1) return Work(1);
  if (k == 1) return q;
  using std::pow;
  return Work(pow(q, k));
}

}  // namespace frictionref::detail
