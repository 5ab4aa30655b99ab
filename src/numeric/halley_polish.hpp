// The zero of a decreasing function on a bracket by Halley's method with a
// certified stop (docs/theory.md 7.4): the polish of the general laws' event
// times in the double engine, 2 or 3 evaluations per event where GSL Brent +
// Newton take about a dozen.
//
// With |f''| <= M2 and |f'''| <= M3 near the root and slope |f'| there, a
// Halley step from a point at error e leaves an error below
// (K3/6 + K2^2/4) |e|^3, K2 = M2/|f'|, K3 = M3/|f'| (the bound the seed's
// predicted stops use, exact_engine docs 3.5), with e within 1% of the step
// once K2 |step| is small. The step is accepted once that bound is an eighth
// of an ulp of the work type at the root's scale; otherwise the caller falls
// back to the bracketing solver.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "numeric/first_zero.hpp"

namespace frictionref::detail {

// jet_at(x) -> Jet<Work> (f, f', f'' at x); third bounds |f'''| on [lo, hi].
template <class Work, class JetAt>
std::optional<Work> halley_polish(const JetAt& jet_at, Work lo, Work hi, const Work& guess,
                                  const Work& third, std::uint64_t& calls) {
  using std::fabs;
  const Work eps = std::numeric_limits<Work>::epsilon();
  Work x = guess;
  for (int iteration = 0; iteration < 6; ++iteration) {
    ++calls;
    const Jet<Work> j = jet_at(x);
    if (j.f == 0) return x;
    (j.f > 0 ? lo : hi) = x;
    const Work d1 = j.d1, d2 = j.d2;
    if (!(d1 < 0)) return std::nullopt;  // not on the falling flank the bracket promises
    const Work denominator = 2 * d1 * d1 - j.f * d2;
    if (!(denominator > 0)) return std::nullopt;
    const Work step = -2 * j.f * d1 / denominator;
    const Work next = x + step;
    if (!(next >= lo && next <= hi)) return std::nullopt;
    const Work size = fabs(step);
    const Work slope = -d1;
    const Work curvature = fabs(d2) + 2 * third * size;  // >= |f''| within 2 steps of x
    if (curvature * size <= Work(1e-3) * slope) {
      const Work e = size * Work(1.01);
      const Work k2 = curvature / slope, k3 = third / slope;
      const Work bound = (k3 / 6 + k2 * k2 / 4) * e * e * e;
      const Work scale = fabs(next) > 1 ? Work(fabs(next)) : Work(1);
      if (bound <= eps * scale / 8) return next;
    }
    x = next;
  }
  return std::nullopt;
}

// A first guess inside a bracket from the jets at its ends: the secant, kept
// strictly inside.
template <class Work>
Work secant_guess(const ZeroBracket<Work>& b) {
  const Work span = b.at_lo.f - b.at_hi.f;
  if (!(span > 0)) return b.lo + (b.hi - b.lo) / 2;
  const Work x = b.lo + (b.hi - b.lo) * (b.at_lo.f / span);
  return x > b.lo && x < b.hi ? x : b.lo + (b.hi - b.lo) / 2;
}

}  // namespace frictionref::detail
