#include "reference_motion.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <stdexcept>

namespace frictionref::cli_test {
namespace {

using Real = boost::multiprecision::cpp_bin_float_50;

const Real pi = boost::math::constants::pi<Real>();

int sign_of(const std::string& kind) { return kind == "slip+" ? 1 : kind == "slip-" ? -1 : 0; }

long double to_long(const Real& value) { return value.convert_to<long double>(); }

}  // namespace

Real ReferenceMotion::velocity(int sign, const Real& a, const Real& va, const Real& t) const {
  return va + cos(a) - cos(t) - sign * lambda_ * (t - a);
}

Real ReferenceMotion::position(int sign, const Real& a, const Real& xa, const Real& va,
                               const Real& t) const {
  const Real h = t - a;
  return xa + (va + cos(a)) * h - (sin(t) - sin(a)) - sign * lambda_ * h * h / 2;
}

// The inputs are doubles passed as long double: exact in 50 digits.
ReferenceMotion::ReferenceMotion(long double lambda, long double v0, long double t_end_in)
    : lambda_(lambda) {
  const Real t_end = t_end_in;
  Real t = 0, x = 0, v = v0;
  std::string kind = v0 > 0 ? "slip+" : v0 < 0 ? "slip-" : "stick";
  while (t < t_end) {
    Real phase_end = t_end, x_end = x, v_end = v;
    std::string next_kind;
    if (kind == "stick") {
      // Breakaways: sin crosses +lambda upwards or -lambda downwards.
      if (lambda_ < 1) {
        const Real base = asin(lambda_);
        for (Real k = floor(t / (2 * pi)) - 1; k * 2 * pi < t_end + 2 * pi; k += 1) {
          const Real forward = base + 2 * pi * k;
          const Real backward = pi + base + 2 * pi * k;
          if (forward > t && forward < phase_end) {
            phase_end = forward;
            next_kind = "slip+";
          }
          if (backward > t && backward < phase_end) {
            phase_end = backward;
            next_kind = "slip-";
          }
        }
      }
    } else {
      // Scan for the first sign change of s v, then bisect to the last digit.
      const int s = sign_of(kind);
      const Real step = Real(1) / 64;
      Real lo = t, hi = t;
      bool stopped = false;
      while (hi < t_end) {
        lo = hi;
        hi = std::min(t_end, Real(hi + step));
        if (s * velocity(s, t, v, hi) <= 0) {
          stopped = true;
          break;
        }
      }
      if (stopped) {
        for (int i = 0; i < 400; ++i) {
          const Real mid = (lo + hi) / 2;
          if (mid == lo || mid == hi) break;
          (s * velocity(s, t, v, mid) > 0 ? lo : hi) = mid;
        }
        phase_end = hi;
        v_end = 0;
        const Real force = sin(phase_end);
        next_kind = force > lambda_ ? "slip+" : force < -lambda_ ? "slip-" : "stick";
      } else {
        v_end = velocity(s, t, v, t_end);
      }
      x_end = position(s, t, x, v, phase_end);
    }
    phases_.push_back(RefPhase{kind, to_long(t), to_long(phase_end), to_long(x), to_long(x_end),
                               to_long(v), to_long(v_end)});
    exact_.push_back(ExactPhase{sign_of(kind), t, x, v});
    t = phase_end;
    x = x_end;
    v = 0;
    kind = next_kind;
  }
}

RefState ReferenceMotion::state(const RefPhase& phase, long double t_in) const {
  // One of phases(): its 50-digit start; a copy: its long double start.
  ExactPhase exact{sign_of(phase.kind), phase.t_begin, phase.x_begin, phase.v_begin};
  for (std::size_t i = 0; i < phases_.size(); ++i)
    if (&phases_[i] == &phase) exact = exact_[i];
  const int s = exact.sign;
  if (s == 0) return {phase.x_begin, 0, 0, phase.kind};
  const Real t = t_in;
  return {to_long(position(s, exact.t_begin, exact.x_begin, exact.v_begin, t)),
          to_long(velocity(s, exact.t_begin, exact.v_begin, t)), to_long(sin(t) - s * lambda_),
          phase.kind};
}

const RefPhase& ReferenceMotion::phase_at(long double t) const {
  for (const RefPhase& phase : phases_) {
    if (phase.t_begin <= t && t < phase.t_end) return phase;
  }
  if (!phases_.empty() && t == phases_.back().t_end) return phases_.back();
  throw std::out_of_range("time outside the reference solution");
}

std::size_t ReferenceMotion::count(const std::string& kind) const {
  std::size_t n = 0;
  for (const RefPhase& phase : phases_) n += phase.kind == kind;
  return n;
}

}  // namespace frictionref::cli_test
