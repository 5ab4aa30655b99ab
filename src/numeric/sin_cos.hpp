// sin and cos of one argument together, in the engine's work type.
//
// For long double (the work type of the double engine) glibc's sinl/cosl cost
// about 15 std::cos calls each (x87 polynomials, and a slow argument
// reduction beyond a few radians); the event loop makes one or two such
// evaluations per event, so they decided its speed. sin_cos(long double) does
// the same job to the same accuracy (a few ulps of long double) for the price
// of about one double cos: a Cody-Waite reduction to the nearest multiple of
// pi/128, a 256-entry table of sin and cos there (computed once in 50-digit
// arithmetic), and the sum formulas with short Taylor corrections
// (docs/benchmarks.md; tested against 50 digits in tests/test_sin_cos.cpp).
// Every other type uses its own sin and cos.
#pragma once

#include <cmath>

namespace frictionref {

template <class T>
struct SinCos {
  T sin;
  T cos;
};

// Long double: table-based, |error| <= 4 ulps of long double in [-1, 1] for
// |x| <= 2^38 (beyond, and for non-finite x, it calls sinl and cosl).
SinCos<long double> sin_cos(long double x);

template <class T>
SinCos<T> sin_cos(const T& x) {
  using std::cos;
  using std::sin;
  return {T(sin(x)), T(cos(x))};
}

}  // namespace frictionref
