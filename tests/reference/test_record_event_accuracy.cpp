// The engine's event times for a rigid block under a ground motion against
// the independent 50-digit reference (record_reference_solver.hpp), in ulps
// of t, on the synthetic records of data/records (docs/accuracy.md,
// "Records"). Limit: 4 ulps on every well-conditioned event: a stop where
// the block decelerates at >= 1e-3 of the record's PGA, a breakaway where
// the net force crosses the band's edge at a slope >= 1e-3 PGA per second.
// Events not so conditioned are counted and shown, not judged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"
#include "record_reference_solver.hpp"

namespace frictionref {
namespace {

namespace ref = frictionref_reference;

const std::string kSource = FRICTIONREF_SOURCE_DIR;

double ulp(double t) { return std::nextafter(std::fabs(t), INFINITY) - std::fabs(t); }

struct Case {
  std::string record;
  double yield_accel_g;
  bool one_way;
  bool inverse;
};

struct Tally {
  std::size_t judged = 0, others = 0;
  double worst = 0, worst_other = 0;
};

void check(const Case& c, Tally& tally) {
  SCOPED_TRACE(c.record + " KY " + std::to_string(c.yield_accel_g) +
               (c.one_way ? " one-way" : " two-way") + (c.inverse ? " inverse" : ""));
  GroundMotionReadOptions read;
  read.inverse = c.inverse;
  auto ground = std::make_shared<const GroundMotion>(
      read_ground_motion(kSource + "/data/records/synthetic/" + c.record, read));
  Model m;
  m.amplitude = 0;
  m.friction = c.yield_accel_g * 9.80665;
  m.ground_motion = ground;
  m.one_way = c.one_way;
  const double t_end = ground->t.back() + 5;
  const Solution s = solve(m, t_end);
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;

  ref::RecordBlock block;
  block.t = ground->t;
  block.a = ground->a;
  block.mu = block.mu_static = m.friction;
  block.one_way = c.one_way;
  const std::vector<ref::RecordEvent> events = ref::solve_record_block(block, t_end);
  ASSERT_EQ(s.phases.size(), events.size() + 1) << s.summary.brief_report();
  const double pga = ground->pga();
  for (std::size_t i = 0; i < events.size(); ++i) {
    const Phase& before = s.phases[i];
    const double t = before.t_end;
    const double error = std::fabs(double(events[i].t - ref::Decimal50(t))) / ulp(t);
    EXPECT_EQ(s.phases[i + 1].kind == PhaseKind::stick          ? 0
              : s.phases[i + 1].kind == PhaseKind::slip_forward ? 1
                                                                : -1,
              events[i].kind_after)
        << "event " << i << " at t = " << t;
    // Conditioning from the engine's own dense output on either side.
    bool judged;
    if (before.kind == PhaseKind::stick) {
      const double dt = 1e-6;
      const double slope = std::fabs(m.ground_acceleration(t + dt) - m.ground_acceleration(t)) / dt;
      judged = slope >= 1e-3 * pga;
    } else {
      judged = std::fabs(s.state_at(t).a) >= 1e-3 * pga;
    }
    if (judged) {
      ++tally.judged;
      tally.worst = std::max(tally.worst, error);
      EXPECT_LE(error, 4) << "event " << i << " at t = " << t;
    } else {
      ++tally.others;
      tally.worst_other = std::max(tally.worst_other, error);
    }
  }
}

TEST(RecordEventAccuracy, SyntheticRecordsAgainstFiftyDigits) {
  Tally tally;
  for (const char* record : {"pulse-train.AT2", "noise-burst.AT2"})
    for (double ky : {0.02, 0.05, 0.1, 0.2})
      for (bool one_way : {true, false})
        for (bool inverse : {false, true}) check({record, ky, one_way, inverse}, tally);
  std::printf(
      "records: %zu well-conditioned events, worst %.2f ulps; %zu others, worst %.2f ulps\n",
      tally.judged, tally.worst, tally.others, tally.worst_other);
  EXPECT_GT(tally.judged, 500u);
}

}  // namespace
}  // namespace frictionref
