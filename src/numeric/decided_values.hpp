// Which values of a dense fast path's row are decided, that is proven to be
// the correctly rounded doubles of the closed form: the bits of decided[i]
// (docs/theory.md 10). At a phase's own ends the row's x and v are the
// stored states (slip_state), so there the acceleration alone must be
// decided; elsewhere all three.
#pragma once

namespace frictionref::detail {

enum DecidedValues : unsigned char {
  kPositionDecided = 1,
  kVelocityDecided = 2,
  kAccelerationDecided = 4,
  kAllDecided = kPositionDecided | kVelocityDecided | kAccelerationDecided,
};

}  // namespace frictionref::detail
