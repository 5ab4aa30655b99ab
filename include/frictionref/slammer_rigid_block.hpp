// SLAMMER's rigid-block (Newmark) analysis, reproduced as a numerical peer
// inside the tool: `newmark --method slammer`, so a user sees its
// discretisation error against the exact answer, as `stiff` shows the
// penalty spring's.
//
// The algorithm is RigidBlock.SlammerRigorous of USGS SLAMMER 1.1 (Jibson
// 1993; Jibson, Rathje, Jibson & Lee 2013, USGS Techniques and Methods
// 12-B1; its Java source is in the public domain), operation for operation,
// so that its results agree to the last bit on the same samples:
//   - the record is taken at its own step d, one sample per step, no
//     interpolation; the ground acceleration a_k (scaled) is compared with
//     the yield level t = KY g;
//   - at rest (|v| < 1e-15) the block slides when |a| > t, with n = sign(a)
//     (sign(0) = +1), else n = a / t; sliding, n = sign(v);
//   - y = a - n t; v = r + d/2 (y + s) (trapezoidal); u = q + d/2 (v + r);
//   - one-way (downslope): v <= 0 ends the slide (v = y = 0); two-way: a
//     change of the sign of v (or r within 1e-15 of 0 is not a slide);
//   - a sample that is exactly 0 is skipped (state unchanged, as if the step
//     did not happen) when the record is used with its normal polarity; not
//     with the inverse one (SLAMMER tests `a == 0 && mult > 0`, and runs the
//     inverse polarity with a negative multiplier);
//   - displacement positive in the direction in which a positive ground
//     acceleration beyond t pushes the block (SLAMMER's "downslope").
// docs/cross-checking.md and docs/theory.md compare it with the exact
// solution of the same record (linear between samples).
#pragma once

#include <cstddef>
#include <vector>

#include "frictionref/ground_motion.hpp"

namespace frictionref {

struct SlammerOptions {
  double yield_accel_g = 0.1;  // KY, in g (>= 0, finite)
  bool two_way = false;        // false: SLAMMER's downslope (one-way) block
  // The record as read is already scaled and, for the inverse polarity,
  // negated (GroundMotionReadOptions::inverse); this tells the algorithm
  // which polarity it is running, for its handling of zero samples.
  bool inverse = false;
  bool keep_history = false;  // fill SlammerResult::displacement_history

  // Throws InvalidInput naming the field and the rule.
  void validate() const;
};

struct SlammerResult {
  double displacement = 0;           // at the last sample, in the record's length unit
  std::size_t slip_episodes = 0;     // slides started (v from 0 to != 0)
  double max_relative_velocity = 0;  // max |v| [length/s]
  double final_velocity = 0;         // v at the last sample [length/s]
  bool at_rest_at_end = true;        // |v| below SLAMMER's rest threshold at the last sample
  std::size_t skipped_zero_samples = 0;
  std::vector<double> displacement_history;  // u after each sample, if asked
};

// Needs a record with a uniform step (GroundMotion::dt: an .AT2 file or one
// column): SLAMMER integrates at the record's step. Throws InvalidInput
// ("record") otherwise, and for bad options.
SlammerResult slammer_rigid_block(const GroundMotion& record, const SlammerOptions& options);

}  // namespace frictionref
