// compare() (comparison.hpp): a correct candidate passes, and each defect is
// caught by the check that names it.
//
// Candidates: the exact curve itself (coarse and fine sampling); an
// independent stiff-spring code written here (central differences, friction
// spring K_f = 1e7, dt = 1e-5, archived every 0.01, as in the seed's DYNARACK
// runs), which must pass for all three seed cases; and synthetic candidates
// with one known defect each: a time shift, a scaled velocity, creep instead
// of sticking (tanh-regularized friction), a missing stop, an extra stop, and
// noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "compare_helpers.hpp"
#include "expect_invalid.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/time_history.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

using testing::exact_history;
using testing::find_check;
using testing::seed_model;

using testing::expect_invalid;

// The stiff-spring code of compare_helpers.hpp under the seed's force.
TimeHistory stiff_spring_candidate(const Model& m, double t_end, double k_f = 1e7, double dt = 1e-5,
                                   double archive = 0.01) {
  const auto force = [&](double t) { return m.amplitude * std::sin(m.omega * t); };
  return testing::stiff_spring_history(m, t_end, force, k_f, dt, archive, "stiff spring K_f=1e7");
}

// Regularized friction -R tanh(v / eps): the mass never stops, it creeps at
// v ~ eps atanh(F / R) where the exact mass sticks. Classical RK4, dt 1e-3.
TimeHistory tanh_candidate(const Model& m, double t_end, double eps) {
  const double dt = 1e-3, archive = 0.01;
  const auto every = static_cast<std::int64_t>(std::llround(archive / dt));
  const auto steps = static_cast<std::int64_t>(std::llround((t_end - m.t0) / dt));
  const auto accel = [&](double t, double v) {
    return (m.amplitude * std::sin(m.omega * t) - m.friction * std::tanh(v / eps)) / m.mass;
  };
  double v = m.v0;
  TimeHistory history;
  for (std::int64_t n = 0; n <= steps; ++n) {
    const double t = m.t0 + static_cast<double>(n) * dt;
    if (n % every == 0) {
      history.t.push_back(m.t0 + static_cast<double>(n / every) * archive);
      history.v.push_back(v);
    }
    const double k1 = accel(t, v);
    const double k2 = accel(t + dt / 2, v + dt / 2 * k1);
    const double k3 = accel(t + dt / 2, v + dt / 2 * k2);
    const double k4 = accel(t + dt, v + dt * k3);
    v += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  history.source = "tanh friction";
  return history;
}

// The stick phases of the exact motion.
std::vector<Phase> stick_phases(const Model& model, double t_end) {
  std::vector<Phase> sticks;
  for (const Phase& phase : solve(model, t_end).phases)
    if (phase.kind == PhaseKind::stick) sticks.push_back(phase);
  return sticks;
}

// Passed, failed, or absent, with the report for the failure message.
::testing::AssertionResult check_is(const ComparisonReport& report, CheckKind kind, bool passed) {
  const Check* check = find_check(report, kind);
  if (check == nullptr)
    return ::testing::AssertionFailure() << to_string(kind) << " missing\n" << report.full_report();
  if (check->passed == passed) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << to_string(kind) << (passed ? " failed" : " passed") << ": " << check->message << "\n"
         << report.full_report();
}
::testing::AssertionResult passes(const ComparisonReport& r, CheckKind kind) {
  return check_is(r, kind, true);
}
::testing::AssertionResult fails(const ComparisonReport& r, CheckKind kind) {
  return check_is(r, kind, false);
}

struct SeedCase {
  double lambda, v0;
  Regime regime;
};
const SeedCase seed_cases[] = {
    {0.3, 0, Regime::continuous}, {0.7, 0, Regime::dead_bands}, {1.01, -1, Regime::stops}};

// ---------------------------------------------------------------------------
// Options, enums, validation.

TEST(CompareOptions, DefaultsValidate) {
  const CompareOptions options;
  EXPECT_NO_THROW(options.validate());
  EXPECT_EQ(options.stick_threshold, 1e-3);
  EXPECT_EQ(options.min_stick_duration, 0.01);
  EXPECT_EQ(options.velocity_max_tolerance, 0.02);
  EXPECT_EQ(options.stop_time_tolerance, 0.01);
  EXPECT_EQ(options.max_missed_stops, 0u);
  EXPECT_EQ(options.max_extra_stops, 0u);
}

TEST(CompareOptions, ValidateNamesFieldValueAndRule) {
  const auto invalid = [](auto set) {
    CompareOptions options;
    set(options);
    return expect_invalid([&] { options.validate(); });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  InvalidInput e = invalid([](CompareOptions& o) { o.stick_threshold = 0; });
  EXPECT_EQ(e.parameter(), "stick_threshold");
  EXPECT_EQ(e.value(), "0");
  EXPECT_EQ(e.rule(), "must be > 0");
  e = invalid([&](CompareOptions& o) { o.velocity_max_tolerance = nan; });
  EXPECT_EQ(e.parameter(), "velocity_max_tolerance");
  EXPECT_EQ(e.rule(), "must be a finite number");
  e = invalid([](CompareOptions& o) { o.stop_time_tolerance = -0.5; });
  EXPECT_EQ(e.parameter(), "stop_time_tolerance");
  EXPECT_EQ(e.value(), "-0.5");
  EXPECT_EQ(e.rule(), "must be >= 0");
  EXPECT_EQ(invalid([](CompareOptions& o) { o.min_stick_duration = -1; }).parameter(),
            "min_stick_duration");
  EXPECT_EQ(invalid([](CompareOptions& o) { o.velocity_rms_tolerance = -1; }).parameter(),
            "velocity_rms_tolerance");
  EXPECT_EQ(invalid([](CompareOptions& o) { o.displacement_max_tolerance = -1; }).parameter(),
            "displacement_max_tolerance");
  EXPECT_EQ(invalid([](CompareOptions& o) { o.regime_window = 0; }).parameter(), "regime_window");
}

TEST(CompareOptions, EnumStrings) {
  for (CheckKind kind :
       {CheckKind::velocity_max, CheckKind::velocity_rms, CheckKind::displacement_max,
        CheckKind::stop_times, CheckKind::missed_stops, CheckKind::extra_stops, CheckKind::creep,
        CheckKind::regime}) {
    EXPECT_EQ(check_kind_from_string(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(CheckKind::stop_times), "stop_times");
  EXPECT_FALSE(check_kind_from_string("velocity").has_value());
  EXPECT_EQ(to_string(Verdict::pass), "PASS");
  EXPECT_EQ(to_string(Verdict::fail), "FAIL");
  EXPECT_EQ(verdict_from_string("FAIL"), Verdict::fail);
  EXPECT_FALSE(verdict_from_string("pass").has_value());
}

TEST(CompareInput, RejectsBadModelHistoryAndStart) {
  const TimeHistory good = exact_history(seed_model(0.7), 5, 0.1);
  Model zero_amplitude = seed_model(0.7);
  zero_amplitude.amplitude = 0;
  EXPECT_EQ(expect_invalid([&] { compare(zero_amplitude, good); }).parameter(), "amplitude");

  Model late = seed_model(0.7);
  late.t0 = 1;  // the record starts at 0, before the model's t0
  const InvalidInput early = expect_invalid([&] { compare(late, good); });
  EXPECT_EQ(early.parameter(), "t[0]");
  EXPECT_NE(early.rule().find("t0 = 1"), std::string::npos) << early.what();

  TimeHistory decreasing = good;
  decreasing.t[3] = decreasing.t[1];
  EXPECT_EQ(expect_invalid([&] { compare(seed_model(0.7), decreasing); }).parameter(), "t[3]");
  TimeHistory ragged = good;
  ragged.v.pop_back();
  EXPECT_EQ(expect_invalid([&] { compare(seed_model(0.7), ragged); }).parameter(), "v");
  TimeHistory nan = good;
  nan.v[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expect_invalid([&] { compare(seed_model(0.7), nan); }).parameter(), "v[2]");
}

// ---------------------------------------------------------------------------
// The detector.

TEST(CompareDetectSticks, InterpolatedEndsAndMinimumDuration) {
  //            t: 0    1    2    3    4    5    6    7    8
  const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> v{0, 0, 2, -2, 0.5, 0, 0.5, 2, 0.5};
  const auto sticks = detect_sticks(t, v, 1.0, 0.3);
  ASSERT_EQ(sticks.size(), 3u);
  EXPECT_EQ(sticks[0].start, 0);  // the record starts at rest
  EXPECT_DOUBLE_EQ(sticks[0].end, 1.5);
  EXPECT_DOUBLE_EQ(sticks[1].start, 3 + 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(sticks[1].end, 6 + 0.5 / 1.5);
  EXPECT_EQ(sticks[1].first_row, 4u);
  EXPECT_EQ(sticks[1].last_row, 6u);
  EXPECT_DOUBLE_EQ(sticks[2].start, 7 + 1.0 / 1.5);
  EXPECT_EQ(sticks[2].end, 8);                          // ... and ends at rest
  EXPECT_EQ(detect_sticks(t, v, 1.0, 0.5).size(), 2u);  // the last one is too short
  EXPECT_EQ(detect_sticks(t, v, 1.0, 1.6).size(), 1u);  // and so is the first
}

TEST(CompareDetectSticks, StopExtrapolatedFromTheMovingSide) {
  // A linear slide to rest at t = 2 exactly, a quadratic breakaway at t = 5.
  const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> v{-4, -2, 0, 0, 0, 0, 1, 4, 9};
  auto sticks = detect_sticks(t, v, 0.5, 0);
  ASSERT_EQ(sticks.size(), 1u);
  EXPECT_EQ(sticks[0].start, 2);  // the zero of the line through (0, -4), (1, -2)
  EXPECT_EQ(sticks[0].end, 5.5);  // |v| = 0.5 between (5, 0) and (6, 1)
  // The extrapolated zero is kept between the last moving and first resting sample.
  const std::vector<double> slow{3, 2, 0.1, 0, 0, 0, 1, 4, 9};
  sticks = detect_sticks(t, slow, 0.5, 0);
  ASSERT_EQ(sticks.size(), 1u);
  EXPECT_EQ(sticks[0].start, 2);
}

// ---------------------------------------------------------------------------
// Correct candidates pass.

TEST(CompareExact, ExactCurvePassesEveryCheckCoarseAndFine) {
  for (const SeedCase& c : seed_cases) {
    for (double dt : {0.1, 0.05, 0.001}) {
      SCOPED_TRACE("lambda " + std::to_string(c.lambda) + " dt " + std::to_string(dt));
      const Model model = seed_model(c.lambda, c.v0);
      const ComparisonReport r = compare(model, exact_history(model, 30, dt));
      EXPECT_TRUE(r.failed_checks().empty()) << r.full_report();
      // Samples 0.1 apart leave the events between samples further apart
      // than the stop-time tolerance (0.0628): nothing there is seen, so the
      // verdict cannot be PASS.
      if (dt > r.stop_time_margin) {
        EXPECT_EQ(r.verdict, Verdict::inconclusive) << r.full_report();
        EXPECT_GT(r.unresolved_events, 0u);
        EXPECT_DOUBLE_EQ(r.resolving_step, 0.5 * r.stop_time_margin);
      } else {
        EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
        EXPECT_EQ(r.unresolved_phases + r.unresolved_events, 0u);
        EXPECT_EQ(r.resolving_step, 0);
      }
      EXPECT_LE(r.velocity_max_error, 1e-15);
      EXPECT_TRUE(r.has_displacement);
      EXPECT_TRUE(passes(r, CheckKind::displacement_max));
      EXPECT_EQ(r.exact_regime, c.regime);
      EXPECT_EQ(r.candidate_regime, c.regime);
      EXPECT_TRUE(r.missed.empty());
      EXPECT_TRUE(r.extra.empty());
      EXPECT_EQ(r.checks.size(), 8u);
    }
  }
}

TEST(CompareExact, DeadBandSticksMatchTheEnginePhases) {
  const Model model = seed_model(0.7);
  const ComparisonReport r = compare(model, exact_history(model, 30, 0.01));
  const std::vector<Phase> phases = stick_phases(model, 30);
  ASSERT_EQ(r.exact_phases.size(), phases.size());
  // Every engine stick is long (about 0.7); each is seen and matched.
  ASSERT_EQ(r.matched.size(), phases.size());
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const MatchedStick& m = r.matched[i];
    EXPECT_EQ(m.phase_start, phases[i].t_begin);
    EXPECT_EQ(m.phase_end, phases[i].t_end);
    EXPECT_EQ(m.start_error, 0);
    EXPECT_EQ(m.end_error, 0);
    // The detector sees |v| < 1e-3: shortly before the stop (v linear) and
    // some 0.05 after the breakaway (v quadratic).
    EXPECT_NEAR(m.exact.start, phases[i].t_begin, 0.01);
    EXPECT_NEAR(m.exact.end, phases[i].t_end, 0.07);
  }
  EXPECT_EQ(r.exact_shown_regime, Regime::dead_bands);
  EXPECT_NEAR(r.exact_stops_per_period, 2, 0.5);
}

TEST(CompareStiffSpring, SeedCasesPass) {
  for (const SeedCase& c : seed_cases) {
    SCOPED_TRACE("lambda " + std::to_string(c.lambda));
    const Model model = seed_model(c.lambda, c.v0);
    const TimeHistory candidate = stiff_spring_candidate(model, 30);
    ASSERT_EQ(candidate.rows(), 3001u);
    const ComparisonReport r = compare(model, candidate);
    EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
    EXPECT_EQ(r.candidate_regime, c.regime);
    // The ringing of the stuck mass on the spring is visible but small:
    // (R - |F|) / sqrt(K_f m) ~ 1e-4.
    if (c.lambda > 0.5) {
      EXPECT_GT(r.creep_max_velocity, 1e-6);
      EXPECT_LT(r.creep_max_velocity, 5e-4);
    }
    EXPECT_LT(r.velocity_max_error, 2e-3);
  }
}

TEST(CompareStiffSpring, SoftSpringCreepsAndFails) {
  // K_f = 1e4: the stuck mass rings at (R - |F|) / sqrt(K_f m) ~ 7e-3.
  const Model model = seed_model(0.7);
  const ComparisonReport r = compare(model, stiff_spring_candidate(model, 30, 1e4, 1e-3));
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::creep));
}

// ---------------------------------------------------------------------------
// One defect each, caught by the check that names it.

TEST(CompareDefect, TimeShift) {
  const Model model = seed_model(0.7);
  const double shift = 0.1;  // 1.6 % of a period
  TimeHistory candidate = exact_history(model, 30, 0.01);
  std::vector<double> shifted;
  for (double t : candidate.t) shifted.push_back(std::max(model.t0, t - shift));
  const std::vector<State> states = sample_at(model, shifted);
  for (std::size_t i = 0; i < states.size(); ++i) candidate.v[i] = states[i].v;
  candidate.x.reset();

  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::velocity_max));
  EXPECT_TRUE(fails(r, CheckKind::stop_times));
  EXPECT_TRUE(passes(r, CheckKind::missed_stops));
  EXPECT_TRUE(passes(r, CheckKind::extra_stops));
  EXPECT_TRUE(passes(r, CheckKind::regime));
  EXPECT_EQ(find_check(r, CheckKind::displacement_max), nullptr);  // no x column
  // Every stick is late by the shift, at both ends.
  ASSERT_FALSE(r.matched.empty());
  for (const MatchedStick& m : r.matched) {
    if (m.exact.start == r.t_first) continue;  // the start of the record is not shifted
    EXPECT_NEAR(m.start_error, shift, 0.01);
    EXPECT_NEAR(m.end_error, shift, 0.01);
  }
  const std::string message = find_check(r, CheckKind::stop_times)->message;
  EXPECT_NE(message.find("stick"), std::string::npos) << message;
}

