// Steady-state closed forms (steady_state.hpp): the regime threshold, the
// regime, and per regime the phases, stuck fraction, slide, peak velocity and
// energy. Expected values are mpmath (40 digits) evaluations of the formulas
// of THEORY.md at the exact binary value of the inputs; the roots are mpmath
// findroot, the slides also mpmath quad of the velocity. A second method
// cross-checks the closed forms: the exact event-driven engine run from rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"

namespace frictionref {
namespace {

using Long = long double;

// |actual - expected| within n units in the last place of the double nearest
// to `expected`.
::testing::AssertionResult within_ulps(double actual, Long expected, double n) {
  const double e = static_cast<double>(expected);
  const double ulp = std::nextafter(std::fabs(e), std::numeric_limits<double>::infinity()) -
                     std::fabs(e);
  const Long error = std::fabs(Long(actual) - expected);
  if (error <= Long(n) * Long(ulp)) return ::testing::AssertionSuccess();
  char text[200];
  std::snprintf(text, sizeof text, "actual %.17g, expected %.21Lg: error %.3g ulps (allowed %g)",
                actual, expected, static_cast<double>(error / Long(ulp)), n);
  return ::testing::AssertionFailure() << text;
}

Model seed_model(double friction) {
  Model model;  // m = B = w = 1
  model.friction = friction;
  return model;
}

// ---- threshold and regime --------------------------------------------------

// mpmath: 2/sqrt(4+pi**2) = 0.5370292721463150768526284
constexpr Long kLambdaStar = 0.5370292721463150768526284L;

TEST(RegimeThreshold, IsTheDoubleNearestTwoOverSqrtFourPlusPiSquared) {
  EXPECT_EQ(regime_threshold(), 0.53702927214631507683);
  // The nearest double, not just a close one.
  const double t = regime_threshold();
  EXPECT_LE(std::fabs(Long(t) - kLambdaStar),
            std::fabs(Long(std::nextafter(t, 0.0)) - kLambdaStar));
  EXPECT_LE(std::fabs(Long(t) - kLambdaStar),
            std::fabs(Long(std::nextafter(t, 1.0)) - kLambdaStar));
  EXPECT_EQ(regime_threshold_quoted, 0.536);
}

TEST(RegimeFor, AroundTheThresholdAndBeyond) {
  const double star = 0.53702927214631507683;
  EXPECT_EQ(regime_for(star - 1e-9), Regime::continuous);
  EXPECT_EQ(regime_for(star + 1e-9), Regime::dead_bands);
  EXPECT_EQ(regime_for(0.0), Regime::continuous);
  EXPECT_EQ(regime_for(0.3), Regime::continuous);
  EXPECT_EQ(regime_for(0.536), Regime::continuous);
  EXPECT_EQ(regime_for(0.7), Regime::dead_bands);
  EXPECT_EQ(regime_for(0.999999), Regime::dead_bands);
  EXPECT_EQ(regime_for(std::nextafter(1.0, 0.0)), Regime::dead_bands);
  EXPECT_EQ(regime_for(1.0), Regime::stops);
  EXPECT_EQ(regime_for(1.01), Regime::stops);
  EXPECT_EQ(regime_for(5.0), Regime::stops);
}

TEST(RegimeFor, ExactAtTheDoubleNeighboursOfLambdaStar) {
  // mpmath: mpf(0.5370292721463151) - 2/sqrt(4+pi**2) = +5.18e-17 > 0, so the
  // double nearest lambda* lies above it (dead bands) and the next double
  // below lies below it (continuous).
  const double star = regime_threshold();
  EXPECT_GT(Long(star), kLambdaStar);
  EXPECT_EQ(regime_for(star), Regime::dead_bands);
  EXPECT_EQ(regime_for(std::nextafter(star, 0.0)), Regime::continuous);
}

TEST(SteadyState, QuotedThresholdDisagreesJustAboveIt) {
  // lambda = 0.5365: 0.536 <= lambda < lambda*, continuous by the exact
  // threshold but dead bands by the seed's 0.536.
  Model model = seed_model(0.5365);
  const SteadyState s = steady_state(model);
  EXPECT_EQ(s.regime, Regime::continuous);
  EXPECT_EQ(s.regime_by_quoted_threshold, Regime::dead_bands);
  EXPECT_EQ(s.lambda, 0.5365);
  EXPECT_EQ(s.threshold, regime_threshold());
  EXPECT_EQ(s.threshold_quoted, 0.536);
  const std::string report = s.report();
  EXPECT_NE(report.find("regime: continuous"), std::string::npos) << report;
  EXPECT_NE(report.find("regime_by_quoted_threshold: dead-bands"), std::string::npos) << report;
  // Below 0.536 both agree.
  const SteadyState low = steady_state(seed_model(0.5355));
  EXPECT_EQ(low.regime, Regime::continuous);
  EXPECT_EQ(low.regime_by_quoted_threshold, Regime::continuous);
}

// The regime against expectations that do not come from regime_for(): the
// position of each lambda against lambda* = 0.5370292721463150768526284 (mpmath,
// tests/steady_state_values.py) and 1, written out.
TEST(SteadyState, RegimeByTheHighPrecisionThreshold) {
  struct Case {
    double lambda;
    Regime regime;
  };
  for (const Case c : {Case{0.0, Regime::continuous}, Case{0.1, Regime::continuous},
                       Case{0.3, Regime::continuous}, Case{0.5365, Regime::continuous},
                       Case{0.53702927214631, Regime::continuous},
                       Case{0.53702927214632, Regime::dead_bands},
                       Case{0.5371, Regime::dead_bands}, Case{0.7, Regime::dead_bands},
                       Case{0.999999, Regime::dead_bands}, Case{1.0, Regime::stops},
                       Case{1.01, Regime::stops}, Case{5.0, Regime::stops}}) {
    EXPECT_EQ(steady_state(seed_model(c.lambda)).regime, c.regime) << c.lambda;
  }
}

// The regime against the exact engine, run from rest over 80 periods and
// read off the last one [2 pi 79 + pi/2, 2 pi 80 + pi/2] by this test: at
// rest for all of it: stops; at rest for part of it: dead bands; never at
// rest: continuous. (Near lambda* the dead band, 4.11 (lambda - lambda*)
// rad, must stay far above the engine's resolution 8 eps w t ~ 9e-13: the
// lambdas here are 1e-4 or more away.)
TEST(SteadyStateCrossCheck, RegimeFromTheEngineCountedHere) {
  const double two_pi = boost::math::constants::two_pi<double>();
  const double begin = 79 * two_pi + two_pi / 4, end = 80 * two_pi + two_pi / 4;
  for (double lambda : {0.05, 0.3, 0.5, 0.5365, 0.5369, 0.5371, 0.54, 0.7, 0.9, 0.999, 1.0, 1.01,
                        2.0}) {
    SCOPED_TRACE(lambda);
    const Solution solution = solve(seed_model(lambda), end);
    ASSERT_EQ(solution.summary.termination, Termination::reached_end);
    double rest = 0;
    for (const Phase& p : solution.phases) {
      if (p.kind != PhaseKind::stick) continue;
      const double lo = std::max(p.t_begin, begin), hi = std::min(p.t_end, end);
      if (hi > lo) rest += hi - lo;
    }
    const Regime simulated = rest >= end - begin ? Regime::stops
                             : rest > 0           ? Regime::dead_bands
                                                  : Regime::continuous;
    EXPECT_EQ(steady_state(seed_model(lambda)).regime, simulated);
  }
}

// ---- input -----------------------------------------------------------------

TEST(SteadyState, ZeroAmplitudeRejected) {
  Model model = seed_model(0.3);
  model.amplitude = 0;
  try {
    steady_state(model);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.parameter(), "amplitude");
    EXPECT_EQ(error.value(), "0");
  }
  model.friction = 0;
  EXPECT_THROW(steady_state(model), InvalidInput);
}

TEST(SteadyState, InvalidModelRejected) {
  Model model = seed_model(0.3);
  model.mass = -1;
  try {
    steady_state(model);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.parameter(), "mass");
  }
}

