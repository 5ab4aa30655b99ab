// The general model (static friction, spring, damper, offset, harmonics)
// against closed forms derived here independently of the engine's phase
// laws (docs/theory.md 7), and its edge cases (theory.md 7.7).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "frictionref/phase.hpp"

namespace frictionref {
namespace {

const double pi = 3.14159265358979323846;

// Relative error in units of the double ulp of `expected` (at least the ulp of 1).
double ulps(double actual, long double expected) {
  const double scale = std::fmax(std::fabs(static_cast<double>(expected)), 1.0);
  return static_cast<double>(std::fabs(actual - expected)) /
         (scale * std::numeric_limits<double>::epsilon());
}

// ---- free Coulomb oscillator: m x'' + k x = -R sign(v) ------------------------
// Every half cycle lasts pi sqrt(m/k) and ends 2R/k closer to 0 (on the other
// side); the mass stays once |k x| <= Rs at a turning point (the classical
// result, e.g. Den Hartog, Mechanical Vibrations, 1956, section 8.2).
TEST(GeneralEngine, FreeCoulombOscillatorLosesTwoRoverKPerHalfCycle) {
  Model m;
  m.mass = 2;
  m.stiffness = 8;  // w_n = 2, half cycle pi / 2
  m.amplitude = 0;
  m.friction = 0.5;  // 2 R / k = 0.125
  m.x0 = 1;
  const Solution s = solve(m, 20.0);
  ASSERT_EQ(s.summary.termination, Termination::reached_end);
  const double half = pi / 2, step = 0.125;
  // |x0| = 1 = 8 steps: turning points at 1 - 0.125 j, sign alternating,
  // until |x| <= R/k = 0.0625 (Rs = R): 1 - 8 * 0.125 = 0 after 8 half cycles.
  ASSERT_EQ(s.phases.size(), 9u);
  for (int j = 0; j < 8; ++j) {
    const Phase& p = s.phases[static_cast<std::size_t>(j)];
    EXPECT_EQ(p.kind, j % 2 == 0 ? PhaseKind::slip_backward : PhaseKind::slip_forward);
    EXPECT_LT(ulps(p.t_end, (j + 1) * static_cast<long double>(half)), 8) << "half cycle " << j;
    const double expected_x = (j % 2 == 0 ? -1 : 1) * (1 - step * (j + 1));
    EXPECT_NEAR(p.x_end, expected_x, 1e-15) << "half cycle " << j;
  }
  EXPECT_EQ(s.phases.back().kind, PhaseKind::stick);
}

// With static friction above the sliding one, the first turning point with
// |k x| <= Rs ends the motion, even where |k x| > R.
TEST(GeneralEngine, FreeCoulombOscillatorStopsWhereStaticFrictionHolds) {
  Model m;
  m.stiffness = 1;
  m.amplitude = 0;
  m.friction = 0.1;          // 2 R / k = 0.2 per half cycle
  m.static_friction = 0.35;  // holds once |x| <= 0.35
  m.x0 = 1;                  // turning points 0.8, 0.6, 0.4, then 0.2 <= 0.35
  const Solution s = solve(m, 30.0);
  ASSERT_EQ(s.phases.size(), 5u);
  EXPECT_NEAR(s.phases[3].x_end, 0.2, 1e-15);
  EXPECT_EQ(s.phases[4].kind, PhaseKind::stick);
  // At x = -0.4 (|k x| = 0.4 > Rs) the mass did reverse.
  EXPECT_NEAR(s.phases[2].x_end, -0.4, 1e-15);
  EXPECT_EQ(s.phases[3].kind, PhaseKind::slip_forward);
}

// ---- the linear oscillator without friction ---------------------------------
// m x'' + c x' + k x = 0 from (x0, v0): v(t) = e^(-s t) (v0 cos(d t) -
// ((w_n^2 x0 + s v0) / d) sin(d t)), s = c/2m, d = sqrt(w_n^2 - s^2). Its zeros
// (where the engine's phases end, R = 0: every one a reversal) are at
// d t = atan2(v0 d, w_n^2 x0 + s v0) + j pi.
TEST(GeneralEngine, UnderdampedFreeVibrationReversesAtTheVelocityZeros) {
  Model m;
  m.mass = 1.5;
  m.stiffness = 6;   // w_n^2 = 4
  m.damping = 0.75;  // s = 0.25
  m.amplitude = 0;
  m.friction = 0;
  m.x0 = 0.5;
  m.v0 = 1;
  const long double s = 0.25L, wn2 = 4, d = std::sqrt(wn2 - s * s);
  const long double first = std::atan2(1.0L * d, wn2 * 0.5L + s * 1.0L);
  const Solution sol = solve(m, 10.0);
  ASSERT_GE(sol.phases.size(), 5u);
  for (std::size_t j = 0; j + 1 < sol.phases.size(); ++j) {
    const long double t = (first + static_cast<long double>(j) * 3.14159265358979323846L) / d;
    EXPECT_LT(ulps(sol.phases[j].t_end, t), 8) << "zero " << j;
    // x there: x(t) = e^(-s t) (x0 cos(d t) + ((v0 + s x0) / d) sin(d t)).
    const long double x =
        std::exp(-s * t) * (0.5L * std::cos(d * t) + (1 + s * 0.5L) / d * std::sin(d * t));
    EXPECT_NEAR(sol.phases[j].x_end, static_cast<double>(x), 1e-15) << "zero " << j;
  }
}

// Overdamped and critically damped free motion never reverses; x decays to 0.
// Critical: x(t) = (x0 + (v0 + w_n x0) t) e^(-w_n t).
TEST(GeneralEngine, CriticallyDampedFreeMotionMatchesItsClosedForm) {
  Model m;
  m.stiffness = 4;  // w_n = 2
  m.damping = 4;    // c = 2 sqrt(k m): zeta = 1
  m.amplitude = 0;
  m.friction = 0;
  m.x0 = 1;
  m.v0 = 0;  // from rest: slides toward 0 (N = -k x0)
  const Solution sol = solve(m, 6.0);
  ASSERT_EQ(sol.phases.size(), 1u);
  EXPECT_EQ(sol.phases[0].kind, PhaseKind::slip_backward);
  for (double t : {0.1, 0.5, 1.0, 2.5, 5.9}) {
    const State st = sol.state_at(t);
    const long double x = (1 + 2.0L * t) * std::exp(-2.0L * t);
    const long double v = -4.0L * t * std::exp(-2.0L * t);
    EXPECT_NEAR(st.x, static_cast<double>(x), 4e-16) << t;
    EXPECT_NEAR(st.v, static_cast<double>(v), 4e-16) << t;
  }
}

// Damping ratios a rounding away from 1 give the critically damped motion to
// rounding (no cancellation between the over- and underdamped forms).
TEST(GeneralEngine, DampingRatiosNextToOneAreContinuous) {
  Model m;
  m.stiffness = 4;
  m.damping = 4;
  m.amplitude = 0;
  m.friction = 0;
  m.x0 = 1;
  const Solution critical = solve(m, 6.0);
  for (double c :
       {std::nextafter(4.0, 5.0), std::nextafter(4.0, 3.0), 4 * (1 + 1e-12), 4 * (1 - 1e-12)}) {
    Model near = m;
    near.damping = c;
    const Solution sol = solve(near, 6.0);
    for (double t : {0.3, 1.7, 4.2}) {
      // The motion depends smoothly on c: |dx/dc| <= t^2 e^(-2t) here, so the
      // difference stays at the level of the change in c times that.
      const double change = std::fabs(c - 4) * t * t;
      EXPECT_NEAR(sol.state_at(t).x, critical.state_at(t).x, 4e-16 + change) << c << " " << t;
      EXPECT_NEAR(sol.state_at(t).v, critical.state_at(t).v, 4e-16 + change) << c << " " << t;
    }
  }
}

// ---- static friction with k = c = 0 -------------------------------------------
// A constant force between R and Rs never starts the mass; above Rs it slides
// at once with a = (F0 - R)/m, x = x0 + a t^2 / 2.
TEST(GeneralEngine, ConstantForceBetweenKineticAndStaticFrictionNeverMoves) {
  Model m;
  m.amplitude = 0;
  m.friction = 0.5;
  m.static_friction = 0.8;
  m.force_offset = 0.8;  // |N| = Rs exactly: holds
  const Solution s = solve(m, 100.0);
  ASSERT_EQ(s.phases.size(), 1u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
  m.force_offset = std::nextafter(0.8, 1.0);
  const Solution moving = solve(m, 2.0);
  ASSERT_EQ(moving.phases.size(), 1u);
  EXPECT_EQ(moving.phases[0].kind, PhaseKind::slip_forward);
  const long double a = std::nextafter(0.8, 1.0) - 0.5L;
  EXPECT_NEAR(moving.phases[0].x_end, static_cast<double>(a * 2), 1e-15);
  EXPECT_NEAR(moving.phases[0].v_end, static_cast<double>(a * 2), 1e-15);
}

// B sin(w t) with Rs > R: the first breakaway is where B sin(w t) = Rs.
TEST(GeneralEngine, BreakawayWhereTheForceFirstExceedsStaticFriction) {
  Model m;
  m.friction = 0.5;
  m.static_friction = 0.75;
  const Solution s = solve(m, 3.0);
  ASSERT_GE(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
  EXPECT_LT(ulps(s.phases[0].t_end, std::asin(0.75L)), 4);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::slip_forward);
  // Just after it: a = (B sin(w t) - R) / m = 0.25 > 0 (the jump of static friction).
  EXPECT_NEAR(evaluate(m, s.phases[1], s.phases[1].t_begin).a, 0.25, 1e-15);
}

// A spring whose equilibrium lies inside the stick band: from rest at x0 with
// |F0 - k x0| <= Rs the mass never moves.
TEST(GeneralEngine, EquilibriumInsideTheStickBandHolds) {
  Model m;
  m.amplitude = 0;
  m.stiffness = 10;
  m.friction = 1;
  m.force_offset = 2;
  m.x0 = 0.15;  // N = 2 - 1.5 = 0.5 <= 1
  const Solution s = solve(m, 50.0);
  ASSERT_EQ(s.phases.size(), 1u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
}

// A slip that reaches v = 0 with R < |N| <= Rs sticks (static friction takes
// over); with |N| > Rs against it, it reverses at once.
TEST(GeneralEngine, StopDecidedByStaticFriction) {
  // Free spring oscillator from x0 = 1: the first turning point is at
  // x = -(1 - 2R/k) = -0.8 with R = 0.1, where |k x| = 0.8.
  Model m;
  m.amplitude = 0;
  m.stiffness = 1;
  m.friction = 0.1;
  m.x0 = 1;
  m.static_friction = 0.8;  // |N| = Rs exactly: sticks
  Solution s = solve(m, 10.0);
  ASSERT_EQ(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::stick);
  m.static_friction = 0.79;  // |N| > Rs: reverses
  s = solve(m, 10.0);
  ASSERT_GE(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::slip_forward);
  EXPECT_EQ(s.summary.reversals >= 1, true);
}

// v0 != 0 starts a slip in its direction whatever the force.
TEST(GeneralEngine, InitialVelocityStartsASlip) {
  Model m;
  m.stiffness = 1;
  m.friction = 0.2;
  m.static_friction = 5;
  m.v0 = -0.01;
  const Solution s = solve(m, 5.0);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_backward);
  EXPECT_EQ(s.phases[0].v_begin, -0.01);
}

// Resonance without damping (w = sqrt(k/m), R = 0): from rest,
// x(t) = B / (2 m w^2) (sin(w t) - w t cos(w t)), growing linearly.
TEST(GeneralEngine, UndampedResonanceGrowsLinearly) {
  Model m;
  m.mass = 1;
  m.stiffness = 4;
  m.omega = 2;
  m.amplitude = 1;
  m.friction = 0;
  m.x0 = 0;
  m.v0 = 1e-300;  // a slip from t0 (at rest with R = Rs = 0 it would break away at once anyway)
  m.v0 = 0;
  const Solution s = solve(m, 40.0);
  for (double t : {1.0, 7.5, 20.25, 39.0}) {
    const long double wt = 2.0L * t;
    const long double x = (std::sin(wt) - wt * std::cos(wt)) / 8;
    EXPECT_NEAR(s.state_at(t).x, static_cast<double>(x), 1e-14 * (1 + t)) << t;
  }
}

// Driven at resonance with a damping far too small to matter over the run
// (c t^3 / m below 1e-17 of x), the motion is the undamped secular growth.
// The textbook split into a steady response (amplitude B / (c w), up to
// 1e323 here) and a transient cancelling it lost every digit (found by
// fuzzing, tests/fuzz/corpus/engine/general-finding-resonance-light-damping).
TEST(GeneralEngine, LightlyDampedResonanceIsTheSecularGrowth) {
  for (double c : {1e-20, 1e-200, 4.9406564584124654e-324}) {
    Model m;
    m.mass = 1;
    m.stiffness = 4;
    m.omega = 2;
    m.amplitude = 1;
    m.friction = 0;
    m.damping = c;
    const Solution s = solve(m, 40.0);
    ASSERT_EQ(s.summary.termination, Termination::reached_end) << c;
    for (double t : {1.0, 7.5, 20.25, 39.0}) {
      const long double wt = 2.0L * t;
      const long double x = (std::sin(wt) - wt * std::cos(wt)) / 8;
      EXPECT_NEAR(s.state_at(t).x, static_cast<double>(x), 1e-14 * (1 + t)) << c << " " << t;
    }
  }
}

// Near resonance with light damping (sigma = c / (2 m w) = 5e-7, |H| = 1e6):
// y = -cos t / (2 sigma) + e^{-sigma t} (cos(nu t) / (2 sigma) + sin(nu t) / (2 nu)),
// nu = sqrt(1 - sigma^2), from rest with R = 0, evaluated here in 50 digits
// (the cancellation of 1e6 leaves 44).
TEST(GeneralEngine, LightlyDampedNearResonanceKeepsItsDigits) {
  using Wide = HighPrecision;
  Model m;
  m.stiffness = 1;
  m.damping = 1e-6;
  m.friction = 0;
  const Solution s = solve(m, 60.0);
  ASSERT_EQ(s.summary.termination, Termination::reached_end);
  const Wide sigma = Wide(m.damping) / 2;
  const Wide nu = sqrt(1 - sigma * sigma);
  for (double t : {0.5, 3.0, 17.0, 59.5}) {
    const Wide tw(t);
    const Wide y = -cos(tw) / (2 * sigma) +
                   exp(-sigma * tw) * (cos(nu * tw) / (2 * sigma) + sin(nu * tw) / (2 * nu));
    EXPECT_NEAR(s.state_at(t).x, static_cast<double>(y), 4e-16 * (1 + t)) << t;
  }
}

// The 50-digit instantiation runs the same template for every model and agrees
// with the double engine to the double engine's rounding.
TEST(GeneralEngine, FiftyDigitInstanceAgrees) {
  Model m;
  m.stiffness = 1;
  m.damping = 0.2;
  m.friction = 0.3;
  m.static_friction = 0.45;
  m.force_offset = 0.1;
  m.harmonics.push_back({0.4, 2.5, 0.3});
  const Solution d = solve(m, 20.0);
  const BasicSolution<HighPrecision> h = solve(model_cast<HighPrecision>(m), HighPrecision(20));
  ASSERT_EQ(d.phases.size(), h.phases.size());
  for (std::size_t i = 0; i < d.phases.size(); ++i) {
    EXPECT_EQ(d.phases[i].kind, h.phases[i].kind) << i;
    EXPECT_LT(ulps(d.phases[i].t_end, static_cast<long double>(h.phases[i].t_end)), 4) << i;
  }
}

// Found by fuzzing (corpus general-finding-decay-to-rounding-reversals): an
// underdamped free vibration (zeta = 0.5) from x0 = 4e6 decays to the
// rounding of x around F0 / k within 8 of its 10 time units. Its velocity
// zeros are a damped half period pi / w_d apart; once the motion is below
// the state's rounding, N = F0 - k x is rounding noise that does not move:
// the mass stays at rest there (R = Rs = 0), instead of reversing at every
// noise crossing of v (hundreds of 1 ms phases before).
TEST(GeneralEngine, FreeVibrationDecayedBelowRoundingComesToRest) {
  Model m;
  m.mass = 65;
  m.amplitude = 0;
  m.omega = 3;
  m.friction = 0;
  m.stiffness = 16022;
  m.damping = 1024;
  m.force_offset = 47;
  m.x0 = 4063232;
  m.v0 = 4456448;
  m.t0 = 4206336;
  const double t_end = 4206346.4719755119;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end);
  const long double k = m.stiffness, c = m.damping, mass = m.mass;
  const long double sigma = c / (2 * mass);
  const long double half = pi / std::sqrt(k / mass - sigma * sigma);
  // At most one phase per half period, plus the first and the last.
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>((t_end - m.t0) / half) + 2);
  // Every slip after the first with a resolvable travel is a half period.
  for (std::size_t i = 1; i + 1 < s.phases.size(); ++i) {
    const Phase& p = s.phases[i];
    if (p.kind == PhaseKind::stick || std::fabs(p.x_end - p.x_begin) < 1e-12) continue;
    EXPECT_NEAR(p.t_end - p.t_begin, static_cast<double>(half), 1e-8) << "phase " << i;
  }
  const Phase& last = s.phases.back();
  EXPECT_EQ(last.kind, PhaseKind::stick);
  const long double equilibrium = 47.0L / 16022.0L;
  EXPECT_LT(ulps(last.x_end, equilibrium), 4);
  EXPECT_EQ(last.v_end, 0);
}

// Found by fuzzing (corpus general-finding-band-edge-noise-stall): critical
// damping, Rs = R = 3, the mass at the stick band's edge (x = F0 + 3 - 1e-8
// where the ulp of x is 9e-10), nudged over it by B = 1e-8 every period.
// Its slips have velocities at the level of their rounding; the search
// crawled through that noise a resolution at a time and hit its cap. Now it
// runs to the end, with the mass inside the band whenever it rests and at
// most four phases per forcing period.
TEST(GeneralEngine, SlipsAtTheLevelOfTheirRoundingEnd) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-8;
  m.omega = 1;
  m.friction = 3;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 4198912;
  m.x0 = 2048;
  m.v0 = 6946816;
  const double t_end = 578.0530482605219;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (t_end / (2 * pi) + 1)));
  for (const Phase& p : s.phases) {
    if (p.kind != PhaseKind::stick) continue;
    // |N| <= Rs + B at rest: x within the band widened by the forcing.
    EXPECT_LE(std::fabs(m.force_offset - p.x_begin), 3 + 1e-8 + 1e-9) << p.t_begin;
  }
}