TEST(CompareDefect, ScaledVelocity) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  for (double& v : candidate.v) v *= 1.1;
  candidate.x.reset();
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::velocity_max));
  // Where the velocity is zero, a scaled zero is zero: the sticks are right.
  EXPECT_TRUE(passes(r, CheckKind::stop_times));
  EXPECT_TRUE(passes(r, CheckKind::missed_stops));
  EXPECT_TRUE(passes(r, CheckKind::extra_stops));
  EXPECT_TRUE(passes(r, CheckKind::creep));
  EXPECT_TRUE(passes(r, CheckKind::regime));
  // The worst error is at the velocity peak, 10 % of 0.3147.
  EXPECT_NEAR(r.velocity_max_error, 0.03147, 0.001);
}

TEST(CompareDefect, CreepInsteadOfSticking) {
  const Model model = seed_model(0.7);
  const ComparisonReport r = compare(model, tanh_candidate(model, 30, 1e-2));
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::creep));
  EXPECT_GT(r.creep_max_velocity, 1e-3);
  // It never rests long enough to count as a stick.
  EXPECT_TRUE(fails(r, CheckKind::missed_stops));
  EXPECT_TRUE(fails(r, CheckKind::regime));
  EXPECT_EQ(r.candidate_regime, Regime::continuous);
}

