#include "reference_motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frictionref::cli_test {
namespace {

const long double pi = 3.141592653589793238462643383279502884L;

int sign_of(const std::string& kind) { return kind == "slip+" ? 1 : kind == "slip-" ? -1 : 0; }

}  // namespace

long double ReferenceMotion::velocity(int sign, long double a, long double va,
                                      long double t) const {
  return va + std::cos(a) - std::cos(t) - sign * lambda_ * (t - a);
}

long double ReferenceMotion::position(int sign, long double a, long double xa, long double va,
                                      long double t) const {
  const long double h = t - a;
  return xa + (va + std::cos(a)) * h - (std::sin(t) - std::sin(a)) - sign * lambda_ * h * h / 2;
}

ReferenceMotion::ReferenceMotion(long double lambda, long double v0, long double t_end)
    : lambda_(lambda) {
  long double t = 0, x = 0, v = v0;
  std::string kind = v0 > 0 ? "slip+" : v0 < 0 ? "slip-" : "stick";
  while (t < t_end) {
    RefPhase phase{kind, t, t_end, x, x, v, v};
    std::string next_kind;
    if (kind == "stick") {
      // Breakaways: sin crosses +lambda upwards or -lambda downwards.
      long double breakaway = t_end;
      if (lambda < 1) {
        const long double base = std::asin(lambda);
        for (long double k = std::floor(t / (2 * pi)) - 1; k * 2 * pi < t_end + 2 * pi; k += 1) {
          const long double forward = base + 2 * pi * k;
          const long double backward = pi + base + 2 * pi * k;
          if (forward > t && forward < breakaway) {
            breakaway = forward;
            next_kind = "slip+";
          }
          if (backward > t && backward < breakaway) {
            breakaway = backward;
            next_kind = "slip-";
          }
        }
      }
      phase.t_end = breakaway;
    } else {
      // Scan for the first sign change of s v, then bisect to the last bit.
      const int s = sign_of(kind);
      const long double step = 1.0L / 64;
      long double lo = t, hi = t;
      bool stopped = false;
      while (hi < t_end) {
        lo = hi;
        hi = std::min(t_end, hi + step);
        if (s * velocity(s, t, v, hi) <= 0) {
          stopped = true;
          break;
        }
      }
      if (stopped) {
        for (int i = 0; i < 200; ++i) {
          const long double mid = (lo + hi) / 2;
          if (mid == lo || mid == hi) break;
          (s * velocity(s, t, v, mid) > 0 ? lo : hi) = mid;
        }
        const long double ts = hi;
        phase.t_end = ts;
        phase.v_end = 0;
        const long double force = std::sin(ts);
        next_kind = force > lambda ? "slip+" : force < -lambda ? "slip-" : "stick";
      } else {
        phase.t_end = t_end;
        phase.v_end = velocity(s, t, v, t_end);
      }
      phase.x_end = position(s, t, x, v, phase.t_end);
    }
    phases_.push_back(phase);
    t = phase.t_end;
    x = phase.x_end;
    v = 0;
    kind = next_kind;
  }
}

RefState ReferenceMotion::state(const RefPhase& phase, long double t) const {
  const int s = sign_of(phase.kind);
  if (s == 0) return {phase.x_begin, 0, 0, phase.kind};
  return {position(s, phase.t_begin, phase.x_begin, phase.v_begin, t),
          velocity(s, phase.t_begin, phase.v_begin, t), std::sin(t) - s * lambda_, phase.kind};
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
