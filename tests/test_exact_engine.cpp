// The engine as a component: streaming, options and termination, input
// validation, and event-time accuracy over 10^5 forcing periods against the
// steady-state closed forms (computed with mpmath, literals below).
#include <gtest/gtest.h>

#include <cmath>

#include "frictionref/frictionref.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

using testing::seed_model;

// mpmath, 40 digits, lambda the double nearest 0.7 / 0.3:
//   asin(0.7); findroot(cos(a) - cos(t) - 0.7 (t - a), pi); acos(0.3 pi / 2)
const long double kBreakaway07 = 0.7753974966107530015554257442371730995078L;
const long double kStop07 = 3.219805724498314087972480208093709817048L;
const long double kReversal03 = 1.080101437630958733795522796742662080427L;
const long double kPiL = 3.141592653589793238462643383279502884197L;

double ulps_apart(double a, double b) {
  const double ulp = std::nextafter(std::fabs(b), INFINITY) - std::fabs(b);
  return std::fabs(a - b) / ulp;
}


TEST(ExactEngine, StreamMatchesSolve) {
  const Model m = seed_model(0.7, 0.25);
  const Solution s = solve(m, 100.0);
  ExactEngine engine(m, 100.0);
  Phase p;
  std::size_t i = 0;
  while (engine.next(p)) {
    ASSERT_LT(i, s.phases.size());
    EXPECT_EQ(p.t_begin, s.phases[i].t_begin);
    EXPECT_EQ(p.t_end, s.phases[i].t_end);
    EXPECT_EQ(p.x_end, s.phases[i].x_end);
    ++i;
  }
  EXPECT_EQ(i, s.phases.size());
  EXPECT_FALSE(engine.next(p));  // stays finished
  EXPECT_EQ(engine.summary().termination, Termination::reached_end);
  EXPECT_EQ(engine.summary().final_state.t, 100.0);
}

TEST(ExactEngine, PhaseLimitIsAStatus) {
  SolveOptions options;
  options.max_phases = 5;
  const Solution s = solve(seed_model(0.7), 1000.0, options);
  EXPECT_EQ(s.phases.size(), 5u);
  EXPECT_EQ(s.summary.termination, Termination::phase_limit);
  EXPECT_FALSE(s.summary.message.empty());
  EXPECT_EQ(s.summary.final_state.t, s.phases.back().t_end);
}

TEST(ExactEngine, RejectsBadHorizonAndModel) {
  const Model m = seed_model(0.3);
  for (double t_end : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    try {
      ExactEngine engine(m, t_end);
      ADD_FAILURE() << "accepted t_end = " << t_end;
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "t_end");
    }
  }
  Model bad = m;
  bad.mass = 0;
  EXPECT_THROW(ExactEngine(bad, 1.0), InvalidInput);
  SolveOptions options;
  options.max_phases = 0;
  EXPECT_THROW(ExactEngine(m, 1.0, options), InvalidInput);
}

// A valid model whose motion would leave the range of double is refused up
// front (found by fuzzing: B/(m w) = 1e600 gave inf velocities).
TEST(ExactEngine, RejectsMotionOutsideTheRangeOfDouble) {
  Model huge_scale = seed_model(0.3);
  huge_scale.mass = 1e-300;
  huge_scale.amplitude = 1e300;
  try {
    ExactEngine engine(huge_scale, 1.0);
    ADD_FAILURE() << "accepted B/(m w) = 1e600";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "amplitude");
  }
  Model fast = seed_model(0.3, 1e299);
  try {
    ExactEngine engine(fast, 1000.0);
    ADD_FAILURE() << "accepted |x| up to 1e302";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "t_end");
  }
  EXPECT_NO_THROW(ExactEngine(seed_model(0.3, 1e290), 1000.0));
}

// The other end (issue 12; tests/fuzz/corpus/engine/finding-stick-outside-band-
// subnormal-scale): B/(m w^2) = 7e-304, below 2^-969, where positions and
// velocities would be subnormal doubles; the engine gave sticks outside the
// friction band. Refused, naming the largest force; a model at the boundary's
// safe side runs.
TEST(ExactEngine, RejectsMotionBelowTheRangeOfDouble) {
  Model tiny;
  tiny.mass = 65534;
  tiny.amplitude = 2.0528951543397287e-289;
  tiny.omega = 65536;
  tiny.friction = 1.4246797912974851e-317;
  tiny.x0 = 14848;
  try {
    ExactEngine engine(tiny, 0.018120148056899137);
    ADD_FAILURE() << "accepted min(B/m, B/(m w), B/(m w^2)) = 7e-304";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "amplitude");
    EXPECT_NE(e.rule().find("2^-969"), std::string::npos) << e.rule();
  }
  Model small = seed_model(0.3);
  small.amplitude = 1e-280;  // B/(m w^2) = 1e-280 > 2^-969 = 2e-292
  EXPECT_NO_THROW(ExactEngine(small, 10.0));
}

