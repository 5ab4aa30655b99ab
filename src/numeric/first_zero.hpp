// The first zero of a smooth function on an interval, found so that none can
// be missed (docs/theory.md 7.4): the event search of the general phase laws.
//
// The function f (s v during a slip, Rs^2 - N^2 during a stick) is known in
// closed form with its first two derivatives at any point, each with a bound
// of its rounding error, and the law gives a rigorous bound M of |f'''| over
// any interval [a, a + h] (from the derivatives of the closed form, not from
// samples). By Taylor's theorem with the Lagrange remainder, on [a, a + h]
//
//   f(a + u) >= f(a) + f'(a) u + f''(a) u^2 / 2 - M u^3 / 6,
//   f'(a + u) lies within f'(a) + f''(a) u -+ M u^2 / 2,
//   f''(a + u) lies within f''(a) -+ M u.
//
// Each step from a point a where f > 0 proves one of:
//   * exclusion: the cubic lower bound stays positive on [a, a + h] (its
//     minimum is at an end or at its one interior local minimum, in closed
//     form), so f has no zero there;
//   * monotonicity: f' < 0 (or > 0) throughout, so a sign test at a + h
//     decides, and a sign change brackets the one zero;
//   * one extremum: f'' keeps its sign, so f' has at most one zero; it is
//     found by bracketing and f there decides (a tangential zero is found
//     here: f reaches 0 at an extremum without changing sign);
// and otherwise halves h. Steps below the time resolution are sign-tested
// (the engine resolves nothing shorter). The result is a bracket on which f
// is decreasing with f(lo) > 0 >= f(hi), for the root solver.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace frictionref::detail {

template <class Work>
struct Jet {
  Work f = 0, d1 = 0, d2 = 0;   // f, f', f'' at the point
  Work e0 = 0, e1 = 0, e2 = 0;  // bounds of their rounding errors
  Work tail = 0, tail2 = 0;     // the law's own data for its third-derivative bound
};

template <class Work>
struct ZeroBracket {
  bool found = false;      // false: f > 0 on the whole interval
  Work lo = 0;             // f(lo) > 0 (or lo = hi: a zero within the resolution of lo)
  Work hi = 0;             // f(hi) <= 0, f decreasing on [lo, hi]; or, after a step at the
                           // resolution, f(hi) within its rounding error of 0
  Jet<Work> at_lo, at_hi;  // the jets there, for the root solver's first guess
};

// Thrown when the search makes no progress (a function at the level of its
// own rounding noise over a long stretch); the engine reports it as a
// numerical failure rather than loop.
struct SearchStalled {};

// Probe concept:
//   Jet<Work> jet(const Work& tau)                                  one evaluation
//   Work third_bound(const Work& tau, const Jet<Work>& at, const Work& h)
//       >= sup |f'''| over [tau, tau + h]
//   Work derivative(const Work& tau), Work second_derivative(const Work& tau)
//       (for the extremum's root)
//   RootResult<Work> decreasing_root(F, DF, lo, hi)                 the scalar type's solver
template <class Work>
class FirstZeroSearch {
 public:
  // Searches (a, end] from a with f(a) >= 0 (jet `at_a`); zeros within
  // `blind` of a are not looked for (a slip that starts at rest has f(a) = 0:
  // its first `blind` is below the resolution). `resolution` is the time
  // resolution. Two caps bound the work: `max_steps`, which the caller sizes
  // to the oscillations f can make on [a, end] (a slip of a stiff spring
  // rings through 10^4 natural periods at ~10 steps each), and a fixed cap on
  // steps at the resolution, which make no provable progress (the stall).
  // `aim`, where given, is a point the caller expects the zero just before
  // (a predicted stop, a little late): a step that would pass over it ends
  // there instead, so that a bracket closed by that step ends at it and the
  // caller's polish starts from a point already evaluated. Only a step's
  // length changes; what each step proves does not.
  static constexpr std::int64_t kDefaultMaxSteps = 100000;
  static constexpr std::int64_t kMaxStepsAtResolution = 100000;