TEST(CompareDefect, CreepAfterTheFinalStop) {
  const Model model = seed_model(1.01, -1);
  const ComparisonReport r = compare(model, tanh_candidate(model, 30, 1e-2));
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::creep));
  EXPECT_TRUE(fails(r, CheckKind::regime));  // moving at the end instead of at rest
  EXPECT_EQ(r.exact_shown_regime, Regime::stops);
}

TEST(CompareDefect, MissingStop) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  candidate.x.reset();
  const Phase removed = stick_phases(model, 30).at(2);  // about [6.36, 7.06]
  ASSERT_LT(removed.t_end, 15.0);                       // outside the regime window
  // A slow slide of 0.01 B/(m w) through the dead band (ramps of 0.002).
  for (std::size_t i = 0; i < candidate.t.size(); ++i) {
    const double t = candidate.t[i];
    if (t > removed.t_begin && t < removed.t_end)
      candidate.v[i] =
          0.01 * std::min({1.0, (t - removed.t_begin) / 0.002, (removed.t_end - t) / 0.002});
  }
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::missed_stops));
  ASSERT_EQ(r.missed.size(), 1u);
  EXPECT_NEAR(r.missed[0].start, removed.t_begin, 0.01);
  const std::string message = find_check(r, CheckKind::missed_stops)->message;
  EXPECT_NE(message.find("[6.36"), std::string::npos) << message;  // names the interval
  EXPECT_TRUE(passes(r, CheckKind::extra_stops));
  EXPECT_TRUE(passes(r, CheckKind::stop_times));
  EXPECT_TRUE(passes(r, CheckKind::velocity_max));
  EXPECT_TRUE(passes(r, CheckKind::velocity_rms));
  EXPECT_TRUE(passes(r, CheckKind::regime));
  EXPECT_TRUE(fails(r, CheckKind::creep));  // it slides where the exact mass is stuck
}

