// A ground-motion record made in a test from its samples (no file), for the
// engine tests of both record families.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "frictionref/ground_motion.hpp"

namespace frictionref::testing {

inline std::shared_ptr<const GroundMotion> record(std::vector<double> t, std::vector<double> a) {
  auto r = std::make_shared<GroundMotion>();
  r->t = std::move(t);
  r->a = std::move(a);
  r->file = "hand-made";
  r->npts = r->t.size();
  return r;
}

}  // namespace frictionref::testing