// Found by fuzzing (corpus general-finding-far-equilibrium-edge-touches):
// a critically damped approach (k = 1, c = 2) to an equilibrium 6e13 from
// 0, whose rounding (1e-2 in N) dwarfs the harmonic (1e-9). At the velocity
// zero the net force was inside the band by less than its rounding but by
// far more than it moves within the time resolution; the at-rest rule
// followed the slope of N and slid, and the slip turned back at once, a
// touch at a time until the cap. The mass rests inside the band.
TEST(GeneralEngine, ApproachToAFarEquilibriumRestsInsideTheBand) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-9;
  m.omega = 2;
  m.friction = 3;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = -60928000000000;
  m.x0 = 2048;
  m.v0 = 694681600;
  const Solution s = solve(m, 289.02652413026095);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  ASSERT_LE(s.phases.size(), 4u);
  const Phase& last = s.phases.back();
  EXPECT_EQ(last.kind, PhaseKind::stick);
  // |N| = |F0 - k x| <= Rs, to the rounding of k x (a few ulps of 6e13).
  EXPECT_LE(std::fabs(m.force_offset - last.x_end), 3 + 0.05);
}

// Found by fuzzing (corpus general-finding-far-equilibrium-slide-against-n):
// an underdamped spring (k = 35, c = 10) released at 1.6e12 towards the
// equilibrium F0 / k = 1.1e14, where N from the slip's closed form is
// rounded by 1e-2, above Rs = 6.3e-3 and of the order of the harmonic
// (B = 2.3e-2). At the eighth velocity zero N = +0.015 (resolvably
// positive) with |N| - Rs inside its rounding; the at-rest rule took the
// edge from N's slope (falling) and let the backward slip go on, against
// N, touch after touch until the cap. The mass may rest there or go
// forwards, never backwards; the motion left is below the rounding of x.
TEST(GeneralEngine, FarEquilibriumNeverSlidesAgainstAResolvableForce) {
  Model m;
  m.mass = 1;
  m.amplitude = 0.02306816;
  m.omega = 1;
  m.friction = 0.006291456;
  m.static_friction = 0.006291456;
  m.stiffness = 35;
  m.damping = 10;
  m.force_offset = 3826688000000000;
  m.x0 = 63155200;
  m.v0 = 1603093174681.6001;
  const Solution s = solve(m, 82.0);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  // Half a damped period each (pi / sqrt(k/m - (c/2m)^2) = 0.9935) until
  // the motion is below the rounding, then nothing resolvable is left.
  ASSERT_GE(s.phases.size(), 7u);
  ASSERT_LE(s.phases.size(), 12u);
  const double equilibrium = m.force_offset / m.stiffness;
  for (std::size_t i = 1; i < 6; ++i)  // while the transient dwarfs B / k
    EXPECT_NEAR(s.phases[i].t_end - s.phases[i].t_begin, pi / std::sqrt(10.0), 1e-3) << i;
  // The last phase ends at the equilibrium to a few ulps of x (one ulp of
  // 1.1e14 is 0.016; the harmonic's reach B / k = 6.6e-4 is far below it).
  const Phase& last = s.phases.back();
  EXPECT_LE(std::fabs(last.x_end - equilibrium),
            8 * std::numeric_limits<double>::epsilon() * equilibrium);
}

