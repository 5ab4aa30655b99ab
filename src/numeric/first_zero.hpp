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
//   * on a step to the caller's aim only: monotonicity from both ends, f'
//     bounded above by the expansion from a on [a, s] and by the one from
//     a + h backwards on [s, a + h] (falls_throughout);
// and otherwise shortens h: to the longest step that exclusion or f's slope
// proves with the same bounds, if over h/2, else to h/2. Steps below the
// time resolution are sign-tested (the engine resolves nothing shorter). The
// result is a bracket on which f is decreasing with f(lo) > 0 >= f(hi), for
// the root solver.
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
  Work first_step = 0;     // the length of the search's first proven step (0: none)
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
  // caller's polish starts from a point already evaluated. `first_step`,
  // where positive, is the length to try first (the first proven step of
  // the search the caller expects this one to repeat) instead of a guess
  // from the bounds. Only a step's length changes; what each step proves
  // does not.
  static constexpr std::int64_t kDefaultMaxSteps = 100000;
  static constexpr std::int64_t kMaxStepsAtResolution = 100000;

  template <class Probe>
  static ZeroBracket<Work> run(Probe& probe, const Work& a, const Jet<Work>& at_a, const Work& end,
                               const Work& blind, const Work& resolution,
                               std::int64_t max_steps = kDefaultMaxSteps,
                               const Work& aim = std::numeric_limits<Work>::quiet_NaN(),
                               const Work& first_step = 0) {
    Work first_proven = 0;
    ZeroBracket<Work> result =
        search(probe, a, at_a, end, blind, resolution, max_steps, aim, first_step, first_proven);
    result.first_step = first_proven;
    return result;
  }

 private:
  template <class Probe>
  static ZeroBracket<Work> search(Probe& probe, const Work& a, const Jet<Work>& at_a,
                                  const Work& end, const Work& blind, const Work& resolution,
                                  std::int64_t max_steps, const Work& aim, const Work& first_step,
                                  Work& first_proven) {
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
    // The bound may grow with the step (a law's bound from the state at cur
    // alone): over a long search interval it is guessed again from the bound
    // over the first guess.
    Work h = end - cur;
    const bool hinted = first_step > 0 && first_step < h;
    if (hinted) {
      h = first_step;
    } else {
      using std::cbrt;
      const Work scale = fabs(j.f) + fabs(j.d1) + fabs(j.d2);
      const Work m = probe.third_bound(cur, j, h);
      if (m > 0 && scale > 0) {
        Work guess = 2 * cbrt(6 * scale / m);
        if (guess < h) {
          const Work m_guess = probe.third_bound(cur, j, guess);
          if (m_guess > 0 && m_guess < m) guess = 2 * cbrt(6 * scale / m_guess);
          if (guess < h) h = guess;
        }
      }
    }
    const Work first = cur;
    // The first proven step, for the caller to pass on. A hinted step that
    // one 1/8 longer would also have been proven by is not passed on: the
    // hint was short (a transient's), and passed on it would stay short.
    const auto note_first = [&](const Work& step, const Jet<Work>& at_first) {
      if (!(cur == first && first_proven == 0)) return;
      first_proven = step;
      if (!(hinted && step == first_step)) return;
      const Work longer = step + step / 8;
      if (!(longer < end - first)) return;
      const Work m = probe.third_bound(first, at_first, longer);
      if (stays_positive(at_first, m, Work(0), longer) || slope_above_zero(at_first, m, longer) ||
          slope_below_zero(at_first, m, longer))
        first_proven = 0;
    };
    // The jet at the aim, once evaluated (a failed proof from both ends may
    // evaluate it before the step that closes the bracket there).
    bool have_aim_jet = false;
    Jet<Work> aim_jet;
    const auto jet_at = [&](const Work& t) {
      if (have_aim_jet && t == aim) return aim_jet;
      return probe.jet(t);
    };
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
        note_first(h, j);
        cur = b;
        if (cur < end) j = jet_at(cur);
        h *= 2;
        continue;
      }
      if (slope_below_zero(j, m, h)) {  // f decreasing on [cur, b]
        const Jet<Work> jb = jet_at(b);
        if (!(jb.f > 0)) return {true, cur, b, j, jb};
        // Still positive: no zero up to b. Longer steps next (a slow decay
        // towards zero, as an overdamped approach to equilibrium, would
        // otherwise be walked at a fixed step until the step cap).
        note_first(h, j);
        cur = b;
        j = jb;
        h *= 2;
        continue;
      }
      if (slope_above_zero(j, m, h)) {  // f increasing: no zero after f(cur) >= 0
        note_first(h, j);
        cur = b;
        if (cur < end) j = jet_at(cur);
        h *= 2;
        continue;
      }
      if (fabs(j.d2) - j.e2 > m * h) {  // f' monotone: at most one extremum
        const Jet<Work> jb = jet_at(b);
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
        note_first(h, j);
        cur = b;
        j = jb;
        h *= 2;
        continue;
      }
      // A step to the aim that nothing above proves, from a point where f
      // falls: f' may still be proven negative throughout from both ends
      // (in a steady state: from just past f's maximum to the predicted
      // stop, a step the expansion from its start alone cannot take).
      if (aimed && j.d1 + j.e1 < 0) {
        if (!have_aim_jet) {
          aim_jet = probe.jet(aim);
          have_aim_jet = true;
        }
        if (falls_throughout(j, aim_jet, m, h)) {
          if (!(aim_jet.f > 0)) return {true, cur, b, j, aim_jet};
          note_first(h, j);
          cur = b;
          j = aim_jet;
          h *= 2;
          continue;
        }
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
        const Jet<Work> jb = jet_at(b);
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
      h = shortened(probe, cur, j, h, m);
    }
    return {};
  }

 public:
  // The sign test's threshold, wherever the search evaluates f: a value
  // within twice its rounding error of zero counts as zero.
  static bool counts_as_zero(const Jet<Work>& j) { return !(j.f > 2 * j.e0); }

  // The cubic lower bound of f(a + u) from the jet at a and m >= sup |f'''|:
  // p(u) = c0 + c1 u + c2 u^2 / 2 - m u^3 / 6, each c_k the jet's value less
  // its rounding bound. (stays_positive tests it; shortened finds its root.)
  struct LowerCubic {
    Work c0, c1, c2, m;
    LowerCubic(const Jet<Work>& j, const Work& bound)
        : c0(j.f - j.e0), c1(j.d1 - j.e1), c2(j.d2 - j.e2), m(bound) {}
    Work operator()(const Work& u) const { return c0 + u * (c1 + u * (c2 / 2 - m * u / 6)); }
    Work slope(const Work& u) const { return c1 + u * (c2 - m * u / 2); }
  };

  // min over [u0, u1] of the cubic lower bound of f(a + u) is > 0.
  static bool stays_positive(const Jet<Work>& j, const Work& m, const Work& u0, const Work& u1) {
    using std::fabs;
    using std::sqrt;
    const LowerCubic p(j, m);
    const Work &c0 = p.c0, &c1 = p.c1, &c2 = p.c2;
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

  // f' < 0 on [a, b], h = b - a, from the jets at both ends and m >= sup
  // |f'''| on [a, b]. By Taylor from either end, f' lies below
  //   U_a(u) = (f'(a) + e1) + (f''(a) + e2) u + m u^2 / 2        (u = t - a),
  //   U_b(w) = (f'(b) + e1) - (f''(b) - e2) w + m w^2 / 2        (w = b - t);
  // both are convex, so U_a < 0 on [0, s] and U_b < 0 on [0, w >= h - s] follow
  // from their values at the ends of those ranges. s is chosen between where
  // U_b can end (h - its root) and where U_a does (its root); only the four
  // checked values, not the roots, prove anything.
  static bool falls_throughout(const Jet<Work>& ja, const Jet<Work>& jb, const Work& m,
                               const Work& h) {
    using std::fabs;
    const Work a1 = ja.d1 + ja.e1, a2 = ja.d2 + ja.e2;
    const Work b1 = jb.d1 + jb.e1, b2 = -(jb.d2 - jb.e2);
    if (!(a1 < 0 && b1 < 0 && h > 0)) return false;
    const Work ra = negative_up_to(a1, a2, m), rb = negative_up_to(b1, b2, m);
    if (!(ra + rb > h)) return false;
    const Work from = h - rb > 0 ? Work(h - rb) : Work(0), to = ra < h ? ra : h;
    const Work eps = std::numeric_limits<Work>::epsilon();
    // (w a little over h - s: the two ranges overlap despite rounding.)
    const Work s = (from + to) / 2, w = (h - s) + 4 * eps * h;
    const Work ua = a1 + s * (a2 + m * s / 2), ub = b1 + w * (b2 + m * w / 2);
    // Rounding of the two quadratics, as in stays_positive.
    const Work margin_a = 8 * eps * (fabs(a1) + fabs(a2) * s + m * s * s / 2);
    const Work margin_b = 8 * eps * (fabs(b1) + fabs(b2) * w + m * w * w / 2);
    return ua < -margin_a && ub < -margin_b;
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
  // The first u > 0 where c1 + c2 u + m u^2 / 2 reaches 0 (c1 < 0, m >= 0):
  // its positive root, in the form without cancellation; infinite if none.
  static Work negative_up_to(const Work& c1, const Work& c2, const Work& m) {
    using std::sqrt;
    if (!(m > 0)) return c2 > 0 ? Work(-c1 / c2) : std::numeric_limits<Work>::infinity();
    const Work root = sqrt(c2 * c2 - 2 * m * c1);
    return c2 > 0 ? Work(-2 * c1 / (c2 + root)) : Work((root - c2) / m);
  }

  // The next step after one of length h proved nothing, and m the bound on
  // it (valid on any shorter step): the longest step that the bounds at cur
  // prove, by exclusion or by f's slope, if longer than h/2, else h/2. The
  // candidates are where each test's polynomial with this m reaches 0: the
  // slope's quadratics in closed form, the exclusion cubic by Newton's
  // method from h (it falls there); each is taken 2^-10 short and checked
  // with its own, smaller, bound, as the step itself will check it. No
  // evaluation of f: in a steady state the step from a slip's start then
  // reaches past the top of f's hump, from where the step to the aim is
  // proven from both ends.
  template <class Probe>
  static Work shortened(Probe& probe, const Work& cur, const Jet<Work>& j, const Work& h,
                        const Work& m) {
    Work longest = h / 2;
    const Work shrink = 1 - Work(0x1p-10);
    const auto consider = [&](const Work& reach,
                              bool (*proves)(const Jet<Work>&, const Work&, const Work&)) {
      const Work step = reach * shrink;
      if (!(step > longest && step < h)) return;
      if (proves(j, probe.third_bound(cur, j, step), step)) longest = step;
    };
    const Work up = j.d1 - j.e1, down = j.d1 + j.e1;
    if (up > 0) consider(negative_up_to(-up, -(j.d2 - j.e2), m), slope_above_zero);
    if (down < 0) consider(negative_up_to(down, j.d2 + j.e2, m), slope_below_zero);
    // The exclusion's cubic, from u = h down.
    const LowerCubic p(j, m);
    if (p.c0 > 0) {
      Work u = h;
      for (int i = 0; i < 8; ++i) {
        const Work value = p(u), slope = p.slope(u);
        if (!(value < 0 && slope < 0)) break;  // past the fall (or at its root)
        u -= value / slope;
      }
      consider(u, [](const Jet<Work>& jet, const Work& bound, const Work& step) {
        return stays_positive(jet, bound, Work(0), step);
      });
    }
    return longest;
  }

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