// A spring so weak that the static deflection of the largest force is beyond
// 1e300 (fuzz finding, corpus general-finding-weak-spring-deflection-overflow:
// F0 / k = 3e470 made the slip's closed form non-finite) is refused; a weak
// spring with a representable deflection runs.
TEST(ExactEngine, RejectsASpringWhoseStaticDeflectionLeavesTheRange) {
  Model weak;
  weak.mass = 232704;
  weak.amplitude = 1000;
  weak.friction = 0;
  weak.static_friction = 31420.39;
  weak.stiffness = 5.432334175734625e-312;
  weak.damping = 2346;
  weak.force_offset = 1.7573814970894711e+159;
  weak.x0 = 262144;
  weak.v0 = 65280;
  weak.t0 = -204.8;
  try {
    ExactEngine engine(weak, -109.51675145368303);
    ADD_FAILURE() << "accepted F0 / k = 3e470";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "stiffness");
    EXPECT_NE(e.rule().find("static deflection"), std::string::npos) << e.rule();
  }
  Model fine = seed_model(0.3);
  fine.stiffness = 1e-290;  // B / k = 1e290 < 1e300
  EXPECT_EQ(solve(fine, 30.0).summary.termination, Termination::reached_end);
}

// Time scales the resolution (8 ulps of max(1, |w t|) / w) cannot resolve:
// a natural frequency, a damping rate or a harmonic 1e10 times the span.
TEST(ExactEngine, RejectsTimeScalesBelowTheResolution) {
  const auto refused_parameter = [](const Model& m, double t_end) -> std::string {
    try {
      ExactEngine engine(m, t_end);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return "";
  };
  Model spring = seed_model(0.3);
  spring.stiffness = 1e22;  // sqrt(k/m) = 1e11 rad per unit time, 1/w = 1
  EXPECT_EQ(refused_parameter(spring, 1.0), "stiffness");
  spring.stiffness = 1e18;  // 1e9 rad: resolved
  EXPECT_EQ(refused_parameter(spring, 1.0), "");
  Model damper = seed_model(0.3);
  damper.damping = 1e11;
  EXPECT_EQ(refused_parameter(damper, 1.0), "damping");
  Model harmonic = seed_model(0.3);
  harmonic.harmonics.push_back({0.5, 1e9, 0});  // 1e9 * 20 = 2e10 rad by t = 20
  EXPECT_EQ(refused_parameter(harmonic, 20.0), "harmonics[0].omega");
  EXPECT_EQ(refused_parameter(harmonic, 5.0), "");
}

TEST(ExactEngine, SummaryCountsAddUp) {
  const Solution s = solve(seed_model(0.7), 200.0);
  const Summary& sum = s.summary;
  EXPECT_EQ(sum.count(PhaseKind::stick) + sum.count(PhaseKind::slip_forward) +
                sum.count(PhaseKind::slip_backward),
            sum.phases);
  EXPECT_EQ(sum.stops, sum.count(PhaseKind::slip_forward) + sum.count(PhaseKind::slip_backward) -
                           (s.phases.back().kind != PhaseKind::stick ? 1 : 0));
  EXPECT_EQ(sum.breakaways, sum.count(PhaseKind::stick) - (s.phases.back().kind == PhaseKind::stick));
  EXPECT_GT(sum.root_function_calls, 0u);
  EXPECT_NE(sum.brief_report().find("termination=reached_end"), std::string::npos);
}

// Dead bands over 10^5 periods from rest: periodic from the first breakaway,
// so every breakaway is alpha + k pi and every stop is t_s + k pi (alternating
// directions). Error against the closed form, in ulps of t: must stay within
// 4 ulps however long the horizon (it does not accumulate).
TEST(ExactEngine, LongHorizonDeadBandsStayWithinFourUlps) {
  const double periods = 1e5;
  ExactEngine engine(seed_model(0.7), periods * 2 * 3.141592653589793);
  Phase p;
  double worst = 0;
  long k_worst = -1;
  std::uint64_t checked = 0;
  while (engine.next(p)) {
    if (p.t_end == engine.t_end()) break;
    const long half = std::lround(static_cast<double>((p.t_end - kBreakaway07) / kPiL));
    const long double base = p.kind == PhaseKind::stick ? kBreakaway07 : kStop07;
    const long k = p.kind == PhaseKind::stick ? half
                                              : std::lround(static_cast<double>((p.t_end - kStop07) / kPiL));
    const double expected = static_cast<double>(base + k * kPiL);
    const double error = ulps_apart(p.t_end, expected);
    if (error > worst) worst = error, k_worst = k;
    ++checked;
  }
  RecordProperty("worst_ulps", std::to_string(worst));
  std::printf("dead bands, 1e5 periods: %llu events, worst %.2f ulps (half period %ld)\n",
              static_cast<unsigned long long>(checked), worst, k_worst);
  EXPECT_LE(worst, 4.0);
  EXPECT_GE(checked, 4 * 99999u);
}

// Continuous regime over 10^5 periods from rest: after the transient the
// reversals lock to tau1 + k pi, cos(tau1) = lambda pi / 2.
TEST(ExactEngine, LongHorizonContinuousLocksToReversalPhase) {
  const double periods = 1e5;
  ExactEngine engine(seed_model(0.3), periods * 2 * 3.141592653589793);
  Phase p;
  double worst = 0;
  std::uint64_t checked = 0;
  while (engine.next(p)) {
    if (p.t_end == engine.t_end() || p.t_end < 500) continue;  // skip the transient
    const long k = std::lround(static_cast<double>((p.t_end - kReversal03) / kPiL));
    const double expected = static_cast<double>(kReversal03 + k * kPiL);
    worst = std::fmax(worst, ulps_apart(p.t_end, expected));
    ++checked;
  }
  std::printf("continuous, 1e5 periods: %llu reversals, worst %.2f ulps\n",
              static_cast<unsigned long long>(checked), worst);
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(engine.summary().count(PhaseKind::stick), 1u);
}

}  // namespace
}  // namespace frictionref
