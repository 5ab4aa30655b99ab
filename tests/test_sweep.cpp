// The lambda sweep (sweep.hpp): the regime found by simulation against the
// regime from the threshold lambda*, the measured figures against the steady
// state computed in high precision (tests/steady_state_values.py), the
// general model against what is known of it in closed form (Den Hartog's
// non-stop boundary, an equilibrium inside the stick band, a constant force
// without spring), the window's phase, the grid, determinism over thread
// counts, progress, and bad input.
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

// (4 + pi^2)^(3/2) / (4 pi): the dead band per half period per unit of
// lambda - lambda* just above lambda* (theory.md 5.6), by mpmath
// (tests/steady_state_values.py).
constexpr double kBandPerLambda = 4.1104204438246365818;

// The literal values of the seed's steady state (m = B = w = 1), by mpmath at
// 50 digits from theory.md 5's closed forms: tests/steady_state_values.py.
struct SeedRow {
  double lambda;
  Regime regime;
  long double stuck_fraction, slide_per_period;
};
const SeedRow kSeedTable[] = {
    {0.1, Regime::continuous, 0.0L, 3.950343760225991473127607L},
    {0.2, Regime::continuous, 0.0L, 3.797481177810589549896541L},
    {0.3, Regime::continuous, 0.0L, 3.528022451120149994927603L},
    {0.4, Regime::continuous, 0.0L, 3.111824735312515922843368L},
    {0.5, Regime::continuous, 0.0L, 2.475963569786648008136887L},
    {0.53, Regime::continuous, 0.0L, 2.215967620461994823875808L},
    {0.536, Regime::continuous, 0.0L, 2.158242001245116430464653L},
    {0.5365, Regime::continuous, 0.0L, 2.153331891394865959794599L},
    {0.54, Regime::dead_bands, 0.003888379636287280880439038L, 2.118911024152492708914567L},
    {0.55, Regime::dead_bands, 0.01700109364174256825145452L, 2.022263889263545926673413L},
    {0.6, Regime::dead_bands, 0.08328223465645307713048598L, 1.576744217496152686775433L},
    {0.65, Regime::dead_bands, 0.1512973766230828056270187L, 1.191890668007591314697775L},
    {0.7, Regime::dead_bands, 0.2219206951943889800486521L, 0.8649878794475476343042898L},
    {0.7246, Regime::dead_bands, 0.2579638330595656847716198L, 0.7246730530952064212840654L},
    {0.75, Regime::dead_bands, 0.2963198067679691965994018L, 0.5936135612396032973184968L},
    {0.8, Regime::dead_bands, 0.3762053505759655720703666L, 0.3755890452409234587737226L},
    {0.9, Regime::dead_bands, 0.5662508066095589066364563L, 0.09187035215496861225877989L},
    {0.95, Regime::dead_bands, 0.6957109084527421368944831L, 0.02272928450335581915146284L},
    {0.99, Regime::dead_bands, 0.8647491251943089263880211L, 0.0009018067188202626092989075L},
    {1.0, Regime::stops, 1.0L, 0.0L},
    {1.01, Regime::stops, 1.0L, 0.0L},
    {1.2, Regime::stops, 1.0L, 0.0L},
};

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
  // The last lambda above lambda* that still differs, measured by bisection
  // on lambda (docs/cli.md, 2026-11-21): the documented distance must bound
  // it, and tightly (the first dead band of the measured period decides,
  // where |w t| is a little below the end of the run).
  struct Measured {
    std::uint64_t periods;
    double last_differing;
  };
  for (const Measured m : {Measured{10, 2.60e-14}, Measured{100, 2.703e-13},
                           Measured{1000, 2.714e-12}}) {
    SCOPED_TRACE(m.periods);
    const double d = sweep_unresolved_distance(m.periods);
    EXPECT_GE(d, m.last_differing);
    EXPECT_LE(d, 1.1 * m.last_differing);
    // Inside: the dead band is below the resolution and shows as reversals.
    const SweepPoint inside = sweep_point(kLambdaStar + d / 2, with_periods(m.periods));
    EXPECT_EQ(inside.regime_simulated, Regime::continuous);
    EXPECT_EQ(inside.reversals_per_period, 2u);
    // Twice as far: resolved, two dead bands per period.
    const double lambda = kLambdaStar + 2 * d;
    const SweepPoint outside = sweep_point(lambda, with_periods(m.periods));
    EXPECT_EQ(outside.regime_simulated, Regime::dead_bands);
    EXPECT_EQ(outside.stops_per_period, 2u);
    EXPECT_EQ(outside.reversals_per_period, 0u);
    // Each band lasts kBandPerLambda (lambda - lambda*) to first order. The
    // double lambda* lies 5.18e-17 above the exact value (mpmath).
    const double excess = (lambda - kLambdaStar) + 5.18e-17;
    const double expected = 2 * kBandPerLambda * excess / (2 * kPi);
    // Sticks of a few ulps of t: only the order of magnitude is resolved.
    EXPECT_NEAR(outside.stuck_fraction, expected, 0.25 * expected);
  }
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