TEST(SteadyState, IndependentOfInitialState) {
  Model a = seed_model(0.7);
  Model b = a;
  b.x0 = 5;
  b.v0 = -3;
  b.t0 = 100;
  const SteadyState sa = steady_state(a), sb = steady_state(b);
  EXPECT_EQ(sa.stop_phase, sb.stop_phase);
  EXPECT_EQ(sa.slide_per_half_period, sb.slide_per_half_period);
  EXPECT_EQ(sa.energy_per_period, sb.energy_per_period);
}

// ---- continuous: lambda = 0.3 ----------------------------------------------

// mpmath, lam = mpf(0.3) (the double), tau1 = acos(lam*pi/2):
constexpr Long kTau1_03 = 1.080101437630958733795523L;       // acos(lam*pi/2)
constexpr Long kSlide_03 = 1.764011225560074997463801L;      // 2*sin(tau1) (= quad of V over [tau1, tau1+pi])
constexpr Long kEnergy_03 = 1.058406735336044959309363L;     // lam*2*2*sin(tau1)
constexpr Long kPeak_03 = 0.8981385308723835379785224L;      // V at findroot(sin(t)-lam, 2.8)

TEST(SteadyState, ContinuousLambdaPointThree) {
  const SteadyState s = steady_state(seed_model(0.3));
  EXPECT_EQ(s.regime, Regime::continuous);
  EXPECT_EQ(s.lambda, 0.3);
  EXPECT_TRUE(within_ulps(s.reversal_phase, kTau1_03, 2));
  EXPECT_TRUE(within_ulps(s.slide_per_half_period, kSlide_03, 2));
  EXPECT_TRUE(within_ulps(s.energy_per_period, kEnergy_03, 2));
  EXPECT_TRUE(within_ulps(s.peak_velocity, kPeak_03, 4));
  EXPECT_EQ(s.stops_per_period, 0);
  EXPECT_EQ(s.stuck_fraction, 0);
  EXPECT_TRUE(std::isnan(s.breakaway_phase));
  EXPECT_TRUE(std::isnan(s.stop_phase));
  // The reversal is consistent: the force beats friction there (sin > lambda).
  EXPECT_GT(std::sin(s.reversal_phase), 0.3);
}