TEST(CompareDefect, ExtraStop) {
  const Model model = seed_model(0.3);  // continuous: reversals, no dead bands
  TimeHistory candidate = exact_history(model, 30, 0.01);
  candidate.x.reset();
  // The second reversal (the end of the second slip), well before the regime window.
  const Solution exact = solve(model, 30.0);
  ASSERT_GE(exact.phases.size(), 4u);
  const double reversal = exact.phases[2].t_end;
  ASSERT_LT(reversal, 15.0);
  for (std::size_t i = 0; i < candidate.t.size(); ++i)
    if (std::fabs(candidate.t[i] - reversal) <= 0.05) candidate.v[i] = 0;
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::extra_stops));
  ASSERT_EQ(r.extra.size(), 1u);
  EXPECT_NEAR(r.extra[0].start, reversal - 0.05, 0.02);
  EXPECT_TRUE(passes(r, CheckKind::missed_stops));
  EXPECT_TRUE(passes(r, CheckKind::creep));
  EXPECT_TRUE(passes(r, CheckKind::regime));
}

TEST(CompareDefect, Noise) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  candidate.x.reset();
  // Uniform noise in +-0.019 B/(m w), standard deviation 0.011 (a fixed LCG,
  // portable): above the RMS tolerance 0.01, each sample within the max 0.02.
  std::uint64_t state = 12345;
  const auto uniform = [&] {  // in [-1, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1p-52 - 1;
  };
  for (double& v : candidate.v) v += 0.019 * uniform();
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::velocity_rms));
  EXPECT_NEAR(r.velocity_rms_error, 0.011, 0.0005);
  // The max check alone would let it through.
  EXPECT_TRUE(passes(r, CheckKind::velocity_max));
  EXPECT_TRUE(fails(r, CheckKind::creep));
}