// Found by fuzzing (corpus general-finding-edge-nudge-zero-noise-start):
// R = Rs = 3 with the mass at the band's edge (x = F0 - 3 exactly), nudged
// over it by B = 1e-9 half of every period. A slip's closed form is exact
// at its start (rounding 0), so the stretch in which v is not looked at was
// one resolution long, and v, far below its noise there, was taken for a
// stop at once: a slip and a stick per resolution, for ever. Now the
// stretch comes from the noise one resolution later, and the slips are the
// physical ones: at most a few per forcing period, the mass in the band
// whenever it rests.
TEST(GeneralEngine, NudgesOverTheBandsEdgeAreWholeSlips) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-9;
  m.omega = 2;
  m.friction = 3;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 4198912;
  m.x0 = 2048;
  m.v0 = -0.02048;
  m.t0 = -0.1;
  const double t_end = 467.99730538487916;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const double periods = (t_end - m.t0) * m.omega / (2 * pi);
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (periods + 1)));
  for (const Phase& p : s.phases) {
    if (p.kind != PhaseKind::stick) continue;
    EXPECT_LE(std::fabs(m.force_offset - p.x_begin), 3 + 1e-9 + 1e-9) << p.t_begin;
  }
}

// Found by fuzzing (corpus general-finding-far-equilibrium-noisy-direction):
// no friction (R = Rs = 0), a critically damped approach to the equilibrium
// F0 / k = 4.2e12 driven by B = 1e-8 at w = 9. Once the transient has died
// the velocity is the harmonic's steady response (amplitude about 1e-9)
// and reverses every pi / w; N = F0 - k x computed from the position is
// rounding noise there (1e-5), and it chose the direction at the velocity
// zeros until the search hit its cap. The motion runs to the end, at most
// four phases per forcing period, the mass at the equilibrium to the
// rounding of x.
TEST(GeneralEngine, FarEquilibriumReversesWithTheHarmonic) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-8;
  m.omega = 9;
  m.friction = 0;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 4198912000000;
  m.x0 = 4393472;
  m.v0 = 65535;
  m.t0 = 2304;
  const double t_end = 2368.2281164733913;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const double periods = (t_end - m.t0) * m.omega / (2 * pi);
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (periods + 1)));
  const Phase& last = s.phases.back();
  EXPECT_LE(std::fabs(last.x_end - m.force_offset),
            4 * std::numeric_limits<double>::epsilon() * m.force_offset);
}

