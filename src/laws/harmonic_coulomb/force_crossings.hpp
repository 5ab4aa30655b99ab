// Where the force B sin(tau) crosses +-R, in closed form (docs/theory.md section 3).
//
// These times do two jobs: they split a slip into pieces on which the velocity
// is monotone (so each piece holds at most one stop, bracketed by a sign test),
// and they are the breakaway times that end a stick.
//
// With lambda = R / B < 1 and alpha = asin(lambda):
//   forward breakaway   alpha + 2 pi k        (sin tau rises through +lambda)
//   backward breakaway  pi + alpha + 2 pi k   (sin tau falls through -lambda)
// For a slip of sign s, d(s v)/d tau = s b sin tau - r vanishes where
// sin tau = s lambda: minima of s*v at the breakaway times in direction s,
// maxima half a period of the force minus 2 alpha later, at
// pi - alpha + 2 pi k (s = +1) and 2 pi - alpha + 2 pi k (s = -1).
// With lambda >= 1 (or B = 0) s*v is monotone and nothing ever breaks away.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace frictionref::detail {

template <class Work>
class ForceCrossings {
 public:
  // b = B / (m w) >= 0, r = R / (m w) >= 0, velocity units.
  ForceCrossings(const Work& b, const Work& r) : crosses_(b > 0 && r < b) {
    using std::asin;
    if (crosses_) alpha_ = asin(r / b);
  }
  // Rebuilt from a stored alpha (the engine keeps alpha, not this object,
  // so its public header does not depend on this private one).
  ForceCrossings(bool crosses, const Work& alpha) : crosses_(crosses), alpha_(alpha) {}

  const Work& alpha() const { return alpha_; }

  // True when lambda < 1: breakaways exist and slips have critical times.
  bool crosses() const { return crosses_; }

  // The earliest breakaway time >= tau (exact grid: base + 2 pi k).
  // Sets `direction` to +1 or -1. Requires crosses().
  Work next_breakaway(const Work& tau, int& direction) const {
    const Work k = periods_in(tau);
    const Work forward = next_at_or_after(alpha_, tau, k);
    const Work backward = next_at_or_after(pi() + alpha_, tau, k);
    direction = forward <= backward ? 1 : -1;
    return forward <= backward ? forward : backward;
  }

  // What the force does within `tolerance` of tau: +1 / -1 if a forward /
  // backward breakaway time is that close, 0 if the force re-enters the band
  // |F| <= R there (pi - alpha + 2 pi k falling through +R, 2 pi - alpha +
  // 2 pi k rising through -R), 2 if no crossing is that close. Breakaways win
  // ties (lambda -> 0, where the band has no width). Requires crosses().
  int crossing_near(const Work& tau, const Work& tolerance) const {
    int direction = 0;
    if (next_breakaway(tau - tolerance, direction) - tau <= tolerance) return direction;
    const Work from = tau - tolerance;
    const Work k = periods_in(from);
    const Work release_forward = next_at_or_after(pi() - alpha_, from, k);
    const Work release_backward = next_at_or_after(two_pi() - alpha_, from, k);
    if (release_forward - tau <= tolerance || release_backward - tau <= tolerance) return 0;
    return 2;
  }

  // The earliest critical time of a slip of sign s strictly after tau.
  // Requires crosses().
  Work next_critical(int s, const Work& tau) const { return next_critical_point(s, tau).tau; }

  // The same, saying whether s v has a minimum there (a breakaway time in
  // direction s: sin tau = s lambda, cos tau = s cos alpha) or a maximum
  // (sin tau = s lambda, cos tau = -s cos alpha).
  struct Critical {
    Work tau;
    bool minimum;
  };
  Critical next_critical_point(int s, const Work& tau) const {
    const Work shift = s > 0 ? Work(0) : pi();
    const Work k = periods_in(tau);
    const Work minimum = next_after(shift + alpha_, tau, k);
    const Work maximum = next_after(shift + pi() - alpha_, tau, k);
    return minimum < maximum ? Critical{minimum, true} : Critical{maximum, false};
  }

  // x / 2 pi rounded to an integer, give or take one: one estimate serves
  // every base in [0, 2 pi] (the exact k is then within 2 of it). Taken with
  // llrint, as an x87 floor or ceil costs as much as a cos call, and these
  // run several times per event.
  static Work periods_in(const Work& x) {
    using std::llrint;
    const Work inverse_two_pi = boost::math::constants::one_div_two_pi<Work>();
    return Work(llrint(x * inverse_two_pi));
  }

 private:
  static Work pi() { return boost::math::constants::pi<Work>(); }
  static Work two_pi() { return boost::math::constants::two_pi<Work>(); }

  // Smallest base + 2 pi k >= tau, for 0 <= base <= 2 pi, from the estimate
  // k0 = periods_in(tau) (the loops make k exact; each runs at most twice).
  static Work next_at_or_after(const Work& base, const Work& tau, Work k) {
    while (base + two_pi() * (k - 1) >= tau) k -= 1;
    while (base + two_pi() * k < tau) k += 1;
    return base + two_pi() * k;
  }
  // Smallest base + 2 pi k > tau, likewise.
  static Work next_after(const Work& base, const Work& tau, Work k) {
    while (base + two_pi() * (k - 1) > tau) k -= 1;
    while (base + two_pi() * k <= tau) k += 1;
    return base + two_pi() * k;
  }

  bool crosses_;
  Work alpha_ = 0;
};

}  // namespace frictionref::detail
