// The edges named in the engine issue: R = 0, R >= B, B = 0, v0 of either
// sign in every force state, t0 != 0, a start exactly at a breakaway time,
// a grazing zero of velocity, no zero-length phases.
#include <gtest/gtest.h>

#include <cmath>

#include "frictionref/frictionref.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

const double kPi = 3.141592653589793;

Model make(double friction, double v0 = 0, double t0 = 0) {
  Model m;
  m.friction = friction;
  m.v0 = v0;
  m.t0 = t0;
  return m;
}

// R = 0: never sticks; slips alternate at the zeros of v = v0 + cos t0 - cos t.
// From rest at t0 = 0 the velocity 1 - cos t touches 0 at 2 pi k without
// changing sign: one forward slip for the whole horizon.
TEST(EdgeCases, NoFrictionNeverSticks) {
  const Solution touching = solve(make(0), 100.0);
  testing::expect_well_formed(touching, 100.0);
  ASSERT_EQ(touching.phases.size(), 1u);
  EXPECT_EQ(touching.phases[0].kind, PhaseKind::slip_forward);

  // v0 = -0.5 at t0 = 0: v = 0.5 - cos t, zero where cos t = 0.5.
  const Solution crossing = solve(make(0, -0.5), 20.0);
  testing::expect_well_formed(crossing, 20.0);
  EXPECT_EQ(crossing.summary.count(PhaseKind::stick), 0u);
  ASSERT_GE(crossing.phases.size(), 4u);
  EXPECT_EQ(crossing.phases[0].kind, PhaseKind::slip_backward);
  const double first_zero = std::acos(0.5);
  EXPECT_NEAR(crossing.phases[0].t_end, first_zero, 4e-16);
  EXPECT_NEAR(crossing.phases[1].t_end, 2 * kPi - first_zero, 4 * 8.9e-16);
}

// R >= B: once stopped, never breaks away. At R = B exactly, from rest the
// force only touches R (at w t = pi/2): the mass does not move.
TEST(EdgeCases, FrictionAtLeastForceNeverBreaksAway) {
  const Solution at_limit = solve(make(1.0), 1000.0);
  testing::expect_well_formed(at_limit, 1000.0);
  ASSERT_EQ(at_limit.phases.size(), 1u);
  EXPECT_EQ(at_limit.phases[0].kind, PhaseKind::stick);

  for (double friction : {1.0, 1.01, 2.0, 5.0}) {
    for (double v0 : {-5.0, -1.0, 1.0, 5.0}) {
      const Solution s = solve(make(friction, v0, 0.25), 500.0);
      testing::expect_well_formed(s, 500.0);
      ASSERT_EQ(s.phases.size(), 2u) << friction << " " << v0;
      EXPECT_EQ(s.phases[0].kind, v0 > 0 ? PhaseKind::slip_forward : PhaseKind::slip_backward);
      EXPECT_EQ(s.phases[1].kind, PhaseKind::stick);
    }
  }
}

// B = 0: a slide decelerating at R/m stops at t0 + m |v0| / R, after
// v0^2 m / (2 R); with R = 0 too the velocity never changes.
TEST(EdgeCases, NoForcing) {
  Model m = make(0.5, 2.0, 1.0);
  m.amplitude = 0;
  m.mass = 2;
  const Solution s = solve(m, 100.0);
  testing::expect_well_formed(s, 100.0);
  ASSERT_EQ(s.phases.size(), 2u);
  EXPECT_DOUBLE_EQ(s.phases[0].t_end, 1.0 + 2 * 2.0 / 0.5);
  EXPECT_DOUBLE_EQ(s.phases[0].x_end, 2.0 * 2.0 * 2 / (2 * 0.5));

  m.friction = 0;
  const Solution coast = solve(m, 100.0);
  ASSERT_EQ(coast.phases.size(), 1u);
  EXPECT_EQ(coast.phases[0].v_end, 2.0);
  EXPECT_DOUBLE_EQ(coast.phases[0].x_end, 2.0 * 99.0);

  m.v0 = 0;
  const Solution rest = solve(m, 100.0);
  ASSERT_EQ(rest.phases.size(), 1u);
  EXPECT_EQ(rest.phases[0].kind, PhaseKind::stick);
}

// v0 of either sign or zero, started in every force state: force above R,
// inside the band, below -R, and on both edges.
TEST(EdgeCases, EveryStartInEveryForceState) {
  const double lambda = 0.5;
  const double alpha = std::asin(lambda);
  const double starts[] = {0.0, alpha, 1.2, kPi / 2, kPi - alpha, 3.0, kPi + alpha, 4.5,
                           3 * kPi / 2, 2 * kPi - alpha, 6.0};
  for (double t0 : starts) {
    for (double v0 : {-2.0, -1e-3, 0.0, 1e-3, 2.0}) {
      const Model m = make(lambda, v0, t0);
      const Solution s = solve(m, t0 + 20.0);
      testing::expect_well_formed(s, t0 + 20.0);
      const double force = std::sin(t0);
      if (v0 > 0) {
        EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_forward);
      } else if (v0 < 0) {
        EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_backward);
      } else if (force > lambda + 1e-12) {
        EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_forward) << t0;
      } else if (force < -lambda - 1e-12) {
        EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_backward) << t0;
      } else if (std::fabs(force) < lambda - 1e-12) {
        EXPECT_EQ(s.phases[0].kind, PhaseKind::stick) << t0;
      }
    }
  }
}