TEST(SteadyState, FrictionlessIsSinusoidal) {
  // R = 0: v = -cos t, x = -sin t: reversals at pi/2, slide 2, peak 1, no loss.
  const SteadyState s = steady_state(seed_model(0.0));
  EXPECT_EQ(s.regime, Regime::continuous);
  EXPECT_TRUE(within_ulps(s.reversal_phase, boost::math::constants::half_pi<Long>(), 1));
  EXPECT_TRUE(within_ulps(s.slide_per_half_period, 2.0L, 1));
  EXPECT_TRUE(within_ulps(s.peak_velocity, 1.0L, 1));
  EXPECT_EQ(s.energy_per_period, 0.0);
}

// ---- dead bands: lambda = 0.7 ----------------------------------------------

// mpmath, lam = mpf(0.7), a = asin(lam), f(t) = cos(a) - cos(t) - lam*(t - a):
constexpr Long kAlpha_07 = 0.7753974966107530015554257L;   // asin(lam)
constexpr Long kStop_07 = 3.21980572449831408797248L;      // findroot(f, pi), in [pi-a, pi+a]
constexpr Long kStuck_07 = 0.2219206951943889800486521L;   // 1 - (stop - a)/pi
constexpr Long kSlide_07 = 0.4324939397237738171521449L;   // quad(f, [a, stop])
constexpr Long kPeak_07 = 0.3147273234507690925581319L;    // f(pi - a)
constexpr Long kEnergy_07 = 0.6054915156132833055998245L;  // lam*2*quad(f, [a, stop])

TEST(SteadyState, DeadBandsLambdaPointSeven) {
  const SteadyState s = steady_state(seed_model(0.7));
  EXPECT_EQ(s.regime, Regime::dead_bands);
  EXPECT_EQ(s.regime_by_quoted_threshold, Regime::dead_bands);
  EXPECT_TRUE(within_ulps(s.breakaway_phase, kAlpha_07, 1));
  EXPECT_TRUE(within_ulps(s.stop_phase, kStop_07, 2));
  EXPECT_TRUE(within_ulps(s.stuck_fraction, kStuck_07, 4));
  EXPECT_TRUE(within_ulps(s.slide_per_half_period, kSlide_07, 4));
  EXPECT_TRUE(within_ulps(s.peak_velocity, kPeak_07, 4));
  EXPECT_TRUE(within_ulps(s.energy_per_period, kEnergy_07, 4));
  EXPECT_EQ(s.stops_per_period, 2);
  EXPECT_TRUE(std::isnan(s.reversal_phase));
  // The stop lies in [pi - a, pi + a], where |sin| <= lambda: the mass sticks.
  const double pi = boost::math::constants::pi<double>();
  EXPECT_GE(s.stop_phase, pi - s.breakaway_phase);
  EXPECT_LE(s.stop_phase, pi + s.breakaway_phase);
}