// Found by fuzzing (corpus general-finding-far-equilibrium-turned-touches):
// no friction (R = Rs = 0), m = k = w = 1 (resonance), c = 0.2, the
// equilibrium F0 / k = 1.4e15 far from 0 (one long double ulp of x 1.2e-4),
// driven by B = 5.7e-4: the steady velocity (amplitude B / c = 2.9e-3) is
// about twice its own rounding there. At the end of a jump over v's noise
// the slip's v was twice its rounding against the slip and not turning back,
// while the at-rest rule (N within rounding, rising) said "on": touch after
// touch one resolution apart until the cap. The run now reaches its end, at
// the equilibrium to the rounding of x, in a few phases per period. Whether
// the mass rests there or goes on reversing is rounding's choice (its
// velocity is twice its own rounding; with Rs = 0 the exact motion never
// sticks): the engine of 2026-11-26 rested, the search's longer steps
// since then reverse; either is accepted, and a rest must be at the
// equilibrium.
TEST(GeneralEngine, FarEquilibriumTurnedAgainstTheSlipRests) {
  Model m;
  m.mass = 1;
  m.amplitude = 0.00057111;
  m.omega = 1;
  m.friction = 0;
  m.stiffness = 1;
  m.damping = 0.2;
  m.force_offset = 1376255000000000;
  m.x0 = 460803;
  m.v0 = 3342336;
  m.t0 = 28160;
  const double t_end = 28738.053048260521;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const double periods = (t_end - m.t0) * m.omega / (2 * pi);
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (periods + 1)));
  for (const Phase& p : s.phases) {
    if (p.kind != PhaseKind::stick) continue;
    // |N| <= Rs = 0 to the rounding of k x (x within 4 ulps of F0 / k)
    EXPECT_LE(std::fabs(p.x_begin - m.force_offset),
              4 * std::numeric_limits<double>::epsilon() * m.force_offset);
  }
  EXPECT_LE(std::fabs(s.phases.back().x_end - m.force_offset),
            4 * std::numeric_limits<double>::epsilon() * m.force_offset);
}

