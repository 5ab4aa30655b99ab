// An independent, deliberately simple solution of the seed problem's model
// (m = B = w = 1, x0 = 0, t0 = 0) in 50 decimal digits
// (boost::multiprecision::cpp_bin_float_50), used as the expected values of
// the CLI tests: theory.md's closed forms, slip ends by scanning for a sign
// change of v and bisecting to the last of the 50 digits, breakaways at
// asin(lambda) + 2 pi k and pi + asin(lambda) + 2 pi k. Shares no code with
// the library. The results are handed out in long double (64-bit mantissa:
// 2^-11 ulp of a double), so the tests can hold the binary's printed doubles
// to a few ulps without the reference's own error counting.
#pragma once

#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace frictionref::cli_test {

struct RefPhase {
  std::string kind;  // "stick", "slip+", "slip-"
  long double t_begin, t_end, x_begin, x_end, v_begin, v_end;
};

struct RefState {
  long double x, v, a;
  std::string kind;
};

// |actual - expected| in units of the spacing of doubles at
// max(scale, |expected|): ulp(max(1, |t|)) for a time with scale 1.
inline long double ulps_off(double actual, long double expected, long double scale = 1) {
  const long double at = std::max(scale, std::fabs(expected));
  int exponent = 0;
  std::frexp(at, &exponent);  // 2^(e-1) <= at < 2^e
  const long double ulp = std::ldexp(1.0L, exponent - 53);
  return std::fabs(static_cast<long double>(actual) - expected) / ulp;
}

class ReferenceMotion {
 public:
  ReferenceMotion(long double lambda, long double v0, long double t_end);
  const std::vector<RefPhase>& phases() const { return phases_; }
  // The state at t inside `phase` (closed form); a is the phase's acceleration.
  RefState state(const RefPhase& phase, long double t) const;
  // The phase with t_begin <= t < t_end (the last one also owns t_end).
  const RefPhase& phase_at(long double t) const;
  std::size_t count(const std::string& kind) const;

 private:
  using Real = boost::multiprecision::cpp_bin_float_50;
  // A phase with its ends in 50 digits (phases_[i] is exact_[i] rounded).
  struct ExactPhase {
    int sign;
    Real t_begin, x_begin, v_begin;
  };
  Real velocity(int sign, const Real& a, const Real& va, const Real& t) const;
  Real position(int sign, const Real& a, const Real& xa, const Real& va, const Real& t) const;

  Real lambda_;
  std::vector<RefPhase> phases_;
  std::vector<ExactPhase> exact_;
};

}  // namespace frictionref::cli_test
