// Structural checks every exact solution must pass, shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "frictionref/frictionref.hpp"

namespace frictionref::testing {

// The seed problem's model: m = B = w = 1, R = lambda, from (x0, v0) = (0, v0) at t0 = 0.
inline Model seed_model(double lambda, double v0 = 0) {
  Model model;
  model.friction = lambda;
  model.v0 = v0;
  return model;
}

inline std::string describe(const Model& m) {
  char text[256];
  std::snprintf(text, sizeof text, "m=%.17g B=%.17g w=%.17g R=%.17g x0=%.17g v0=%.17g t0=%.17g",
                m.mass, m.amplitude, m.omega, m.friction, m.x0, m.v0, m.t0);
  return text;
}

// Contiguous, non-empty phases from t0 to t_end; x and v continuous across
// boundaries; every slip that ends before t_end ends with v = 0; a stick has
// v = 0 and constant x; slips of one direction are never adjacent (a touch
// does not split a slip).
inline void expect_well_formed(const Solution& s, double t_end) {
  SCOPED_TRACE(describe(s.model));
  ASSERT_FALSE(s.phases.empty());
  EXPECT_EQ(s.phases.front().t_begin, s.model.t0);
  EXPECT_EQ(s.phases.front().x_begin, s.model.x0);
  EXPECT_EQ(s.phases.front().v_begin, s.model.v0);
  EXPECT_EQ(s.phases.back().t_end, t_end);
  EXPECT_EQ(s.summary.termination, Termination::reached_end);
  EXPECT_EQ(s.summary.phases, s.phases.size());
  for (std::size_t i = 0; i < s.phases.size(); ++i) {
    const Phase& p = s.phases[i];
    SCOPED_TRACE("phase " + std::to_string(i));
    EXPECT_LT(p.t_begin, p.t_end);
    if (p.kind == PhaseKind::stick) {
      EXPECT_EQ(p.v_begin, 0);
      EXPECT_EQ(p.v_end, 0);
      EXPECT_EQ(p.x_begin, p.x_end);
    }
    if (i + 1 < s.phases.size()) {
      const Phase& q = s.phases[i + 1];
      EXPECT_EQ(p.t_end, q.t_begin);
      EXPECT_EQ(p.x_end, q.x_begin);
      EXPECT_EQ(p.v_end, 0);
      EXPECT_EQ(q.v_begin, 0);
      EXPECT_FALSE(p.kind == q.kind) << "two adjacent phases of kind " << to_string(p.kind);
    }
  }
}

}  // namespace frictionref::testing