TEST(CompareDefect, SmallNoisePasses) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  std::uint64_t state = 99;
  for (double& v : candidate.v) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    v += 2e-4 * (static_cast<double>(state >> 11) * 0x1p-52 - 1);
  }
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
}

TEST(CompareDefect, DisplacementOffset) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  for (std::size_t i = 0; i < candidate.t.size(); ++i)
    if (candidate.t[i] > 20) (*candidate.x)[i] += 0.05;  // a jump in position only
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_TRUE(fails(r, CheckKind::displacement_max));
  EXPECT_NEAR(r.displacement_max_error, 0.05, 1e-12);
  EXPECT_GT(r.displacement_max_error_time, 20);
  EXPECT_EQ(r.failed_checks(), std::vector<std::string>{"displacement_max"});
}

// ---------------------------------------------------------------------------
// Reports.

TEST(CompareReport, BriefReportHasTheDiagnosisOneLinePerCheckAndTheVerdict) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  for (double& v : candidate.v) v *= 1.1;
  const ComparisonReport r = compare(model, candidate);
  const std::string brief = r.brief_report();
  EXPECT_EQ(brief.rfind("diagnosis: scale: v = 1.1 v_exact: ", 0), 0u) << brief;
  EXPECT_NE(brief.find("\nvelocity_max: FAIL max |v - v_exact| = "), std::string::npos) << brief;
  EXPECT_NE(brief.find("\nstop_times: PASS "), std::string::npos) << brief;
  EXPECT_NE(brief.find("\nregime: PASS "), std::string::npos) << brief;
  const std::string last = "verdict: FAIL (checks velocity_max, velocity_rms)\n";
  ASSERT_GE(brief.size(), last.size());
  EXPECT_EQ(brief.substr(brief.size() - last.size()), last) << brief;
  std::size_t lines = 0;
  for (char c : brief) lines += c == '\n';
  EXPECT_EQ(lines, r.checks.size() + 2);

  // The full report opens with the same diagnosis and ends with the rest.
  const std::string full = r.full_report();
  EXPECT_EQ(full.rfind("diagnosis: scale: ", 0), 0u) << full;
  for (const char* part : {"candidate: exact", "model: mass=1 amplitude=1 omega=1 friction=0.7",
                           "stick detection: |v| < 0.001 B/(m w)", "tolerances: velocity_max 0.02",
                           "stop_time 0.01 periods", "  stick 1: exact [0, "}) {
    EXPECT_NE(full.find(part), std::string::npos) << part << "\n" << full;
  }
  const std::string checks = brief.substr(brief.find('\n') + 1);
  EXPECT_EQ(full.substr(full.size() - checks.size()), checks);
}

