// Can the candidate's samples see the exact motion? A check that passes on
// samples that never look at a phase proves nothing about it, so PASS needs
// every exact phase longer than the stop-time tolerance to hold a sample, and
// the samples around every exact event to be at most that tolerance apart
// (docs/cross-checking.md, "What compare can and cannot see").
#pragma once

#include <cstddef>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::comparison {

struct Resolution {
  std::vector<UnresolvedPart> parts;  // the first `keep` in time order
  std::size_t phases = 0;             // unresolved phases in all
  std::size_t events = 0;             // unresolved events in all
  double resolving_step = 0;          // an archive step that resolves them; 0 if none needed
};

// `phases`: the engine's phases in time order; `t`: the candidate's times
// (non-decreasing, at least two); `tolerance`: the stop-time tolerance [time].
// Only what lies inside [t.front(), t.back()] is judged.
Resolution resolution(const std::vector<Phase>& phases, const std::vector<double>& t,
                      double tolerance, std::size_t keep = 100);

}  // namespace frictionref::comparison
