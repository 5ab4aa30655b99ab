// The seed problem's three cases (m = B = w = 1; THEORY.md "Seed cases"),
// checked against the facts the seed states and against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "frictionref/frictionref.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

using testing::seed_model;

const double kPi = 3.141592653589793;


// Case 10.1, lambda = 0.3 from rest: stuck until the force first reaches R
// (closed form asin(0.3)), then slides for ever with direct reversals.
TEST(SeedCases, Lambda03NoStopAfterTheStart) {
  const Solution s = solve(seed_model(0.3, 0), 200.0);
  testing::expect_well_formed(s, 200.0);
  ASSERT_GE(s.phases.size(), 3u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
  EXPECT_EQ(s.phases[0].t_end, std::asin(0.3));  // asin is correctly rounded enough: 0.5 ulp
  for (std::size_t i = 1; i < s.phases.size(); ++i) {
    EXPECT_NE(s.phases[i].kind, PhaseKind::stick) << "phase " << i;
  }
  EXPECT_EQ(s.summary.count(PhaseKind::stick), 1u);
  EXPECT_EQ(s.summary.reversals, s.summary.stops);
  EXPECT_EQ(steady_state(s.model).regime, Regime::continuous);
}

// The transient: slip durations converge to pi, the deviation changing sign
// and roughly halving every half period (THEORY.md).
TEST(SeedCases, Lambda03SlipDurationsConvergeToPi) {
  const Solution s = solve(seed_model(0.3, 0), 60.0);
  double previous = 0;
  for (std::size_t i = 2; i + 1 < s.phases.size(); ++i) {
    const double deviation = s.phases[i].duration() - kPi;
    if (i > 2 && std::fabs(previous) > 1e-6) {
      EXPECT_LT(deviation * previous, 0) << "phase " << i;  // alternates
      EXPECT_LT(std::fabs(deviation), 0.75 * std::fabs(previous)) << "phase " << i;
      EXPECT_GT(std::fabs(deviation), 0.25 * std::fabs(previous)) << "phase " << i;
    }
    previous = deviation;
  }
}

// Case 10.2, lambda = 0.7 from rest: dead bands, two stops per period, each
// stick ending at a closed-form breakaway time.
TEST(SeedCases, Lambda07TwoStopsPerPeriod) {
  const double periods = 50;
  const Solution s = solve(seed_model(0.7, 0), periods * 2 * kPi);
  testing::expect_well_formed(s, periods * 2 * kPi);
  const double alpha = std::asin(0.7);
  int sticks_after_first_breakaway = 0;
  for (std::size_t i = 0; i + 1 < s.phases.size(); ++i) {
    const Phase& p = s.phases[i];
    if (p.kind != PhaseKind::stick) continue;
    // A stick ends at alpha + 2 pi k (forward) or pi + alpha + 2 pi k (backward).
    const double phase = std::remainder(p.t_end - alpha, kPi);
    EXPECT_NEAR(phase, 0, 1e-12 * (1 + p.t_end)) << "stick " << i << " ends at " << p.t_end;
    const PhaseKind expected = std::remainder(p.t_end - alpha, 2 * kPi) == phase
                                   ? PhaseKind::slip_forward
                                   : PhaseKind::slip_backward;
    EXPECT_EQ(s.phases[i + 1].kind, expected);
    if (i > 0) ++sticks_after_first_breakaway;
  }
  // Periodic from the first breakaway: stick, slip+, stick, slip- per period.
  EXPECT_NEAR(sticks_after_first_breakaway, 2 * periods, 1);
  EXPECT_EQ(s.summary.reversals, 0u);
  EXPECT_EQ(steady_state(s.model).regime, Regime::dead_bands);
}

// Case 10.3, lambda = 1.01 with v0 = -1: one backward slide, then stuck for
// ever. The stop solves v = -1 + (1 - cos t) + 1.01 t = 0, i.e.
// cos(t) = 1.01 t, whose only root in (0, 1) we check by its residual and
// by bisection in long double (a different method from the engine's).
TEST(SeedCases, Lambda101StopsForGood) {
  const Solution s = solve(seed_model(1.01, -1), 1000.0);
  testing::expect_well_formed(s, 1000.0);
  ASSERT_EQ(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_backward);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::stick);
  long double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const long double mid = (lo + hi) / 2;
    (std::cos(mid) - 1.01L * mid > 0 ? lo : hi) = mid;
  }
  const double stop = static_cast<double>(lo);
  EXPECT_NEAR(s.phases[0].t_end, stop, 4 * std::nextafter(stop, 2.0) - 4 * stop);
  // x at the stop: x = -t + t - sin t ... in closed form
  // x(t) = (v0 + cos 0) t - sin t + 1.01 t^2 / 2 with v0 = -1.
  const long double t = lo;
  const double x_stop = static_cast<double>(-std::sin(t) + 1.01L * t * t / 2);
  EXPECT_NEAR(s.phases[0].x_end, x_stop, 1e-15);
  EXPECT_EQ(steady_state(s.model).regime, Regime::stops);
}

}  // namespace
}  // namespace frictionref

namespace frictionref {
namespace {

// Either side of the exact threshold lambda* = 2/sqrt(4 + pi^2) (mpmath
// literal), 1e-9 away: above, a dead band of ~4.11 (lambda - lambda*) rad
// (docs/theory.md 5.6) in every half period after the first breakaway;
// below, once the transient has died out, no stick at all.
TEST(SeedCases, RegimesAtTheThresholdPlusMinus1e9) {
  const double lambda_star = 0.53702927214631507685;
  const double periods = 200;
  const double t_end = periods * 2 * kPi;

  const Solution above = solve(seed_model(lambda_star + 1e-9, 0), t_end);
  testing::expect_well_formed(above, t_end);
  EXPECT_EQ(steady_state(above.model).regime, Regime::dead_bands);
  EXPECT_NEAR(static_cast<double>(above.summary.count(PhaseKind::stick)), 2 * periods, 1);
  for (std::size_t i = 1; i + 1 < above.phases.size(); ++i) {
    const Phase& p = above.phases[i];
    if (p.kind != PhaseKind::stick) continue;
    EXPECT_NEAR(p.duration(), 4.1104e-9, 0.05e-9) << "stick " << i << " at " << p.t_begin;
  }

  const Solution below = solve(seed_model(lambda_star - 1e-9, 0), t_end);
  testing::expect_well_formed(below, t_end);
  EXPECT_EQ(steady_state(below.model).regime, Regime::continuous);
  for (const Phase& p : below.phases) {
    if (p.t_begin > 50 * 2 * kPi) {
      EXPECT_NE(p.kind, PhaseKind::stick) << "stick at " << p.t_begin;
    }
  }
  std::printf("lambda* - 1e-9: %llu sticks in %g periods, last ends at t = %.6g\n",
              static_cast<unsigned long long>(below.summary.count(PhaseKind::stick)), periods,
              [&] {
                double last = 0;
                for (const Phase& p : below.phases)
                  if (p.kind == PhaseKind::stick) last = p.t_end;
                return last;
              }());
}

}  // namespace
}  // namespace frictionref