TEST(SteadyState, StopsRegime) {
  for (double lambda : {1.0, 1.01, 5.0}) {
    const SteadyState s = steady_state(seed_model(lambda));
    EXPECT_EQ(s.regime, Regime::stops) << lambda;
    EXPECT_EQ(s.regime_by_quoted_threshold, Regime::stops) << lambda;
    EXPECT_EQ(s.stuck_fraction, 1.0);
    EXPECT_EQ(s.stops_per_period, 0);
    EXPECT_EQ(s.slide_per_half_period, 0.0);
    EXPECT_EQ(s.peak_velocity, 0.0);
    EXPECT_EQ(s.energy_per_period, 0.0);
    EXPECT_TRUE(std::isnan(s.reversal_phase));
    EXPECT_TRUE(std::isnan(s.breakaway_phase));
    EXPECT_TRUE(std::isnan(s.stop_phase));
  }
}

// At lambda* the two regimes meet: the continuous reversal phase equals the
// breakaway asin(lambda*), the dead band has zero length, and slide and peak
// velocity are continuous. mpmath: asin(ls) = acos(ls*pi/2) =
// 0.5669115049410094050828977, 2*ls = 1.074058544292630153705257,
// 2*cos(a) - ls*(pi - 2*a) = 0.6088961457396847683418094.
TEST(SteadyState, RegimesMeetContinuouslyAtTheThreshold) {
  const double star = regime_threshold();
  const SteadyState above = steady_state(seed_model(star));
  const SteadyState below = steady_state(seed_model(std::nextafter(star, 0.0)));
  ASSERT_EQ(above.regime, Regime::dead_bands);
  ASSERT_EQ(below.regime, Regime::continuous);
  EXPECT_NEAR(above.breakaway_phase, 0.5669115049410094050828977, 1e-15);
  EXPECT_NEAR(below.reversal_phase, 0.5669115049410094050828977, 1e-14);
  EXPECT_GE(above.stuck_fraction, 0.0);
  EXPECT_LT(above.stuck_fraction, 1e-13);
  EXPECT_NEAR(above.slide_per_half_period, 1.074058544292630153705257, 1e-13);
  EXPECT_NEAR(below.slide_per_half_period, 1.074058544292630153705257, 1e-13);
  EXPECT_NEAR(above.peak_velocity, 0.6088961457396847683418094, 1e-13);
  EXPECT_NEAR(below.peak_velocity, 0.6088961457396847683418094, 1e-13);
}

// ---- units -----------------------------------------------------------------

// m = 2, B = 3, w = 0.5, R = 2.1 (lambda = 2.1/3 = 0.70000000000000002960...):
// phases are dimensionless; slide scales by B/(m w^2) = 6, velocity by
// B/(m w) = 3, energy by R B/(m w^2) = 12.6. mpmath, lam = mpf(2.1)/3.
TEST(SteadyState, UnitsScaleTheDimensionlessSolution) {
  Model model;
  model.mass = 2;
  model.amplitude = 3;
  model.omega = 0.5;
  model.friction = 2.1;
  const SteadyState s = steady_state(model);
  EXPECT_EQ(s.regime, Regime::dead_bands);
  EXPECT_TRUE(within_ulps(s.lambda, 0.7000000000000000296059473L, 1));
  EXPECT_TRUE(within_ulps(s.breakaway_phase, 0.7753974966107531051969718L, 1));  // asin(lam)
  EXPECT_TRUE(within_ulps(s.stop_phase, 3.219805724498313855464065L, 2));        // findroot
  EXPECT_TRUE(within_ulps(s.stuck_fraction, 0.2219206951943890870485081L, 4));
  // quad(f, [a, stop]) * B/(m w^2)
  EXPECT_TRUE(within_ulps(s.slide_per_half_period, 2.594963638342641576167137L, 4));
  // f(pi - a) * B/(m w)
  EXPECT_TRUE(within_ulps(s.peak_velocity, 0.9441819703523069244463577L, 4));
  // R * 2 * quad(f, [a, stop]) * B/(m w^2)
  EXPECT_TRUE(within_ulps(s.energy_per_period, 10.89884728103909508086012L, 4));

  // The same numbers from the dimensionless lambda = 0.7 case, scaled (lambda
  // differs by 3e-17 relative, far below the tolerance).
  const SteadyState d = steady_state(seed_model(0.7));
  EXPECT_NEAR(s.slide_per_half_period, 6 * d.slide_per_half_period, 1e-14);
  EXPECT_NEAR(s.peak_velocity, 3 * d.peak_velocity, 1e-14);
  EXPECT_NEAR(s.energy_per_period, 12.6 * d.slide_per_half_period * 2, 1e-13);
  EXPECT_NEAR(s.stop_phase, d.stop_phase, 1e-14);
}

