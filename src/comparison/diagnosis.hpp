// The diagnosis: which class of defect most likely explains a verdict, with
// the measurements that point at it (docs/cross-checking.md, "The diagnosis").
//
// FAIL is explained, in this order, by the first that fits:
//  1. a global transformation of the exact velocity that, once removed,
//     leaves a candidate within the velocity tolerances: a constant time
//     shift (fitted by Gauss-Newton on the exact closed forms, not on the
//     samples), a scale factor;
//  2. what the candidate does inside the exact phases: sign flips sample after
//     sample inside the sticks (chattering), slow motion inside most sticks
//     (creep), then the earliest of a slip it sits through (missed
//     breakaway) and a stick it slides through (missed stop);
//  3. a constant velocity bias (drift), or a displacement error that is a
//     straight line in time (drift) or a constant (offset);
//  4. otherwise unclassified, naming the first failed check.
#pragma once

#include "exact_motion.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref::comparison {

// Needs r complete up to the verdict.
Diagnosis diagnose(const ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact);

}  // namespace frictionref::comparison
