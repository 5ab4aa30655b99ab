// compare() under a recorded ground motion (comparison.hpp,
// motion_scales.hpp): its tolerances are relative to the record's PGV,
// PGV^2/PGA and T* = 2 pi PGV/PGA, which coincide with the harmonic scales
// B/(m w), B/(m w^2) and 2 pi / w for a harmonic ground acceleration; a
// correct candidate passes, a wrong one fails with the record's units named.
//
// Candidates: the exact motion itself; an independent stiff-spring code
// written here (central differences, friction spring K_f = 1e7, the record
// interpolated here, not by the library); the same with its velocity scaled.
// And the exact motion of the seed model checked against a model whose record
// is that seed forcing, sampled: two engines, one answer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compare_helpers.hpp"
#include "expect_invalid.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"
#include "frictionref/motion_scales.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/time_history.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

using testing::exact_history;
using testing::expect_invalid;
using testing::find_check;

const std::string kSource = FRICTIONREF_SOURCE_DIR;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Newmark's rigid block on a synthetic record, two-way, KY = 0.1 g.
Model record_model() {
  Model m;
  m.amplitude = 0;
  m.friction = 0.1 * 9.80665;
  m.ground_motion = std::make_shared<const GroundMotion>(
      read_ground_motion(kSource + "/data/records/synthetic/noise-burst.AT2"));
  return m;
}

// A record of f(t) sampled every h on [0, t_end], in units where g = 1.
template <class F>
std::shared_ptr<const GroundMotion> sampled(F f, double t_end, double h) {
  auto r = std::make_shared<GroundMotion>();
  const auto n = static_cast<std::int64_t>(std::llround(t_end / h));
  for (std::int64_t i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) * h;
    r->t.push_back(t);
    r->a.push_back(f(t));
  }
  r->file = "sampled";
  r->npts = r->t.size();
  r->gravity = 1;
  return r;
}

// The stiff-spring code of compare_helpers.hpp under the record's force
// -m a_g(t), its own interpolation of the record, walked forward with the step.
TimeHistory stiff_spring_candidate(const Model& m, double t_end, double k_f, double dt,
                                   double archive) {
  const GroundMotion& record = *m.ground_motion;
  std::size_t i = 0;
  const auto force = [&](double t) {
    while (i + 2 < record.t.size() && record.t[i + 1] <= t) ++i;
    if (t > record.t.back()) return 0.0;
    const double s = (t - record.t[i]) / (record.t[i + 1] - record.t[i]);
    return -m.mass * (record.a[i] + s * (record.a[i + 1] - record.a[i]));
  };
  return testing::stiff_spring_history(m, t_end, force, k_f, dt, archive,
                                       "stiff spring on the record");
}

// ---------------------------------------------------------------------------
// The scales.

TEST(MotionScales, HarmonicForcing) {
  Model m;
  m.mass = 2;
  m.amplitude = 6;
  m.omega = 4;
  const MotionScales s = motion_scales(m, "to compare");
  EXPECT_EQ(s.velocity, 0.75);        // 6 / (2 * 4)
  EXPECT_EQ(s.displacement, 0.1875);  // 6 / (2 * 16)
  EXPECT_DOUBLE_EQ(s.period, M_PI / 2);
  EXPECT_EQ(s.velocity_name, "B/(m w)");
  EXPECT_EQ(s.displacement_name, "B/(m w^2)");
  EXPECT_EQ(s.period_unit, "periods");
}

TEST(MotionScales, RecordFromItsPeaks) {
  Model m;
  m.amplitude = 0;
  // a = 3 -> -1 over [0, 1]: PGA 3, PGV 9/8 (test_ground_motion.cpp).
  auto r = std::make_shared<GroundMotion>();
  r->t = {0, 1};
  r->a = {3, -1};
  r->file = "hand-made";
  m.ground_motion = r;
  const MotionScales s = motion_scales(m, "to compare");
  EXPECT_EQ(s.velocity, 1.125);
  EXPECT_EQ(s.displacement, 1.125 * 1.125 / 3);
  EXPECT_DOUBLE_EQ(s.period, 2 * M_PI * 1.125 / 3);
  EXPECT_EQ(s.velocity_name, "PGV");
  EXPECT_EQ(s.displacement_name, "PGV^2/PGA");
  EXPECT_EQ(s.period_unit, "T*");
}

// (B/m) cos(w t) as a record: PGA = B/m, PGV -> B/(m w), so the record's
// scales tend to the harmonic ones, to O(h^2).
TEST(MotionScales, HarmonicGroundAccelerationGivesTheHarmonicScales) {
  Model harmonic;
  harmonic.mass = 2;
  harmonic.amplitude = 6;
  harmonic.omega = 4;
  Model record = harmonic;
  record.amplitude = 0;
  const double b_over_m = 3, w = 4, h = 2 * M_PI / w / 4000;
  record.ground_motion =
      sampled([&](double t) { return b_over_m * std::cos(w * t); }, 3 * 2 * M_PI / w, h);
  const MotionScales a = motion_scales(harmonic, "to compare");
  const MotionScales b = motion_scales(record, "to compare");
  EXPECT_NEAR(b.velocity / a.velocity, 1, 1e-5);
  EXPECT_NEAR(b.displacement / a.displacement, 1, 1e-5);
  EXPECT_NEAR(b.period / a.period, 1, 1e-5);
}