  template <class Probe>
  static ZeroBracket<Work> run(Probe& probe, const Work& a, const Jet<Work>& at_a, const Work& end,
                               const Work& blind, const Work& resolution,
                               std::int64_t max_steps = kDefaultMaxSteps,
                               const Work& aim = std::numeric_limits<Work>::quiet_NaN()) {
    using std::fabs;
    Work cur = a;
    Jet<Work> j = at_a;
    std::int64_t steps = 0, steps_at_resolution = 0;
    if (blind > 0) {  // no zero is looked for before a + blind: start there
      Work b = a + blind < end ? Work(a + blind) : end;
      Jet<Work> jb = probe.jet(b);
      // Below zero by more than its rounding at the stretch's end: the zero
      // is resolvable inside the stretch (the noise that set its length has
      // decayed); a shorter stretch, down to the resolution.
      while (jb.f < -2 * jb.e0 && b - a > 2 * resolution) {
        b = a + (b - a) / 2;
        jb = probe.jet(b);
      }
      if (!(jb.f > 0)) return {true, a, b, j, jb};
      cur = b;
      j = jb;
    }
    // A first step where the cubic term of the Taylor bound is comparable to
    // the value (halving from the whole interval would cost a dozen tries).
    Work h = end - cur;
    {
      using std::cbrt;
      const Work m = probe.third_bound(cur, j, h);
      const Work scale = fabs(j.f) + fabs(j.d1) + fabs(j.d2);
      if (m > 0 && scale > 0) {
        const Work guess = 2 * cbrt(6 * scale / m);
        if (guess < h) h = guess;
      }
    }
    const Work first = cur;
    while (cur < end) {
      // A point stepped to where f is within twice its rounding of zero is a
      // zero, as at the resolution's sign test below: f cannot be told from
      // 0 there. (A slip whose velocity is rounding noise all along, f just
      // above e0, was otherwise crawled by proven steps of 1e-11 towards a
      // horizon a hundred time units away, until the step cap: found by a
      // sweep of equilibria 1e18 from 0.)
      if (cur > first && counts_as_zero(j)) return {true, cur, cur, j, j};
      if (++steps > max_steps) throw SearchStalled{};
      if (h > end - cur) h = end - cur;
      // (Never a step to the aim shorter than the resolution: the branch at
      // the resolution below would lengthen it again, for ever.)
      const bool aimed = aim - cur >= resolution && aim < cur + h && aim < end;
      if (aimed) h = aim - cur;
      const Work b = aimed ? aim : h == end - cur ? end : cur + h;
      const Work m = probe.third_bound(cur, j, h);
      if (stays_positive(j, m, Work(0), h)) {
        cur = b;
        if (cur < end) j = probe.jet(cur);
        h *= 2;
        continue;
      }
      if (slope_below_zero(j, m, h)) {  // f decreasing on [cur, b]
        const Jet<Work> jb = probe.jet(b);
        if (!(jb.f > 0)) return {true, cur, b, j, jb};
        // Still positive: no zero up to b. Longer steps next (a slow decay
        // towards zero, as an overdamped approach to equilibrium, would
        // otherwise be walked at a fixed step until the step cap).
        cur = b;
        j = jb;
        h *= 2;
        continue;
      }
      if (slope_above_zero(j, m, h)) {  // f increasing: no zero after f(cur) >= 0
        cur = b;
        if (cur < end) j = probe.jet(cur);
        h *= 2;
        continue;
      }
      if (fabs(j.d2) - j.e2 > m * h) {  // f' monotone: at most one extremum
        const Jet<Work> jb = probe.jet(b);
        const bool falls_first = j.d1 < 0;
        if ((j.d1 < 0) == (jb.d1 < 0)) {  // no extremum inside: f monotone
          if (falls_first && !(jb.f > 0)) return {true, cur, b, j, jb};
        } else {
          const Work te = extremum(probe, cur, b, falls_first);
          const Jet<Work> je = probe.jet(te);
          if (falls_first) {  // minimum at te
            // Within rounding of 0 there: a tangency, taken at the minimum
            // itself (a crossing in the noise would be up to sqrt(e0 / f'')
            // early, where the force has not turned yet).
            if (fabs(je.f) <= je.e0) return {true, te, te, je, je};
            if (!(je.f > 0)) return {true, cur, te, j, je};
          } else if (!(jb.f > 0)) {  // maximum at te, then falling to b
            if (je.f > 0) return {true, te, b, je, jb};
            // f <= 0 at the computed maximum: te was rounded past it into a
            // fall so steep that one ulp of te holds the zero (a record's
            // ramp of 3e222 per unit time: found by fuzzing). The zero is in
            // (cur, te], after f(cur) > 0: that is the bracket (f(lo) > 0, as
            // the caller expects of every bracket but the blind stretch's).
            return {true, cur, te, j, je};
          }
        }
        cur = b;
        j = jb;
        h *= 2;
        continue;
      }
      if (h <= resolution) {
        // (Never a step below the resolution, save the last one to `end`:
        // b must move past cur.)
        if (h < resolution && h < end - cur) {
          h = resolution;
          continue;
        }
        if (++steps_at_resolution > kMaxStepsAtResolution) throw SearchStalled{};
        // Nothing provable at the resolution: a sign test, where a value
        // within twice its rounding error of zero counts as zero (f hovering
        // at the level of its noise would otherwise be crossed a resolution
        // at a time, for ever when its slope is below its own rounding: a
        // stall found by fuzzing). Past it, f - e0 > e0 makes the next
        // exclusion step about e0 / |f'| long. The bracket's hi may then
        // have f > 0.
        const Jet<Work> jb = probe.jet(b);
        if (counts_as_zero(jb)) {
          // Falling into the noise while convex: a tangency (v grazing 0)
          // or a pair of zeros round a minimum. The minimum decides, not the
          // first point in the noise (up to sqrt(e0 / f'') early, where the
          // force has not yet turned): find it where f' changes sign.
          if (jb.f > 0 && j.d1 < 0 && j.d2 - j.e2 > 0) {
            const Work reach = cur + 2 * (-j.d1 / j.d2) + resolution;
            const Work b2 = reach < end ? reach : end;
            const Jet<Work> j2 = probe.jet(b2);
            if (j2.d1 - j2.e1 > 0) {
              const Work te = extremum(probe, cur, b2, true);
              const Jet<Work> je = probe.jet(te);
              if (fabs(je.f) <= je.e0) return {true, te, te, je, je};
              if (je.f < 0) return {true, cur, te, j, je};
            }
          }
          return {true, cur, b, j, jb};
        }
        cur = b;
        j = jb;
        continue;
      }
      h /= 2;
    }
    return {};
  }

