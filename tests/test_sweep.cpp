// The lambda sweep (sweep.hpp): the regime found by simulation against the
// regime from the threshold lambda*, the measured figures against the
// closed-form steady state (steady_state.hpp), the window's phase, the grid,
// determinism over thread counts, progress, and bad input.
//
// Where the two regimes may differ, and why (docs/cli.md, "sweep"): only for
// 0 < lambda - lambda* <= d(P) = 8 eps (2 pi P + pi/2) / 4.1104, about
// 2.72e-15 P. There the dead band, 4.1104 (lambda - lambda*) rad long
// (theory.md 5.6), is shorter than the engine's time resolution 8 eps |w t|
// (theory.md 4.1) at the end of the run, and the engine shows the stop and
// the breakaway after it as one reversal. The distance grows linearly with P
// because the resolution is relative to |w t|. It is not a long transient:
// above lambda* the motion is periodic from the first breakaway (theory.md
// 5.6), and below it the reversal map contracts by |kappa| = (sin tau1 -
// lambda) / (sin tau1 + lambda), which tends to 0 at lambda*. The slow
// transient is at small lambda (|kappa| -> 1, decay ~ exp(-4 lambda P)),
// where it changes the slide per period but never the regime: the mass does
// not come to rest there.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/sweep.hpp"