TEST(MotionScales, RefusedWithoutAnExcitation) {
  Model m;
  m.amplitude = 0;
  InvalidInput e = expect_invalid([&] { motion_scales(m, "to compare"); });
  EXPECT_EQ(e.parameter(), "amplitude");
  EXPECT_TRUE(contains(e.rule(), "must be > 0 to compare")) << e.what();
  m.ground_motion = sampled([](double) { return 0.0; }, 1, 0.5);
  e = expect_invalid([&] { motion_scales(m, "for convergence"); });
  EXPECT_EQ(e.parameter(), "ground_motion");
  EXPECT_EQ(e.value(), "sampled");
  EXPECT_TRUE(contains(e.rule(), "zero throughout for convergence")) << e.what();
  // A record whose PGV underflows: the scales would be 0.
  m.ground_motion = sampled([](double) { return 1e-300; }, 1e-20, 1e-20);
  e = expect_invalid([&] { motion_scales(m, "to compare"); });
  EXPECT_EQ(e.parameter(), "ground_motion");
  EXPECT_TRUE(contains(e.rule(), "finite, non-zero scales")) << e.what();
}

// ---------------------------------------------------------------------------
// Candidates.

TEST(CompareRecord, ExactMotionPassesWithTheRecordsScales) {
  const Model model = record_model();
  const ComparisonReport r = compare(model, exact_history(model, 12, 0.005));
  EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
  EXPECT_EQ(r.scales.velocity, model.ground_motion->pgv());
  EXPECT_EQ(r.scales.velocity_name, "PGV");
  EXPECT_EQ(r.stick_velocity, 1e-3 * model.ground_motion->pgv());
  // The block comes to rest once the ground is still: the steady state.
  EXPECT_EQ(r.exact_regime, Regime::stops);
  EXPECT_GT(r.exact_sticks.size(), 5u);
  EXPECT_EQ(r.matched.size(), r.exact_sticks.size());
  EXPECT_TRUE(contains(r.full_report(), "scales: velocity PGV = ")) << r.full_report();
  EXPECT_FALSE(contains(r.full_report(), "B/(m w)")) << r.full_report();
}

TEST(CompareRecord, IndependentStiffSpringCodePasses) {
  const Model model = record_model();
  const TimeHistory candidate = stiff_spring_candidate(model, 12, 1e7, 1e-5, 0.005);
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
  // The error is the penalty's and the step's, far under the tolerance.
  EXPECT_LT(r.velocity_max_error / r.scales.velocity, 5e-3) << r.full_report();
  EXPECT_GT(r.velocity_max_error, 0);
}

TEST(CompareRecord, ScaledVelocityFailsNamingPgv) {
  const Model model = record_model();
  TimeHistory candidate = exact_history(model, 12, 0.005);
  for (double& v : candidate.v) v *= 1.2;
  candidate.x.reset();
  const ComparisonReport r = compare(model, candidate);
  EXPECT_EQ(r.verdict, Verdict::fail);
  const Check* velocity = find_check(r, CheckKind::velocity_max);
  ASSERT_NE(velocity, nullptr);
  EXPECT_FALSE(velocity->passed);
  EXPECT_TRUE(contains(velocity->message, " PGV (")) << velocity->message;
  EXPECT_EQ(r.diagnosis.defect, Defect::scale) << r.full_report();
  EXPECT_NEAR(r.diagnosis.value, 1.2, 1e-6);
}

// The seed's forcing B sin(w t) is the record a_g = -(B/m) sin(w t): the
// seed's closed-form engine and the record engine on the sampled forcing
// agree to the interpolation's O(h^2), far inside compare's tolerances.
TEST(CompareRecord, SeedMotionPassesAgainstItsForcingAsARecord) {
  for (double lambda : {0.3, 0.7}) {
    SCOPED_TRACE(lambda);
    const Model seed = testing::seed_model(lambda);
    Model record = seed;
    record.amplitude = 0;
    record.ground_motion = sampled([](double t) { return -std::sin(t); }, 32, 2 * M_PI / 2000);
    const ComparisonReport r = compare(record, exact_history(seed, 30, 0.01));
    EXPECT_EQ(r.verdict, Verdict::pass) << r.full_report();
    // v_g = cos(t) - 1: PGV = 2 B/(m w), not B/(m w) (the ground starts at rest).
    EXPECT_NEAR(r.scales.velocity, 2, 1e-5);
    EXPECT_LT(r.velocity_max_error, 1e-5) << r.full_report();
  }
}

}  // namespace
}  // namespace frictionref