  // The sign test's threshold, wherever the search evaluates f: a value
  // within twice its rounding error of zero counts as zero.
  static bool counts_as_zero(const Jet<Work>& j) { return !(j.f > 2 * j.e0); }

  // min over [u0, u1] of the cubic lower bound of f(a + u) is > 0.
  static bool stays_positive(const Jet<Work>& j, const Work& m, const Work& u0, const Work& u1) {
    using std::fabs;
    using std::sqrt;
    const Work c0 = j.f - j.e0;
    const Work c1 = j.d1 - j.e1;
    const Work c2 = j.d2 - j.e2;
    const auto p = [&](const Work& u) { return c0 + u * (c1 + u * (c2 / 2 - m * u / 6)); };
    // Rounding of p itself.
    const Work margin = 8 * std::numeric_limits<Work>::epsilon() *
                        (fabs(c0) + fabs(c1) * u1 + fabs(c2) * u1 * u1 / 2 + m * u1 * u1 * u1 / 6);
    if (!(p(u0) > margin) || !(p(u1) > margin)) return false;
    // Interior local minimum: the smaller root of p'(u) = c1 + c2 u - m u^2 / 2
    // (m > 0), or -c1 / c2 when m = 0 and p is convex.
    Work r;
    if (m > 0) {
      const Work disc = c2 * c2 + 2 * m * c1;
      if (disc < 0) return true;  // p' < 0 throughout: p falls, the ends decide
      const Work root = sqrt(disc);
      r = c2 < 0 ? Work((c2 - root) / m) : Work(-2 * c1 / (c2 + root));
    } else {
      if (!(c2 > 0)) return true;
      r = -c1 / c2;
    }
    if (!(r > u0 && r < u1)) return true;
    return p(r) > margin;
  }

  // f' < 0 on [a, a + h]: its upper bound (convex in u) is < 0 at both ends.
  static bool slope_below_zero(const Jet<Work>& j, const Work& m, const Work& h) {
    const Work c1 = j.d1 + j.e1;
    const Work c2 = j.d2 + j.e2;
    return c1 < 0 && c1 + h * (c2 + m * h / 2) < 0;
  }

  // f' > 0 on [a, a + h]: its lower bound (concave in u) is > 0 at both ends.
  static bool slope_above_zero(const Jet<Work>& j, const Work& m, const Work& h) {
    const Work c1 = j.d1 - j.e1;
    const Work c2 = j.d2 - j.e2;
    return c1 > 0 && c1 + h * (c2 - m * h / 2) > 0;
  }

 private:
  // The zero of f' on [lo, hi], where it changes sign once (rising if
  // f falls first).
  template <class Probe>
  static Work extremum(Probe& probe, const Work& lo, const Work& hi, bool falls_first) {
    const Work s = falls_first ? Work(-1) : Work(1);  // s f' decreasing
    const auto g = [&](const Work& tau) { return s * probe.derivative(tau); };
    const auto dg = [&](const Work& tau) { return s * probe.second_derivative(tau); };
    return probe.decreasing_root(g, dg, lo, hi).root;
  }
};

}  // namespace frictionref::detail