namespace frictionref {
namespace {

using testing::expect_invalid;

const double kLambdaStar = regime_threshold();
const double kPi = boost::math::double_constants::pi;

// 8 eps (2 pi P + pi/2) / 4.1104, written out (the documented distance).
double documented_distance(double periods) {
  const double pi = boost::math::double_constants::pi;
  return 8 * 0x1p-52 * (2 * pi * periods + pi / 2) / 4.1104;
}

SteadyState closed_form(double lambda) {
  Model model;
  model.friction = lambda;
  return steady_state(model);
}

SweepOptions with_periods(std::uint64_t periods) {
  SweepOptions options;
  options.periods = periods;
  return options;
}

// The grid of the agreement test: 2401 lambdas over [0, 1.2], plus lambdas
// crowded around lambda* (ulps and decades on both sides, and the window's
// own scale) and around 0 and 1.
std::vector<double> agreement_lambdas(double window) {
  std::vector<double> lambdas;
  for (int i = 0; i <= 2400; ++i) lambdas.push_back(1.2 * i / 2400);
  for (double anchor : {kLambdaStar, 1.0}) {
    double below = anchor, above = anchor;
    for (int k = 0; k < 8; ++k) {
      lambdas.push_back(below = std::nextafter(below, 0.0));
      lambdas.push_back(above = std::nextafter(above, 2.0));
    }
    lambdas.push_back(anchor);
  }
  for (int j = 2; j <= 16; ++j) {
    for (double m : {1.0, 3.0}) {
      lambdas.push_back(kLambdaStar - m * std::pow(10.0, -j));
      lambdas.push_back(kLambdaStar + m * std::pow(10.0, -j));
    }
  }
  for (double f : {0.25, 0.5, 0.9, 1.1, 2.0, 4.0}) lambdas.push_back(kLambdaStar + f * window);
  for (double tiny : {5e-324, 1e-300, 1e-16, 1e-8}) lambdas.push_back(tiny);
  std::sort(lambdas.begin(), lambdas.end());
  lambdas.erase(std::unique(lambdas.begin(), lambdas.end()), lambdas.end());
  return lambdas;
}

// ---- the simulated regime against the threshold ----------------------------

TEST(SweepRegimes, AgreeOnAFineGridExceptJustAboveLambdaStar) {
  for (std::uint64_t periods : {1u, 20u}) {
    SCOPED_TRACE(periods);
    const double window = sweep_unresolved_distance(periods);
    const std::vector<double> lambdas = agreement_lambdas(window);
    ASSERT_GT(lambdas.size(), 2400u + 90u);
    const std::vector<SweepPoint> points = sweep(lambdas, with_periods(periods));
    std::size_t differ = 0;
    for (const SweepPoint& p : points) {
      ASSERT_EQ(p.termination, Termination::reached_end) << p.lambda;
      if (p.regimes_agree()) continue;
      ++differ;
      // Confined to the documented window, and of the documented kind. The
      // double nearest lambda* lies above the exact value (...1513 against
      // ...150769), so it is the first double in the window.
      EXPECT_GE(p.lambda, kLambdaStar) << p.lambda;
      EXPECT_LE(p.lambda - kLambdaStar, window) << p.lambda;
      EXPECT_EQ(p.regime_simulated, Regime::continuous) << p.lambda;
      EXPECT_EQ(p.regime_threshold, Regime::dead_bands) << p.lambda;
      EXPECT_EQ(p.reversals_per_period, 2u) << p.lambda;  // the merged dead bands
    }
    // The window is not empty: lambda* itself (the double above the exact
    // value) and the 8 doubles above it fall there.
    EXPECT_GE(differ, 9u);
  }
}

TEST(SweepRegimes, TheWindowIsTheEngineTimeResolutionAndGrowsWithThePeriods) {
  for (std::uint64_t periods : {10u, 100u, 1000u}) {
    SCOPED_TRACE(periods);
    const double d = sweep_unresolved_distance(periods);
    EXPECT_DOUBLE_EQ(d, documented_distance(static_cast<double>(periods)));
    // Inside: the dead band is below the resolution and shows as reversals.
    const SweepPoint inside = sweep_point(kLambdaStar + d / 2, with_periods(periods));
    EXPECT_EQ(inside.regime_simulated, Regime::continuous);
    EXPECT_EQ(inside.reversals_per_period, 2u);
    // Twice as far: resolved, two dead bands of 4.1104 (lambda - lambda*) rad each.
    const double lambda = kLambdaStar + 2 * d;
    const SweepPoint outside = sweep_point(lambda, with_periods(periods));
    EXPECT_EQ(outside.regime_simulated, Regime::dead_bands);
    EXPECT_EQ(outside.stops_per_period, 2u);
    EXPECT_EQ(outside.reversals_per_period, 0u);
    const double expected = 2 * 4.1104 * (lambda - kLambdaStar) / (2 * kPi);
    // Sticks of a few ulps of t: only the order of magnitude is resolved.
    EXPECT_NEAR(outside.stuck_fraction, expected, 0.25 * expected);
  }
  // Measured (2026-11-21): the last lambda that differs is lambda* + 2.70e-13
  // for 100 periods, 2.71e-12 for 1000, 2.60e-14 for 10, 1.44e-15 for 1.
  EXPECT_NEAR(sweep_unresolved_distance(100), 2.72e-13, 0.01e-13);
}

TEST(SweepRegimes, BelowLambdaStarEvenOnePeriodIsEnough) {
  // Just below lambda* the approach to the continuous steady state is
  // fastest (kappa -> 0): a single period already shows it, to the last ulp.
  double lambda = kLambdaStar;
  for (int k = 0; k < 20; ++k) {
    lambda = std::nextafter(lambda, 0.0);
    const SweepPoint p = sweep_point(lambda, with_periods(1));
    EXPECT_EQ(p.regime_simulated, Regime::continuous) << lambda;
    EXPECT_EQ(p.reversals_per_period, 2u) << lambda;
    EXPECT_EQ(p.stuck_fraction, 0) << lambda;
  }
}

// ---- the figures against the closed-form steady state ----------------------

TEST(SweepPoint, MatchesTheClosedFormSteadyStateAwayFromLambdaStar) {
  const std::uint64_t periods = 100;
  std::vector<double> lambdas;
  for (int i = 4; i <= 240; ++i) lambdas.push_back(0.005 * i);  // 0.02 ... 1.2
  const std::vector<SweepPoint> points = sweep(lambdas, with_periods(periods));
  for (const SweepPoint& p : points) {
    SCOPED_TRACE(p.lambda);
    const SteadyState s = closed_form(p.lambda);
    EXPECT_EQ(p.regime_simulated, s.regime);
    EXPECT_NEAR(p.stuck_fraction, s.stuck_fraction, 1e-12);
    EXPECT_EQ(p.stops_per_period, s.stops_per_period);
    EXPECT_EQ(p.reversals_per_period, s.regime == Regime::continuous ? 2u : 0u);
    const double slide = 2 * s.slide_per_half_period;
    if (s.regime == Regime::stops) {
      EXPECT_EQ(p.slide_per_period, 0);
    } else {
      // The continuous transient decays like |kappa|^(2 P) ~ exp(-4 lambda P).
      const double tolerance = std::max(1e-9, std::exp(-4 * p.lambda * periods));
      EXPECT_NEAR(p.slide_per_period, slide, tolerance * slide);
    }
  }
}

TEST(SweepPoint, SeedCasesToTheDigitsOfTheTheoryTable) {
  // theory.md 5.8 (mpmath): lambda 0.3 slides 1.76401122556 per half period;
  // lambda 0.7 sticks 0.221920695194 of the period and slides 0.432493939724.
  const SweepPoint continuous = sweep_point(0.3, SweepOptions{});
  EXPECT_EQ(continuous.regime_simulated, Regime::continuous);
  EXPECT_NEAR(continuous.slide_per_period, 2 * 1.76401122556, 1e-10);
  EXPECT_EQ(continuous.stuck_fraction, 0);
  EXPECT_EQ(continuous.stops_per_period, 0u);
  EXPECT_EQ(continuous.reversals_per_period, 2u);
  const SweepPoint dead = sweep_point(0.7, SweepOptions{});
  EXPECT_EQ(dead.regime_simulated, Regime::dead_bands);
  EXPECT_NEAR(dead.stuck_fraction, 0.221920695194, 1e-12);
  EXPECT_NEAR(dead.slide_per_period, 2 * 0.432493939724, 1e-11);
  EXPECT_EQ(dead.stops_per_period, 2u);
  EXPECT_EQ(dead.reversals_per_period, 0u);
}

TEST(SweepPoint, SmallLambdaTransientIsSlowButTheRegimeIsRight) {
  // lambda = 0.01: |kappa|^(2 P) is 0.018 after 100 periods and 4e-18 after 1000.
  const double slide = 2 * closed_form(0.01).slide_per_half_period;
  const SweepPoint short_run = sweep_point(0.01, with_periods(100));
  const SweepPoint long_run = sweep_point(0.01, with_periods(1000));
  EXPECT_EQ(short_run.regime_simulated, Regime::continuous);
  EXPECT_GT(std::fabs(short_run.slide_per_period / slide - 1), 1e-4);
  EXPECT_NEAR(long_run.slide_per_period, slide, 1e-12 * slide);
}

TEST(SweepPoint, StopsAreCountedOnceWhereTheStopIsAtAMultipleOfPi) {
  // Near lambda_pi ~ 0.7246 the forward stop lies at w t = pi (and the
  // backward one at 2 pi): a window from 2 pi k to 2 pi (k + 1) would count
  // the backward stop at both ends or at neither, within rounding. The window
  // runs from force maximum to force maximum, where no steady-state event lies.
  double lo = 0.7, hi = 0.75;  // stop phase > pi at lo, < pi at hi
  while (std::nextafter(lo, hi) < hi) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    (closed_form(mid).stop_phase > kPi ? lo : hi) = mid;
  }
  std::vector<double> lambdas;
  double below = lo, above = lo;
  for (int k = 0; k < 100; ++k) {
    lambdas.push_back(below = std::nextafter(below, 0.0));
    lambdas.push_back(above = std::nextafter(above, 1.0));
  }
  for (std::uint64_t periods : {1u, 7u, 20u}) {
    for (const SweepPoint& p : sweep(lambdas, with_periods(periods))) {
      EXPECT_EQ(p.stops_per_period, 2u) << p.lambda << " " << periods;
      EXPECT_EQ(p.reversals_per_period, 0u) << p.lambda << " " << periods;
    }
  }
}

TEST(SweepPoint, StopsRegimeAndTheInitialVelocity) {
  // At rest from the start, or after the initial slide.
  for (double v0 : {0.0, -1.0, 2.5}) {
    SweepOptions options;
    options.v0 = v0;
    const SweepPoint p = sweep_point(1.1, options);
    EXPECT_EQ(p.regime_simulated, Regime::stops) << v0;
    EXPECT_EQ(p.stuck_fraction, 1) << v0;
    EXPECT_EQ(p.slide_per_period, 0) << v0;
  }
  // lambda = 1 exactly: the force only touches R, the mass never moves.
  EXPECT_EQ(sweep_point(1.0, SweepOptions{}).regime_simulated, Regime::stops);
  // A slide whose stop comes inside the measured period: the period ends at
  // rest with no breakaway, so the mass has stopped for good.
  SweepOptions one;
  one.periods = 1;
  one.v0 = 3;  // v = 3 + 1 - cos t - 1.1 t: stops at t = 2.28
  const SweepPoint late = sweep_point(1.1, one);
  EXPECT_EQ(late.regime_simulated, Regime::stops);
  EXPECT_EQ(late.stops_per_period, 1u);
  EXPECT_GT(late.slide_per_period, 0);
  EXPECT_LT(late.stuck_fraction, 1);
  // An initial slide that outlasts the run (at most (|v0| + 2) / lambda rad,
  // theory.md 3.3): the measured period shows that slide, not the steady
  // state. This is the documented limit of the comparison for large |v0|.
  SweepOptions fast;
  fast.periods = 10;
  fast.v0 = 1000;
  const SweepPoint sliding = sweep_point(1.1, fast);
  EXPECT_EQ(sliding.regime_simulated, Regime::continuous);
  EXPECT_EQ(sliding.regime_threshold, Regime::stops);
}

TEST(SweepPoint, NoFrictionDriftsWithoutStops) {
  // R = 0 from rest: v = 1 - cos t >= 0 touches zero at 2 pi k (no stops,
  // no reversals) and slides 2 pi per period; the symmetric steady state
  // (v = -cos t, 4 per period) needs v0 = -1.
  const SweepPoint drift = sweep_point(0, SweepOptions{});
  EXPECT_EQ(drift.regime_simulated, Regime::continuous);
  EXPECT_EQ(drift.stops_per_period + drift.reversals_per_period, 0u);
  EXPECT_NEAR(drift.slide_per_period, 2 * kPi, 1e-12);
  SweepOptions symmetric;
  symmetric.v0 = -1;
  const SweepPoint periodic = sweep_point(0, symmetric);
  EXPECT_EQ(periodic.reversals_per_period, 2u);
  EXPECT_NEAR(periodic.slide_per_period, 4, 1e-12);
}

// ---- window, grid ----------------------------------------------------------

TEST(SweepWindow, FromForceMaximumToForceMaximum) {
  const double pi = boost::math::double_constants::pi;
  EXPECT_EQ(sweep_window(1).begin, pi / 2);
  EXPECT_DOUBLE_EQ(sweep_window(1).end, 2 * pi + pi / 2);
  const SweepWindow w = sweep_window(100);
  EXPECT_NEAR(w.begin, 99 * 2 * pi + pi / 2, 1e-12);
  EXPECT_NEAR(w.end, 100 * 2 * pi + pi / 2, 1e-12);
  EXPECT_NEAR(std::sin(w.end), 1, 1e-15);
  EXPECT_EQ(expect_invalid([] { sweep_window(0); }).parameter(), "periods");
}

TEST(SweepGrid, EvenlySpacedWithExactEnds) {
  const std::vector<double> grid = sweep_grid(0, 1.2, 13);
  ASSERT_EQ(grid.size(), 13u);
  EXPECT_EQ(grid.front(), 0);
  EXPECT_EQ(grid.back(), 1.2);
  for (std::size_t i = 1; i < grid.size(); ++i) EXPECT_NEAR(grid[i] - grid[i - 1], 0.1, 1e-15);
  // Decimal ends in long double: every point is the double nearest i / 10.
  const std::vector<double> decimal = sweep_grid(0, 1.2L, 13);
  for (std::size_t i = 0; i < decimal.size(); ++i)
    EXPECT_EQ(decimal[i], static_cast<double>(i) / 10) << i;
  // With the double 1.2 (just below 1.2) the fifth of seven is below 0.8.
  EXPECT_EQ(sweep_grid(0, 1.2, 7)[4], 0.7999999999999999);
  EXPECT_EQ(sweep_grid(0, 1.2L, 7)[4], 0.8);
  EXPECT_EQ(sweep_grid(0, 1.2L, 7)[5], 1.0);
  EXPECT_EQ(sweep_grid(0.7, 0.7, 1), std::vector<double>{0.7});
  EXPECT_EQ(sweep_grid(0.5, 0.6, 2), (std::vector<double>{0.5, 0.6}));
}

TEST(SweepGrid, RefusesWhatIsNotAGrid) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expect_invalid([&] { sweep_grid(nan, 1, 3); }).parameter(), "lambda_from");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(-0.1, 1, 3); }).parameter(), "lambda_from");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(0, HUGE_VAL, 3); }).parameter(), "lambda_to");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(0.5, 0.4, 3); }).parameter(), "lambda_to");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(0, 1, 0); }).parameter(), "points");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(0, 1, 1); }).parameter(), "points");
  EXPECT_EQ(expect_invalid([&] { sweep_grid(1, 1, 2); }).parameter(), "points");
  const InvalidInput repeat = expect_invalid([&] { sweep_grid(0.5, std::nextafter(0.5, 1.0), 5); });
  EXPECT_EQ(repeat.parameter(), "points");
  EXPECT_NE(repeat.rule().find("repeat"), std::string::npos);
}

