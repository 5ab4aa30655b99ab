// The closed form of a rigid block's slip on one segment of a ground motion
// record (docs/theory.md 9.2): the net acceleration is linear in time there,
// so from the piece's start (x_a, v_a)
//
//   v(h) = v_a + A h + J h^2 / 2,   x(h) = x_a + v_a h + A h^2 / 2 + J h^3 / 6,
//
// h the time since the start, A = g(start) - s mu the acceleration there
// (mu = R / m, s the slip direction), J the jerk (the slope of g per unit of
// time). A stop is a root of the quadratic v; the piece splits at the vertex
// h* = -A / J into two monotone halves, so each holds at most one root and
// the first one is bracketed without any sampling (theory.md 9.3).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace frictionref::detail {

template <class Work>
struct SlipPiece {
  Work x;  // at the piece's start
  Work v;
  Work acceleration;  // A
  Work jerk;          // J

  Work velocity_at(const Work& h) const { return v + h * (acceleration + h * jerk / Work(2)); }
  Work position_at(const Work& h) const {
    return x + h * (v + h * (acceleration / Work(2) + h * jerk / Work(6)));
  }
  Work acceleration_at(const Work& h) const { return acceleration + jerk * h; }

  // The first h in (0, length] where s v reaches 0, s v being > 0 just
  // after the start (or v = 0 there and s A > 0, or A = 0 and s J > 0);
  // 0 from rest without either (the slip cannot move); negative if there is
  // none. `calls` counts velocity evaluations.
  Work first_stop(int s, const Work& length, std::uint64_t& calls) const {
    using std::fabs;
    using std::sqrt;
    // From rest, a slip moves only if s A > 0 or (A = 0 and) s J > 0; a
    // start that rounding left without either stops at once (root() below
    // needs s v > 0 just after its bracket's start: without it, Newton
    // walked half the piece towards 0 and the block slid 850 m backwards in a
    // forward slip, found by fuzzing).
    if (v == 0 && !(s * acceleration > 0) && !(s * jerk > 0)) return 0;
    const Work sv_end = s * velocity_at(length);
    ++calls;
    // The vertex of v, where the piece splits into two monotone halves.
    // Only where A and J have opposite signs is it ahead (h* > 0): the
    // division is skipped elsewhere, with the same outcome.
    Work vertex = -1;
    if ((acceleration > 0 && jerk < 0) || (acceleration < 0 && jerk > 0))
      vertex = -acceleration / jerk;
    if (vertex > 0 && vertex < length) {
      const Work sv_vertex = s * velocity_at(vertex);
      ++calls;
      if (sv_vertex <= 0) return root(s, Work(0), vertex, calls);
      if (sv_end <= 0) return root(s, vertex, length, calls);
      return -1;
    }
    if (sv_end <= 0) return root(s, Work(0), length, calls);
    return -1;
  }

 private:
  // The root of v in (lo, hi], where s v is monotone, > 0 just after lo and
  // <= 0 at hi: the stable closed form of the quadratic, then Newton steps
  // kept inside the bracket.
  Work root(int s, const Work& lo, const Work& hi, std::uint64_t& calls) const {
    using std::fabs;
    using std::sqrt;
    Work h;
    const Work a = jerk / Work(2), b = acceleration, c = v;
    if (c == 0) {
      // From rest (a breakaway or a reversal): the other root of h (a h + b).
      h = a != 0 ? -b / a : hi;
    } else if (a == 0) {
      h = -c / b;
    } else {
      const Work disc = b * b - Work(4) * a * c;
      if (disc <= 0) {
        h = -b / (Work(2) * a);  // a touch: the vertex
      } else {
        const Work q = -(b + (b >= 0 ? sqrt(disc) : -sqrt(disc))) / Work(2);
        const Work r1 = q / a, r2 = c / q;
        // The root inside the bracket (the other lies outside it).
        const bool r1_in = r1 > lo && r1 <= hi, r2_in = r2 > lo && r2 <= hi;
        h = r1_in && r2_in ? (r1 < r2 ? r1 : r2) : r1_in ? r1 : r2_in ? r2 : hi;
      }
    }
    if (!(h > lo)) h = lo + (hi - lo) / Work(2);
    if (h > hi) h = hi;
    // Newton on v inside [lo, hi] (where s v is monotone): at most a few steps.
    Work low = lo, high = hi;
    for (int step = 0; step < 4; ++step) {
      const Work f = s * velocity_at(h);
      ++calls;
      if (f == 0) break;
      if (f > 0)
        low = h;
      else
        high = h;
      const Work df = s * acceleration_at(h);
      Work next = df != 0 ? h - f / df : (low + high) / Work(2);
      // Converged before the bracket test: a Newton step below an ulp rounds
      // next to h itself, which the test (h is then an end of the bracket)
      // would replace by a bisection away from the root (a stop 6.5e-5 s
      // late, found by checking the general family against these laws).
      if (fabs(next - h) <= fabs(h) * Work(4) * std::numeric_limits<Work>::epsilon()) {
        if (next > low && next <= high) h = next;
        break;
      }
      if (!(next > low && next <= high)) next = (low + high) / Work(2);
      h = next;
    }
    return h;
  }
};

}  // namespace frictionref::detail