// Against the mpmath values of kSeedTable. Stuck fraction: the time at rest
// is a sum of differences of event times near |w t| = 2 pi P, each within 1
// ulp of t (docs/accuracy.md: 0.5005), so it is good to 4 ulp(t_end) per band
// edge pair, over 2 pi. Slide: a sum of differences of positions, which stay
// within a few units here; 1e-13 absolute is about 64 ulps of |x| <= 4, plus
// the continuous transient, which decays like |kappa|^(2 P) ~ exp(-4 lambda P)
// (below 1e-17 for lambda >= 0.1 and P = 100).
TEST(SweepPoint, MatchesTheSteadyStateComputedInHighPrecision) {
  const std::uint64_t periods = 100;
  std::vector<double> lambdas;
  for (const SeedRow& row : kSeedTable) lambdas.push_back(row.lambda);
  const std::vector<SweepPoint> points = sweep(lambdas, with_periods(periods));
  const double end = sweep_window(periods).end;
  const double time_ulp = std::nextafter(end, 2 * end) - end;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SweepPoint& p = points[i];
    const SeedRow& row = kSeedTable[i];
    SCOPED_TRACE(row.lambda);
    EXPECT_EQ(p.lambda, row.lambda);
    EXPECT_EQ(p.regime_simulated, row.regime);
    EXPECT_EQ(p.regime_threshold, row.regime);
    EXPECT_EQ(p.threshold_rule, SweepThreshold::lambda_star);
    EXPECT_NEAR(p.stuck_fraction, static_cast<double>(row.stuck_fraction), 8 * time_ulp / (2 * kPi));
    EXPECT_NEAR(p.slide_per_period, static_cast<double>(row.slide_per_period), 1e-13);
    EXPECT_EQ(p.stops_per_period, row.regime == Regime::dead_bands ? 2u : 0u);
    EXPECT_EQ(p.reversals_per_period, row.regime == Regime::continuous ? 2u : 0u);
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
  // lambda = 0.01: |kappa|^(2 P) is 0.018 after 100 periods and 4e-18 after
  // 1000. Steady slide per period 4 sin(tau1), cos(tau1) = lambda pi / 2
  // (theory.md 5.4), here in long double.
  const long double c = 0.01L * 3.14159265358979323846264338327950288L / 2;
  const double slide = static_cast<double>(4 * std::sqrt(1 - c * c));
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
  // lambda_pi: v = 0 at w t = pi after the breakaway at asin(lambda), i.e.
  // f(lambda) = cos(a) + 1 - lambda (pi - a) = 0 with a = asin(lambda)
  // (theory.md 5.6); f > 0 at 0.7 (stop after pi), < 0 at 0.75. Bisection
  // in long double, here.
  const auto f = [](long double lambda) {
    const long double a = std::asin(lambda);
    return std::cos(a) + 1 - lambda * (3.14159265358979323846264338327950288L - a);
  };
  double lo = 0.7, hi = 0.75;
  while (std::nextafter(lo, hi) < hi) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    (f(mid) > 0 ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo, 0.7246, 1e-4);
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

// ---- the general model -------------------------------------------------------

SweepOptions general(double stiffness, double omega, double static_ratio = 1) {
  SweepOptions options;
  options.base.stiffness = stiffness;
  options.base.omega = omega;
  options.static_ratio = static_ratio;
  return options;
}

TEST(SweepGeneral, DenHartogsNonStopBoundaryOfASpringWithoutDamper) {
  // m = B = k = 1, w = 2: beta = 2. Den Hartog's non-stop solution exists for
  // lambda < 2/3, and the mass leaves at once at each reversal iff
  // lambda < (4/3) / sqrt(4 + S^2), Rs = S R (theory.md 8.2; worked out in
  // tests/steady_state_values.py): 4 / (3 sqrt 5) for S = 1, 8/15 for
  // S = 1.5. Below it the motion is non-stop; above it there are stops (and
  // no motion at all where Rs = S lambda B >= B: the mass starts at rest at
  // x0 = 0, where |N| = |B sin(w t)| <= Rs).
  struct Case {
    double static_ratio, boundary;
  };
  for (const Case c : {Case{1, 0.5962847939999439190}, Case{1.5, 0.5333333333333333333}}) {
    SCOPED_TRACE(c.static_ratio);
    const SweepOptions options = general(1, 2, c.static_ratio);
    EXPECT_EQ(sweep_threshold_rule(options), SweepThreshold::den_hartog);
    std::vector<double> lambdas;
    for (double f : {0.25, 0.5, 0.8, 0.95, 0.99, 1.01, 1.05, 1.2, 1.5}) lambdas.push_back(f * c.boundary);
    const std::vector<SweepPoint> points = sweep(lambdas, options);
    for (const SweepPoint& p : points) {
      SCOPED_TRACE(p.lambda);
      EXPECT_EQ(p.threshold_rule, SweepThreshold::den_hartog);
      if (p.lambda < c.boundary) {
        EXPECT_EQ(p.regime_simulated, Regime::continuous);
        EXPECT_EQ(p.stops_per_period, 0u);
        EXPECT_EQ(p.reversals_per_period, 2u);
        EXPECT_EQ(p.regime_threshold, Regime::continuous);  // it is also stable
        EXPECT_TRUE(p.regimes_agree());
      } else if (c.static_ratio * p.lambda >= 1) {
        // Rs >= B: from rest at x0 = 0 the mass never leaves.
        EXPECT_EQ(p.regime_simulated, Regime::stops);
        EXPECT_EQ(p.stuck_fraction, 1);
        EXPECT_FALSE(p.regime_threshold.has_value());
      } else {
        EXPECT_EQ(p.regime_simulated, Regime::dead_bands);
        EXPECT_GT(p.stops_per_period, 0u);
        EXPECT_FALSE(p.regime_threshold.has_value());  // no closed form there
        EXPECT_FALSE(p.regimes_agree());
        EXPECT_FALSE(p.regimes_differ());
      }
    }
  }
}

TEST(SweepGeneral, AnEquilibriumInsideTheStickBandNeverMoves) {
  // k = 2, F0 = 1, x0 = 0.5: at rest at x0 the net force is F0 - k x0 +
  // B sin(w t) = sin t, so the mass never leaves iff Rs = S lambda B >= B:
  // with S = 2, iff lambda >= 1/2. Below, wherever the mass rests, |N| sweeps
  // an interval of width 2 B > 2 Rs within every period: it can never stop
  // for good, and it is not at rest for a whole period.
  SweepOptions options = general(2, 1, 2);
  options.base.force_offset = 1;
  options.base.x0 = 0.5;
  EXPECT_EQ(sweep_threshold_rule(options), SweepThreshold::none);
  const std::vector<double> lambdas = {0.1, 0.3, 0.45, 0.49, 0.5, 0.6, 1, 1.5};
  for (const SweepPoint& p : sweep(lambdas, options)) {
    SCOPED_TRACE(p.lambda);
    EXPECT_FALSE(p.regime_threshold.has_value());
    EXPECT_EQ(p.threshold_rule, SweepThreshold::none);
    if (p.lambda >= 0.5) {
      EXPECT_EQ(p.regime_simulated, Regime::stops);
      EXPECT_EQ(p.stuck_fraction, 1);
      EXPECT_EQ(p.slide_per_period, 0);
      EXPECT_EQ(p.stops_per_period + p.reversals_per_period, 0u);
    } else {
      EXPECT_NE(p.regime_simulated, Regime::stops);
      EXPECT_LT(p.stuck_fraction, 1);
      EXPECT_GT(p.slide_per_period, 0);
    }
  }
}

TEST(SweepGeneral, AConstantForceWithoutSpring) {
  // k = 0, F0 = 0.5, m = B = w = 1, from rest at t = 0. N = 0.5 + sin t:
  //   lambda >= 1.5 (R >= B + F0): never moves;
  //   0.5 < lambda < 1.5: N > -R always, so only forward slips, each from a
  //     breakaway (N = R) to a stop where N < R, then at rest: one stop per
  //     period, periodic from the first breakaway;
  //   lambda < 0.5 (R < F0): it leaves at once, v = (F0 - R) t + 1 - cos t > 0
  //     for ever, x = (F0 - R) t^2 / 2 + t - sin t; the slide over the window
  //     is x(end) - x(begin), here in long double.
  SweepOptions options;
  options.base.force_offset = 0.5;
  options.periods = 100;
  const SweepWindow window = sweep_window(options.periods, options.base);
  const auto x = [](long double r, long double t) {
    return (0.5L - r) * t * t / 2 + t - std::sin(t);
  };
  const std::vector<double> lambdas = {0, 0.2, 0.45, 0.55, 0.9, 1.2, 1.45, 1.5, 2};
  for (const SweepPoint& p : sweep(lambdas, options)) {
    SCOPED_TRACE(p.lambda);
    EXPECT_FALSE(p.regime_threshold.has_value());
    if (p.lambda >= 1.5) {
      EXPECT_EQ(p.regime_simulated, Regime::stops);
      EXPECT_EQ(p.stuck_fraction, 1);
      EXPECT_EQ(p.slide_per_period, 0);
    } else if (p.lambda > 0.5) {
      EXPECT_EQ(p.regime_simulated, Regime::dead_bands);
      EXPECT_EQ(p.stops_per_period, 1u);
      EXPECT_EQ(p.reversals_per_period, 0u);
      EXPECT_GT(p.stuck_fraction, 0);
      EXPECT_LT(p.stuck_fraction, 1);
    } else {
      EXPECT_EQ(p.regime_simulated, Regime::continuous);
      EXPECT_EQ(p.stops_per_period + p.reversals_per_period, 0u);
      EXPECT_EQ(p.stuck_fraction, 0);
      const long double end = x(p.lambda, window.end);
      const long double slide = end - x(p.lambda, window.begin);
      // A difference of two positions of the engine, each a few ulps of
      // |x(end)| (~6e4 here): 16 ulps of it.
      const double ulp = std::nextafter(static_cast<double>(end), 1e300) - static_cast<double>(end);
      EXPECT_NEAR(p.slide_per_period, static_cast<double>(slide), 16 * ulp);
    }
  }
}

TEST(SweepGeneral, UnitsScaleTheSeedsModel) {
  // m = 2, B = 3, w = 0.5, lambda = 0.7 (R = 0.7 * 3 = 2.0999999999999996):
  // the phases of lambda = R / B, lengths times B / (m w^2) = 6. mpmath
  // (tests/steady_state_values.py): stuck 0.2219206951943888730487961,
  // slide per period 5.189927276685288459317203. The window is in user
  // time: (2 pi (P - 1) + pi/2) / w to (2 pi P + pi/2) / w.
  SweepOptions options;
  options.base.mass = 2;
  options.base.amplitude = 3;
  options.base.omega = 0.5;
  options.periods = 50;
  EXPECT_EQ(sweep_threshold_rule(options), SweepThreshold::lambda_star);
  const long double pi = 3.14159265358979323846264338327950288L;
  const SweepWindow window = sweep_window(50, options.base);
  EXPECT_EQ(window.begin, static_cast<double>((2 * pi * 49 + pi / 2) / 0.5L));
  EXPECT_EQ(window.end, static_cast<double>((2 * pi * 50 + pi / 2) / 0.5L));
  const SweepPoint p = sweep_point(0.7, options);
  EXPECT_EQ(p.regime_simulated, Regime::dead_bands);
  EXPECT_EQ(p.regime_threshold, Regime::dead_bands);
  EXPECT_EQ(p.stops_per_period, 2u);
  // Times near 630 (ulp 1.1e-13) over a period of 4 pi; positions within a few units.
  EXPECT_NEAR(p.stuck_fraction, 0.2219206951943888730487961, 1e-13);
  EXPECT_NEAR(p.slide_per_period, 5.189927276685288459317203, 1e-12);
}

TEST(SweepGeneral, TheWindowSpansTheForcingsCommonPeriod) {
  const long double pi = 3.14159265358979323846264338327950288L;
  Model base;
  base.harmonics = {Harmonic{0.2, 0.5, 0}};  // period 4 pi: 2 periods of w = 1
  SweepWindow window = sweep_window(10, base);
  EXPECT_EQ(window.begin, static_cast<double>(4 * pi * 9 + pi / 2));
  EXPECT_EQ(window.end, static_cast<double>(4 * pi * 10 + pi / 2));
  base.harmonics = {Harmonic{0.2, 3, 1}};  // a multiple of w: 2 pi
  window = sweep_window(10, base);
  EXPECT_EQ(window.end, sweep_window(10).end);
  base.harmonics = {Harmonic{0.2, std::sqrt(2.0), 0}};  // no common period
  EXPECT_EQ(expect_invalid([&] { sweep_window(10, base); }).parameter(), "harmonics[0].omega");
  SweepOptions options;
  options.base = base;
  EXPECT_EQ(expect_invalid([&] { options.validate(); }).parameter(), "harmonics[0].omega");
}

TEST(SweepGeneral, SameAsTheSeedSweepWhenNothingIsAdded) {
  // A base model left at its defaults, and a static ratio of 1, run the
  // seed's model: the same numbers as the seed's sweep, bit for bit.
  SweepOptions seed;
  seed.periods = 20;
  SweepOptions spelled_out = seed;
  spelled_out.base.mass = 1;
  spelled_out.static_ratio = 1;
  for (double lambda : {0.3, 0.6, 1.1}) {
    const SweepPoint a = sweep_point(lambda, seed), b = sweep_point(lambda, spelled_out);
    EXPECT_EQ(a.slide_per_period, b.slide_per_period);
    EXPECT_EQ(a.stuck_fraction, b.stuck_fraction);
  }
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
  // The general model's fields: the base model's own rules, B > 0, and the
  // fields the sweep sets itself.
  const auto refused = [](auto change) {
    SweepOptions o;
    change(o);
    return expect_invalid([&] { o.validate(); }).parameter();
  };
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.amplitude = 0; }), "amplitude");
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.stiffness = -1; }), "stiffness");
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.friction = 0.3; }), "friction");
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.static_friction = 0.3; }), "static_friction");
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.v0 = 1; }), "v0");
  EXPECT_EQ(refused([](SweepOptions& o) { o.base.t0 = 1; }), "t0");
  EXPECT_EQ(refused([](SweepOptions& o) { o.static_ratio = 0.5; }), "static_ratio");
  EXPECT_EQ(refused([](SweepOptions& o) { o.static_ratio = std::nan(""); }), "static_ratio");
  SweepOptions wide;
  wide.base.amplitude = 1e300;
  EXPECT_EQ(expect_invalid([&] { sweep_point(1e10, wide); }).parameter(), "lambda");
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