TEST(SweepOptions, Validate) {
  SweepOptions options;
  options.periods = 0;
  EXPECT_EQ(expect_invalid([&] { options.validate(); }).parameter(), "periods");
  options.periods = SweepOptions::max_periods + 1;
  EXPECT_EQ(expect_invalid([&] { options.validate(); }).parameter(), "periods");
  options.periods = 1;
  options.v0 = std::numeric_limits<double>::infinity();
  EXPECT_EQ(expect_invalid([&] { options.validate(); }).parameter(), "v0");
  EXPECT_EQ(expect_invalid([] { sweep_point(-1, SweepOptions{}); }).parameter(), "lambda");
  EXPECT_EQ(expect_invalid([] {
              sweep({0.3, std::nan("")}, SweepOptions{});
            }).parameter(),
            "lambda");
  // The engine's own refusal (motion beyond the range of double) comes
  // before any thread starts.
  SweepOptions huge;
  huge.v0 = 1e299;
  EXPECT_EQ(expect_invalid([&] { sweep({0.3}, huge); }).parameter(), "t_end");
}

// ---- parallel run ------------------------------------------------------------

TEST(Sweep, SameResultsInLambdaOrderForAnyNumberOfThreads) {
  const std::vector<double> lambdas = sweep_grid(0, 1.2, 301);
  SweepOptions options;
  options.periods = 10;
  options.v0 = 0.25;
  options.threads = 1;
  const std::vector<SweepPoint> one = sweep(lambdas, options);
  ASSERT_EQ(one.size(), lambdas.size());
  for (unsigned threads : {2u, 3u, 7u, 0u}) {
    options.threads = threads;
    const std::vector<SweepPoint> many = sweep(lambdas, options);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
      SCOPED_TRACE(i);
      EXPECT_EQ(many[i].lambda, lambdas[i]);
      EXPECT_EQ(many[i].lambda, one[i].lambda);
      EXPECT_EQ(many[i].stuck_fraction, one[i].stuck_fraction);  // bit for bit
      EXPECT_EQ(many[i].slide_per_period, one[i].slide_per_period);
      EXPECT_EQ(many[i].stops_per_period, one[i].stops_per_period);
      EXPECT_EQ(many[i].reversals_per_period, one[i].reversals_per_period);
      EXPECT_EQ(many[i].regime_simulated, one[i].regime_simulated);
      EXPECT_EQ(many[i].regime_threshold, one[i].regime_threshold);
    }
  }
  // And the same as one point at a time.
  options.threads = 2;
  const SweepPoint alone = sweep_point(lambdas[123], options);
  EXPECT_EQ(alone.slide_per_period, one[123].slide_per_period);
  EXPECT_EQ(alone.stuck_fraction, one[123].stuck_fraction);
}

TEST(Sweep, ProgressIsReportedOnTheCallingThreadAndEndsComplete) {
  const std::vector<double> lambdas = sweep_grid(0.6, 0.9, 400);
  SweepOptions options;
  options.periods = 500;  // long enough (> 0.1 s) for progress calls during the run
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> seen;
  bool elsewhere = false;
  sweep(lambdas, options, [&](std::size_t done, std::size_t total) {
    elsewhere |= std::this_thread::get_id() != caller;
    EXPECT_EQ(total, lambdas.size());
    seen.push_back(done);
  });
  EXPECT_FALSE(elsewhere);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), lambdas.size());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_TRUE(sweep({}, options).empty());
}

TEST(Sweep, AnExceptionFromTheProgressCallbackStopsTheWorkers) {
  const std::vector<double> lambdas = sweep_grid(0.6, 0.9, 2000);
  SweepOptions options;
  options.periods = 1000;  // ~0.8 s of work: the first progress call (0.1 s) comes mid-run
  EXPECT_THROW(
      sweep(lambdas, options, [](std::size_t, std::size_t) { throw std::runtime_error("stop"); }),
      std::runtime_error);
}

}  // namespace
}  // namespace frictionref