TEST(SteadyState, UnitsInTheContinuousRegime) {
  // m = 4, B = 2, w = 2, R = 0.6 (lambda = 0.3): slide 2 sin(tau1) B/(m w^2)
  // = kSlide_03 / 8, peak kPeak_03 * B/(m w) = kPeak_03 / 4, energy R * 2 *
  // slide = 0.6 * 2 * kSlide_03 / 8. (0.6/2 is exactly the double 0.3.)
  Model model;
  model.mass = 4;
  model.amplitude = 2;
  model.omega = 2;
  model.friction = 0.6;
  const SteadyState s = steady_state(model);
  EXPECT_EQ(s.regime, Regime::continuous);
  EXPECT_TRUE(within_ulps(s.reversal_phase, kTau1_03, 2));
  EXPECT_TRUE(within_ulps(s.slide_per_half_period, kSlide_03 / 8, 2));
  EXPECT_TRUE(within_ulps(s.peak_velocity, kPeak_03 / 4, 4));
  EXPECT_TRUE(within_ulps(s.energy_per_period, Long(0.6) * 2 * kSlide_03 / 8, 4));
}

// ---- cross-check with the exact engine --------------------------------------

// Distance from tau to the nearest point of base + 2 pi k.
Long distance_mod_two_pi(Long tau, Long base) {
  const Long two_pi = boost::math::constants::two_pi<Long>();
  const Long d = tau - base;
  return std::fabs(d - two_pi * std::round(d / two_pi));
}

TEST(SteadyStateCrossCheck, DeadBandStopsFromTheEngine) {
  // lambda = 0.7 from rest: periodic from the first breakaway. Every stop of a
  // forward slip is at kStop_07 (mod 2 pi), of a backward slip at kStop_07 + pi.
  const Long pi = boost::math::constants::pi<Long>();
  const Model model = seed_model(0.7);
  const Solution solution = solve(model, 20 * boost::math::constants::two_pi<double>());
  const std::vector<Phase>& phases = solution.phases;
  int stops = 0, breakaways = 0;
  for (std::size_t k = 0; k + 1 < phases.size(); ++k) {
    const Phase& p = phases[k];
    const Long t = p.t_end;
    if (p.kind == PhaseKind::stick) {
      ++breakaways;
      const int s = slip_sign(phases[k + 1].kind);
      ASSERT_NE(s, 0);
      EXPECT_LT(distance_mod_two_pi(t, kAlpha_07 + (s < 0 ? pi : 0)), 1e-12L) << "t=" << p.t_end;
      continue;
    }
    ++stops;
    ASSERT_EQ(phases[k + 1].kind, PhaseKind::stick) << "t=" << p.t_end;
    const int s = slip_sign(p.kind);
    EXPECT_LT(distance_mod_two_pi(t, kStop_07 + (s < 0 ? pi : 0)), 1e-12L) << "t=" << p.t_end;
    // Each complete slip after the first breakaway slides the steady amount.
    EXPECT_NEAR(std::fabs(p.x_end - p.x_begin), double(kSlide_07), 1e-12) << "t=" << p.t_end;
  }
  EXPECT_GE(stops, 39);
  EXPECT_GE(breakaways, 39);
  // Peak velocity where sin t = lambda on the way down: t = pi - a + 2 pi k.
  for (int k = 2; k < 19; ++k) {
    const double t = double(pi - kAlpha_07 + 2 * pi * k);
    EXPECT_NEAR(solution.state_at(t).v, double(kPeak_07), 1e-12) << "t=" << t;
    EXPECT_NEAR(solution.state_at(t + double(pi)).v, -double(kPeak_07), 1e-12) << "t=" << t;
  }
  // Fraction of time stuck after the first breakaway, whole periods only.
  const Long start = kAlpha_07, end = kAlpha_07 + 19 * boost::math::constants::two_pi<Long>();
  Long stuck = 0;
  for (const Phase& p : phases) {
    if (p.kind != PhaseKind::stick) continue;
    const Long lo = std::max<Long>(p.t_begin, start), hi = std::min<Long>(p.t_end, end);
    if (hi > lo) stuck += hi - lo;
  }
  EXPECT_NEAR(double(stuck / (end - start)), double(kStuck_07), 1e-12);
}