// Starting at rest exactly at a breakaway time: the stick would have zero
// length, so the first phase is the slip, from t0.
TEST(EdgeCases, StartExactlyAtBreakaway) {
  for (double lambda : {0.1, 0.5, 0.7, 0.99}) {
    const double alpha = std::asin(lambda);
    for (double t0 : {alpha, alpha + 2 * kPi, kPi + alpha, alpha - 2 * kPi}) {
      const Solution s = solve(make(lambda, 0, t0), t0 + 10.0);
      testing::expect_well_formed(s, t0 + 10.0);
      const bool forward = std::remainder(t0 - alpha, 2 * kPi) == 0;
      EXPECT_EQ(s.phases[0].kind, forward ? PhaseKind::slip_forward : PhaseKind::slip_backward)
          << "lambda " << lambda << " t0 " << t0;
      EXPECT_EQ(s.phases[0].t_begin, t0);
    }
  }
}

// t0 != 0: the force is B sin(w t), not B sin(w (t - t0)). Starting at rest at
// t0 = 1 (force sin 1 = 0.84 > 0.7) the slip begins at once; at t0 = 0 it
// would wait for asin(0.7).
TEST(EdgeCases, ForcePhaseIsAbsoluteTime) {
  const Solution s = solve(make(0.7, 0, 1.0), 11.0);
  testing::expect_well_formed(s, 11.0);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_forward);
  EXPECT_EQ(s.phases[0].t_begin, 1.0);
}

// A grazing zero: v0 chosen so that, in exact arithmetic, the forward slip's
// velocity minimum at the breakaway time alpha + 2 pi is exactly zero:
//   v(t) = v0 + 1 - cos t - lambda t = 0 and t = alpha + 2 pi
//   => v0 = lambda (alpha + 2 pi) - 1 + cos(alpha).
// With v0 rounded to double the minimum is within ~1e-16 of zero: the engine
// either sees a touch (slip goes on) or a dead band shorter than
// sqrt(2e-16 / cos(alpha)) ~ 2e-8, and nothing else.
TEST(EdgeCases, GrazingZeroOfVelocity) {
  for (double lambda : {0.2, 0.5, 0.8}) {
    const long double alpha = std::asin(static_cast<long double>(lambda));
    const long double two_pi = 6.283185307179586476925286766559L;
    const double v0 =
        static_cast<double>(lambda * (alpha + two_pi) - 1 + std::cos(alpha));
    const Solution s = solve(make(lambda, v0), 9.0);
    testing::expect_well_formed(s, 9.0);
    ASSERT_GE(s.phases.size(), 1u);
    EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_forward);
    const double graze = static_cast<double>(alpha + two_pi);
    if (s.phases.size() == 1) {
      // A touch (counted) or a minimum just above zero (not counted); either
      // way v is zero to rounding at the graze.
      EXPECT_LE(s.summary.touches, 1u) << lambda;
      EXPECT_NEAR(evaluate(s.model, s.phases[0], graze).v, 0, 1e-15) << lambda;
    } else {
      // slip+, a very short stick around the graze, slip+ again
      ASSERT_GE(s.phases.size(), 3u) << lambda;
      EXPECT_EQ(s.phases[1].kind, PhaseKind::stick);
      EXPECT_LT(s.phases[1].duration(), 1e-7) << lambda;
      EXPECT_NEAR(s.phases[1].t_end, graze, 1e-14);
      EXPECT_EQ(s.phases[2].kind, PhaseKind::slip_forward);
    }
  }
}

// No zero-length phase anywhere on a dense grid of models that includes
// exact reversals, grazes and starts at breakaway times.
TEST(EdgeCases, NoZeroLengthPhases) {
  for (double lambda : {0.0, 0.05, 0.3, 0.5370292721463151, 0.6, 0.99, 1.0, 1.5}) {
    for (double v0 : {-3.0, -0.5, 0.0, 0.5, 3.0}) {
      for (double t0 : {0.0, std::asin(lambda < 1 ? lambda : 1.0), -2.5, 100.125}) {
        const Solution s = solve(make(lambda, v0, t0), t0 + 60.0);
        testing::expect_well_formed(s, t0 + 60.0);
      }
    }
  }
}

}  // namespace
}  // namespace frictionref

namespace frictionref {
namespace {

// Found by fuzzing: R = 0 and a touch of v = 0 a few ulps before the horizon,
// in the piece that ends there. The slip goes on to t_end (it used to be cut
// into two adjacent slip+ phases).
TEST(EdgeCases, TouchInThePieceEndingAtTheHorizon) {
  Model m;
  m.mass = 10000;
  m.amplitude = 252;
  m.omega = 6.5536000000000004e-05;
  m.friction = 0;
  m.x0 = 1114111;
  m.t0 = 6.4000000000000002e-09;
  const double t_end = 12367720.102327986;
  const Solution s = solve(m, t_end);
  testing::expect_well_formed(s, t_end);  // no two adjacent phases of one kind
  EXPECT_EQ(s.summary.count(PhaseKind::stick), 0u);
}

}  // namespace
}  // namespace frictionref
