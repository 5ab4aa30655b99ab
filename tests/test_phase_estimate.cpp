// The phase-count estimate behind the guard of `events` (phase_estimate.hpp):
// 4 per period of the fastest rate (forcing, harmonics, the spring's
// natural frequency), 4 per record sample interval, 4 for the transient.
// Expected values written by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"
#include "frictionref/phase_estimate.hpp"

namespace frictionref {
namespace {

TEST(PhaseEstimate, FourPerForcingPeriodAsTheSeedsGuard) {
  Model m;  // w = 1: 30 time units are 30 / (2 pi) periods
  const PhaseEstimate e = estimate_phases(m, 30);
  EXPECT_DOUBLE_EQ(e.phases, 30 * 4 / (2 * M_PI) + 4);
  EXPECT_EQ(e.basis, "4 per forcing period");
}

TEST(PhaseEstimate, TheFastestHarmonicCountsUnlessItsAmplitudeIsZero) {
  Model m;
  m.harmonics = {Harmonic{0.5, 10, 0}, Harmonic{0, 1000, 0}};
  const PhaseEstimate e = estimate_phases(m, 2 * M_PI);  // 10 periods of w = 10
  EXPECT_DOUBLE_EQ(e.phases, 44);
  EXPECT_EQ(e.basis, "4 per forcing period");
}

TEST(PhaseEstimate, AStiffSpringCountsByItsNaturalPeriod) {
  Model m;
  m.mass = 4;
  m.stiffness = 4e16;  // sqrt(k/m) = 1e8
  m.t0 = 10;
  const PhaseEstimate e = estimate_phases(m, 10 + 2 * M_PI);  // 1e8 natural periods
  EXPECT_DOUBLE_EQ(e.phases, 4e8 + 4);
  EXPECT_EQ(e.basis, "4 per natural period 2 pi sqrt(m/k)");
  m.stiffness = 1;  // slower than the forcing: the forcing counts
  EXPECT_EQ(estimate_phases(m, 12).basis, "4 per forcing period");
}

TEST(PhaseEstimate, ARecordCountsItsSampleIntervalsInsideTheRun) {
  Model m;
  m.amplitude = 0;
  auto r = std::make_shared<GroundMotion>();
  for (int i = 0; i <= 1000; ++i) {
    r->t.push_back(i * 0.01);
    r->a.push_back(0);
  }
  m.ground_motion = r;
  // Samples at 0, 0.01, ..., 5: 501 of them from t0 = 0 to t_end = 5.
  const PhaseEstimate e = estimate_phases(m, 5);
  EXPECT_DOUBLE_EQ(e.phases, 5 * 4 / (2 * M_PI) + 4 + 4 * 501);
  EXPECT_EQ(e.basis, "4 per record sample");
}

}  // namespace
}  // namespace frictionref