// Found by fuzzing (corpus general-finding-unresolvable-dip-touches): the
// mass at the band's edge (R = Rs = 3, F0 = 3: x = 0), nudged over it by
// B = 1e-9. At a touch the slope of v was -9e-21, inside its rounding, with
// v'' > 0: a dip of 46 time resolutions, crossed one resolution per touch
// until the cap of 64 touches. The stretch not searched now runs over the
// dip.
TEST(GeneralEngine, UnresolvableDipIsSteppedOver) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-9;
  m.omega = 2;
  m.friction = 3;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 3;
  m.x0 = 2048;
  m.v0 = -19465.3;
  m.t0 = 358.3;
  const double t_end = 826.39730538487925;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const double periods = (t_end - m.t0) * m.omega / (2 * pi);
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (periods + 1)));
  for (const Phase& p : s.phases) {
    if (p.kind != PhaseKind::stick) continue;
    EXPECT_LE(std::fabs(m.force_offset - p.x_begin), 3 + 1e-9 + 1e-15) << p.t_begin;
  }
}

// Found by fuzzing (corpus general-finding-edge-excess-rounding-of-rs): R =
// Rs = 7.2e9 and an equilibrium 6e13 from 0. At the first velocity zero
// after the approach, |N| - Rs was -3e-10, resolvable from the slip's closed
// form, but its rounding bound included that of Rs itself (1.6e-9): the stop
// looked ambiguous, the mass slid on, and touch after touch hit the cap.
TEST(GeneralEngine, ExcessOverStaticFrictionHasItsOwnRounding) {
  Model m;
  m.mass = 1;
  m.amplitude = 1e-9;
  m.omega = 2;
  m.friction = 7227651000;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = -60928000000000;
  m.x0 = 2048;
  m.v0 = 694681600;
  const Solution s = solve(m, 289.02652413026095);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  ASSERT_LE(s.phases.size(), 4u);
  const Phase& last = s.phases.back();
  EXPECT_EQ(last.kind, PhaseKind::stick);
  EXPECT_LE(std::fabs(m.force_offset - last.x_end), m.friction * (1 + 1e-12));
}