TEST(CompareReport, ToleranceOptionsAreHonoured) {
  const Model model = seed_model(0.7);
  TimeHistory candidate = exact_history(model, 30, 0.01);
  for (double& v : candidate.v) v *= 1.1;
  candidate.x.reset();
  CompareOptions loose;
  loose.velocity_max_tolerance = 0.05;
  loose.velocity_rms_tolerance = 0.05;
  EXPECT_EQ(compare(model, candidate, loose).verdict, Verdict::pass);
}

}  // namespace
}  // namespace frictionref

namespace frictionref {
namespace {

// Found by fuzzing: a candidate with huge values (and a repeated time) made
// the RMS error NaN; it must be a finite or infinite number and FAIL.
TEST(CompareReport, HugeCandidateValuesGiveNoNaN) {
  TimeHistory history;
  history.t = {0, 1, 1, 2};
  history.v = {1e300, -1e300, 1.7e308, -1.7e308};
  history.source = "huge";
  const ComparisonReport report = compare(seed_model(0.7), history);
  EXPECT_FALSE(std::isnan(report.velocity_rms_error));
  EXPECT_FALSE(std::isnan(report.velocity_max_error));
  EXPECT_EQ(report.verdict, Verdict::fail);
  for (const Check& check : report.checks) EXPECT_FALSE(std::isnan(check.value)) << check.name();
}

// Found by fuzzing: a record shorter than the engine's time resolution is
// still compared (the engine gets a horizon it resolves).
TEST(CompareReport, RecordShorterThanTheTimeResolution) {
  TimeHistory history;
  history.t = {0, 1e-17};
  history.v = {0, 0};
  history.source = "short";
  const ComparisonReport report = compare(seed_model(0.7), history);
  EXPECT_EQ(report.rows, 2u);
  EXPECT_EQ(report.velocity_max_error, 0);
}

}  // namespace
}  // namespace frictionref