TEST(SteadyStateCrossCheck, ContinuousReversalsConvergeInTheEngine) {
  // lambda = 0.3 from rest: the transient halves each half period; after 30
  // periods reversal times mod pi equal tau1 and each slide is 2 sin(tau1).
  const Long pi = boost::math::constants::pi<Long>();
  const Model model = seed_model(0.3);
  const double horizon = 60 * boost::math::constants::two_pi<double>();
  const Solution solution = solve(model, horizon);
  const std::vector<Phase>& phases = solution.phases;
  ASSERT_GE(phases.size(), 3u);
  EXPECT_EQ(phases[0].kind, PhaseKind::stick);
  int late_reversals = 0;
  for (std::size_t k = 1; k < phases.size(); ++k) {
    // Direct reversals only: no stick after the first breakaway.
    EXPECT_NE(phases[k].kind, PhaseKind::stick) << "phase " << k << " t=" << phases[k].t_begin;
    if (k + 1 == phases.size()) break;
    EXPECT_EQ(slip_sign(phases[k + 1].kind), -slip_sign(phases[k].kind));
    const Long t = phases[k].t_end;
    if (t < 30 * 2 * pi) continue;
    ++late_reversals;
    // Forward slips start at tau1 (mod 2 pi), backward ones at tau1 + pi.
    const int next = slip_sign(phases[k + 1].kind);
    EXPECT_LT(distance_mod_two_pi(t, kTau1_03 + (next < 0 ? pi : 0)), 1e-9L) << "t=" << double(t);
    if (phases[k].t_begin >= 30 * 2 * pi) {
      EXPECT_NEAR(std::fabs(phases[k].x_end - phases[k].x_begin), double(kSlide_03), 1e-9)
          << "t=" << double(t);
    }
  }
  EXPECT_GE(late_reversals, 58);
  // Peak velocity at sin t = lambda on the way down: t = pi - a + 2 pi k.
  const Long alpha = std::asin(Long(0.3));  // asin of the double 0.3
  for (int k = 31; k < 59; ++k) {
    const double t = double(pi - alpha + 2 * pi * k);
    EXPECT_NEAR(solution.state_at(t).v, double(kPeak_03), 1e-9) << "t=" << t;
    EXPECT_NEAR(solution.state_at(t + double(pi)).v, -double(kPeak_03), 1e-9) << "t=" << t;
  }
}

}  // namespace
}  // namespace frictionref

namespace frictionref {
namespace {

// Found by fuzzing: R / B within an ulp of lambda*, where the long double
// quotient and the reported (double) lambda fall on different sides. The
// regime is that of the lambda the report shows: the double
// 35196.89849646949 / 65540 = 0.5370292721463151, which lies 5.18e-17 above
// lambda* (mpmath, tests/steady_state_values.py; the exact quotient lies
// 1.2e-18 below it): dead bands.
TEST(SteadyState, RegimeIsThatOfTheReportedLambda) {
  Model m;
  m.mass = 1792;
  m.amplitude = 65540;
  m.friction = 35196.89849646949;
  const SteadyState s = steady_state(m);
  EXPECT_EQ(s.lambda, 0.5370292721463151);
  EXPECT_EQ(s.regime, Regime::dead_bands);
}

}  // namespace
}  // namespace frictionref