// Found by fuzzing (corpus general-finding-noise-decays-in-stretch): R = Rs
// = 0, the equilibrium 1.2e15 from 0, where the state's rounding (1e-4 in
// long double) exceeds the harmonic's whole motion (4e-5). After a restart
// the slip's rounding decays with the transient; the stretch not searched,
// set by the noise at its start, ran 68 time units and ended with v
// resolvably of the wrong sign, and touch after touch hit the cap. The run
// ends, within the phase bound, at the equilibrium to the rounding of x.
TEST(GeneralEngine, NoiseThatDecaysInsideTheStretchCutsIt) {
  Model m;
  m.mass = 1;
  m.amplitude = 8.193e-05;
  m.omega = 1;
  m.friction = 0;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 1219584000000000;
  m.x0 = 2051000;
  m.v0 = 7208960;
  const double t_end = 578.0530482605219;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(4 * (t_end / (2 * pi) + 1)));
  EXPECT_LE(std::fabs(s.phases.back().x_end - m.force_offset),
            4 * std::numeric_limits<double>::epsilon() * m.force_offset);
}

// Found by fuzzing (corpus general-finding-edge-gap-cascade): F0 = R = Rs =
// 196611 with k = 1, the harmonic B = 3e-8 pushing the mass forward a little
// each period: N = F0 - x + B sin t exceeds Rs while x < B, so x creeps
// towards B = 3e-8 and never passes it (then |N| <= Rs for ever). N from the
// position carries the rounding of F0 (1e-12), the slip's closed form does
// not: near the end of the creep each breakaway came a rounding early and
// the slip stopped at once, a cascade of 2-ns phases. Now: one stick and one
// forward slip per period, x increasing and below B.
TEST(GeneralEngine, CreepTowardsTheBandsEdgeStaysOnePhasePairPerPeriod) {
  Model m;
  m.mass = 1;
  m.amplitude = 3e-8;
  m.omega = 1;
  m.friction = 196611;
  m.stiffness = 1;
  m.damping = 2;
  m.force_offset = 196611;
  m.t0 = 1060000;
  const double t_end = 1060578.0530482605;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const double periods = (t_end - m.t0) / (2 * pi);
  EXPECT_LE(s.phases.size(), static_cast<std::size_t>(2 * periods + 3));
  double x = 0;
  for (const Phase& p : s.phases) {
    EXPECT_NE(p.kind, PhaseKind::slip_backward) << p.t_begin;
    EXPECT_GE(p.x_end, x) << p.t_begin;
    EXPECT_LE(p.x_end, 3e-8) << p.t_begin;
    x = p.x_end;
  }
}

