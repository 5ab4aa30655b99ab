#include "resolution.hpp"

#include <algorithm>
#include <cmath>

namespace frictionref::comparison {

Resolution resolution(const std::vector<Phase>& phases, const std::vector<double>& t,
                      double tolerance, std::size_t keep) {
  Resolution r;
  const double first = t.front(), last = t.back();
  double shortest = tolerance;  // the shortest phase that must hold a sample, or the tolerance
  const auto add = [&](const UnresolvedPart& part) {
    if (r.parts.size() < keep) r.parts.push_back(part);
  };
  for (const Phase& phase : phases) {
    const double lo = std::max(phase.t_begin, first), hi = std::min(phase.t_end, last);
    if (!(lo < hi)) continue;
    // The event that begins the phase, when it lies inside the record: the
    // samples around it (the last at or before it, the first at or after it).
    if (phase.t_begin > first) {
      // t.front() < t_begin < t.back(): both exist.
      const auto after = std::lower_bound(t.begin(), t.end(), phase.t_begin);
      const double gap = *after == phase.t_begin ? 0 : *after - *std::prev(after);
      if (gap > tolerance) {
        ++r.events;
        add({UnresolvedPart::Kind::event, phase.kind, phase.t_begin, phase.t_begin, gap});
      }
    }
    // The phase itself: a sample strictly inside it (or on a record end it
    // reaches past), when it lasts longer than the tolerance.
    if (hi - lo <= tolerance) continue;
    shortest = std::min(shortest, hi - lo);
    const bool open_lo = phase.t_begin > first, open_hi = phase.t_end < last;
    auto inside = open_lo ? std::upper_bound(t.begin(), t.end(), lo)
                          : std::lower_bound(t.begin(), t.end(), lo);
    const bool seen = inside != t.end() && (open_hi ? *inside < hi : *inside <= hi);
    if (!seen) {
      ++r.phases;
      const auto after = std::upper_bound(t.begin(), t.end(), hi);
      const double right = after == t.end() ? last : *after;
      const double left = inside == t.begin() ? first : *std::prev(inside);
      add({UnresolvedPart::Kind::phase, phase.kind, phase.t_begin, phase.t_end, right - left});
    }
  }
  // Samples at most this far apart see every phase longer than the tolerance
  // (half the shortest) and every event (within the tolerance).
  if (r.phases + r.events > 0) r.resolving_step = 0.5 * shortest;
  return r;
}

}  // namespace frictionref::comparison