// ---- a stiff spring: a slip that rings through 10^4 natural periods ------------
// m = 1, k = 1e10 or 1e12 (w_n = 1e5, 1e6), B sin t, R = Rs = 0.3. Stuck at
// x_s after the forward slip, the mass breaks away backwards where
// sin t - k x_s = -R: t_b = pi - asin(k x_s - R). From (x_s, 0) at t_b the
// backward slip is x = sin t / (k - 1) + R / k + A cos(w_n (t - t_b))
// + C sin(w_n (t - t_b)), so v = S(t) + W cos(w_n (t - t_b) + phi) with
// S = cos t / (k - 1), W = w_n sqrt(A^2 + C^2), phi = atan2(A, C): it comes
// back near 0 once per natural period and first crosses it about 2 pi - t_b
// (0.82 later: 1.3e4 and 1.3e5 natural periods), where its humps first rise
// 3e-19 above 0 (k = 1e12). The reference takes each hump's top at
// S(t_j) + W (t_j where the cosine is 1; S moves the top by S'^2 / (2 W
// w_n^2) ~ 1e-37), the first one above 0, and bisects the rising half
// period before it, in long double. (Issue 9: the event search's step cap
// stopped this slip; with the cap sized to the span, the stop at 1e12 came
// five periods late, the first humps taken for touches within a rounding
// bound that carried G's argument rounding on each of the terms that cancel.)
struct StiffSlip {
  long double k, t_b, wn, a, c, w, phi;
  StiffSlip(long double k_, long double t_b_, long double x_s)
      : k(k_), t_b(t_b_), wn(std::sqrt(k_)) {
    a = x_s - (std::sin(t_b) / (k - 1) + 0.3L / k);
    c = -std::cos(t_b) / ((k - 1) * wn);
    w = wn * std::hypot(a, c);
    phi = std::atan2(a, c);
  }
  long double slow(long double t) const { return std::cos(t) / (k - 1); }
  long double v(long double t) const { return slow(t) + w * std::cos(wn * (t - t_b) + phi); }
  long double first_stop() const {
    const long double two_pi = 6.28318530717958647692528676655900577L;
    for (long double j = 1; j < 1e7; ++j) {
      const long double top = t_b + (two_pi * j - phi) / wn;
      if (slow(top) + w < 0) continue;
      long double lo = top - two_pi / (2 * wn), hi = top;  // v rises from < 0 to > 0
      for (int i = 0; i < 200; ++i) {
        const long double mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        (v(mid) < 0 ? lo : hi) = mid;
      }
      return hi;
    }
    return std::numeric_limits<long double>::quiet_NaN();  // no stop in 1e7 periods
  }
};

TEST(GeneralEngine, StiffSpringSlipRingsThroughTenThousandNaturalPeriods) {
  for (const double k : {1e10, 1e12}) {
    // At rest at x_s = 0.7 / k from t = 2 (N = sin 2 - 0.7 inside the band),
    // as after the forward slip that ends near pi / 2, without its chatter.
    Model m;
    m.mass = 1;
    m.stiffness = k;
    m.friction = 0.3;
    m.x0 = 0.7 / k;
    m.t0 = 2;
    ExactEngine engine(m, 3.6);
    Phase stick, p;
    ASSERT_TRUE(engine.next(stick) && engine.next(p)) << k << ": " << engine.summary().message;
    ASSERT_EQ(stick.kind, PhaseKind::stick) << k;
    const long double x_s = stick.x_end;
    const long double t_b = pi - std::asin(static_cast<long double>(k) * x_s - 0.3L);
    EXPECT_LE(ulps(stick.t_end, t_b), 64) << k << ": " << stick.t_end;
    ASSERT_EQ(p.kind, PhaseKind::slip_backward) << k;
    const long double stop = StiffSlip(k, stick.t_end, x_s).first_stop();
    EXPECT_LE(ulps(p.t_end, stop), 8)
        << k << ": " << p.t_end << " vs " << static_cast<double>(stop);
    EXPECT_NEAR(k * p.x_end, std::sin(p.t_end) + 0.3, 4 / std::sqrt(k)) << k;
  }
}

}  // namespace
}  // namespace frictionref
