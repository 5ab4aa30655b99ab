// The seed's steady cycle, computed once in 50 digits and replayed
// (docs/theory.md 3.9; SolveOptions::replay_min_cycles), against the same
// engine event by event (replay_min_cycles = 0) and against an independent
// 50-digit run: the 50-digit engine, event by event, started at the replay's
// base (the breakaway alpha + n0 pi, computed in 50 digits, with the work
// type's x there and v = 0).
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <random>
#include <vector>

#include "engine/event_loop.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/multiprecision.hpp"
#include "laws/harmonic_coulomb/converging_cycle.hpp"
#include "laws/harmonic_coulomb/family.hpp"
#include "random_models.hpp"

namespace frictionref {
namespace {

using Loop = detail::EventLoop<double, detail::HarmonicCoulombFamily<double>>;
using HighPhase = BasicPhase<HighPrecision>;

SolveOptions replay_after(std::uint64_t cycles) {
  SolveOptions options;
  options.replay_min_cycles = cycles;
  return options;
}

// Every phase of an engine or of the event loop itself.
template <class Stream>
std::vector<Phase> phases_of(Stream& stream) {
  std::vector<Phase> phases;
  Phase phase;
  while (stream.next(phase)) phases.push_back(phase);
  return phases;
}

// The exact motion from the replay's base, by the 50-digit engine event by
// event (a breakaway merged into its start instant is not a phase here).
std::vector<HighPhase> exact_from_base(const Model& model, const Loop& loop, double t_end) {
  const auto& replay = loop.family().cycle_replay();
  BasicModel<HighPrecision> start = model_cast<HighPrecision>(model);
  const HighPrecision pi = boost::math::constants::pi<HighPrecision>();
  if (replay.sliding())  // the reversal at the work type's base_tau()
    start.t0 = HighPrecision(replay.base_tau()) / start.omega;
  else
    start.t0 = (asin(start.friction / start.amplitude) + HighPrecision(replay.base_turns()) * pi) /
               start.omega;
  start.x0 = HighPrecision(replay.base_x());
  start.v0 = 0;
  BasicExactEngine<HighPrecision> engine(start, HighPrecision(t_end));
  std::vector<HighPhase> phases;
  HighPhase phase;
  while (engine.next(phase)) {
    // The start is a breakaway: a stick of a rounding's length there is
    // the start instant.
    if (phases.empty() && phase.kind == PhaseKind::stick &&
        phase.t_end - phase.t_begin < HighPrecision(1e-40) * (1 + abs(phase.t_end)))
      continue;
    phases.push_back(phase);
  }
  return phases;
}

// The index of the stick that ends at the base breakaway (nearest in time).
std::size_t base_stick(const std::vector<Phase>& phases, const HighPhase& first_exact) {
  const double t = static_cast<double>(first_exact.t_begin);
  std::size_t best = 0;
  double distance = HUGE_VAL;
  for (std::size_t i = 0; i + 1 < phases.size(); ++i) {
    if (phases[i].kind != PhaseKind::stick) continue;
    const double d = std::fabs(phases[i].t_end - t);
    if (d < distance) {
      distance = d;
      best = i;
    }
  }
  return best;
}

struct Counts {
  std::uint64_t models = 0, replaying_models = 0, phases = 0, replayed_phases = 0;
  std::uint64_t sliding_models = 0;  // replaying continuous sliding
  std::uint64_t differing = 0;  // values, each the correctly rounded one
  std::uint64_t differing_t = 0, differing_x = 0, differing_v = 0;
  std::uint64_t in_50_digits = 0;
};

// One model both ways: the same phases, and where a value differs, the
// replaying run's is the correctly rounded exact one. `all_values`: check
// every replayed value so, differing or not.
void compare(const testing::RandomModel& r, bool all_values, Counts& counts) {
  const Model& model = r.model;
  SCOPED_TRACE(testing::describe(r));
  std::optional<BasicExactEngine<double>> event_by_event;
  try {
    event_by_event.emplace(model, r.t_end, replay_after(0));
  } catch (const InvalidInput&) {
    return;  // out of the engine's range: the same either way (tested elsewhere)
  }
  const std::vector<Phase> a = phases_of(*event_by_event);
  Loop loop(model, r.t_end, replay_after(1));
  const std::vector<Phase> b = phases_of(loop);
  ++counts.models;
  counts.phases += b.size();
  ASSERT_EQ(a.size(), b.size());
  const auto& replay = loop.family().cycle_replay();
  const std::uint64_t replayed = loop.summary().replayed_phases;
  counts.replayed_phases += replayed;
  counts.in_50_digits += loop.summary().replay_values_in_50_digits;
  if (replay.replayed()) ++counts.replaying_models;
  if (replay.sliding()) ++counts.sliding_models;
  for (std::size_t i = 0; i < b.size(); ++i) {
    ASSERT_EQ(a[i].kind, b[i].kind) << "phase " << i;
    if (i > 0) {
      ASSERT_EQ(b[i].t_begin, b[i - 1].t_end) << "phase " << i;
      ASSERT_EQ(b[i].x_begin, b[i - 1].x_end) << "phase " << i;
      ASSERT_EQ(b[i].v_begin, b[i - 1].v_end) << "phase " << i;
    }
  }
  const Summary& sa = event_by_event->summary();
  const Summary& sb = loop.summary();
  ASSERT_EQ(sa.termination, sb.termination);
  ASSERT_EQ(sa.stops, sb.stops);
  ASSERT_EQ(sa.reversals, sb.reversals);
  ASSERT_EQ(sa.breakaways, sb.breakaways);
  ASSERT_EQ(sa.phases_by_kind, sb.phases_by_kind);
  bool differs = false;
  for (std::size_t i = 0; i < b.size() && !differs; ++i)
    differs = a[i].t_end != b[i].t_end || a[i].x_end != b[i].x_end || a[i].v_end != b[i].v_end;
  if (!replay.replayed()) {
    ASSERT_FALSE(differs) << "no replay, yet the phases differ";
    return;
  }
  if (!differs && !all_values) return;

  const std::vector<HighPhase> exact = exact_from_base(model, loop, r.t_end);
  ASSERT_FALSE(exact.empty());
  // The exact run starts after phase k: the stick that ends at the base
  // breakaway (its cycle 0 is then observed, not replayed), or the slip that
  // ends at the base reversal (then replayed from there).
  const std::size_t k =
      replay.sliding() ? b.size() - replayed - 1 : base_stick(b, exact.front());
  const std::size_t first_replayed = k + 1 + (replay.sliding() ? 0 : replay.cycle_length());
  const std::size_t end_replayed = first_replayed + replayed;
  ASSERT_EQ(end_replayed, b.size()) << "the replay goes on to the horizon";
  ASSERT_EQ(exact.size(), b.size() - (k + 1)) << "base stick " << k;
  // The scales of the motion's terms: a value that cancels to near zero (x
  // back at 0 after a slide there and back) is known to the 50-digit run
  // only to ~1e-48 of them. In velocity: (B + R) / (m w) per radian of
  // forcing phase, over a period; in x that over w, over a period.
  const double period = 2 * testing::kPiDouble;
  const double speed = (model.amplitude + model.friction) / (model.mass * model.omega) * period;
  double x_scale = std::fabs(model.x0) + speed / model.omega * period, v_scale = speed;
  for (const Phase& p : b) {
    x_scale = std::fmax(x_scale, std::fabs(p.x_end));
    v_scale = std::fmax(v_scale, std::fabs(p.v_end));
  }
  const double t_scale = std::fabs(model.t0) + std::fabs(r.t_end) + period / model.omega;
  for (std::size_t i = k + 1; i < b.size(); ++i) {
    const HighPhase& e = exact[i - (k + 1)];
    ASSERT_EQ(e.kind, b[i].kind) << "phase " << i;
    const bool is_replayed = i >= first_replayed && i < end_replayed;
    const auto check = [&](double value_a, double value_b, const HighPrecision& truth, double scale,
                           const char* what) {
      if (!is_replayed) {
        ASSERT_EQ(value_a, value_b) << what << " of phase " << i << ", not replayed";
        return;
      }
      if (value_a == value_b && !all_values) return;
      const HighPrecision error = abs(HighPrecision(value_b) - truth);
      // Correctly rounded, up to the 50-digit run's own resolution.
      const HighPrecision half_gap =
          HighPrecision(std::fabs(value_b) - std::nextafter(std::fabs(value_b), 0.0)) / 2;
      ASSERT_LE(error, half_gap + HighPrecision(1e-40 * scale))
          << what << " of replayed phase " << i << ": " << value_b << ", event by event " << value_a
          << ", exact " << truth.str(25);
      if (value_a == value_b) return;
      ++counts.differing;
      ++(what[0] == 't'   ? counts.differing_t
         : what[0] == 'x' ? counts.differing_x
                          : counts.differing_v);
    };
    check(a[i].t_end, b[i].t_end, e.t_end, t_scale, "t_end");
    check(a[i].x_end, b[i].x_end, e.x_end, x_scale, "x_end");
    check(a[i].v_end, b[i].v_end, e.v_end, v_scale, "v_end");
  }
}

// Models of the tests' random stream over 4 to 10 forcing periods.
testing::RandomModel longer(testing::RandomModel r, std::mt19937_64& random) {
  r.periods = 4 + 6 * static_cast<double>(random() >> 11) * 0x1.0p-53;
  r.t_end = r.model.t0 + r.periods * 2 * testing::kPiDouble / r.model.omega;
  return r;
}

void print(const Counts& c) {
  std::cout << c.models << " models (" << c.replaying_models << " replaying, "
            << c.sliding_models << " of them sliding continuously), " << c.phases
            << " phases, " << c.replayed_phases << " replayed (" << c.in_50_digits
            << " of their t and x rounded in 50 digits, the rest in double-double); " << c.differing
            << " values (t " << c.differing_t << ", x " << c.differing_x << ", v " << c.differing_v
            << ") differ from the event-by-event run's, each the correctly rounded exact one\n";
}

// 10^5 random models (every family of lambda, the stream of the other
// random tests over 4-10 periods), replayed from their first steady cycle
// on and event by event: the same phases, and every value where the two
// differ is the correctly rounded exact one in the replaying run. In four
// shards of 25,000 consecutive models of one stream, so that ctest runs them
// side by side.
class CycleReplayShard : public ::testing::TestWithParam<int> {};

TEST_P(CycleReplayShard, SameEventsAsEventByEventOnRandomModels) {
  constexpr int kShardSize = 25000;
  testing::ModelStream stream(1107);
  std::mt19937_64 random(1108);
  for (int i = 0; i < GetParam() * kShardSize; ++i) longer(stream.next(), random);
  Counts counts;
  for (int i = 0; i < kShardSize && !HasFatalFailure(); ++i)
    compare(longer(stream.next(), random), false, counts);
  print(counts);
  EXPECT_GT(counts.replaying_models, 2500u);
  EXPECT_GT(counts.differing, 0u);
  RecordProperty("differing", std::to_string(counts.differing));
}

INSTANTIATE_TEST_SUITE_P(CycleReplay, CycleReplayShard, ::testing::Values(0, 1, 2, 3));

// Every value of every replayed phase, not only where the two runs differ,
// is the correctly rounded exact one (the 50-digit run from the base), on
// the first 300 replaying models of another stream.
TEST(CycleReplay, EveryReplayedValueIsCorrectlyRounded) {
  testing::ModelStream stream(1109);
  std::mt19937_64 random(1110);
  Counts counts;
  for (int i = 0; i < 100000 && counts.replaying_models < 300 && !HasFatalFailure(); ++i)
    compare(longer(stream.next(), random), true, counts);
  print(counts);
  EXPECT_EQ(counts.replaying_models, 300u);
}

// The default replays only long runs (SolveOptions::replay_min_cycles =
// 1024 whole cycles left): the seed's lambda = 0.7 over 100 periods goes
// event by event; over 10^4 periods everything after the first whole cycle
// is replayed, to the horizon, with no value needing 50 digits.
TEST(CycleReplay, DefaultReplaysOnlyLongRuns) {
  Model model;
  model.friction = 0.7;
  ExactEngine short_run(model, 100 * 2 * M_PI);
  phases_of(short_run);
  EXPECT_EQ(short_run.summary().replayed_phases, 0u);
  ExactEngine long_run(model, 1e4 * 2 * M_PI);
  phases_of(long_run);
  const Summary& s = long_run.summary();
  EXPECT_EQ(s.phases, 40000u);
  EXPECT_GE(s.replayed_phases, s.phases - 10);
  EXPECT_EQ(s.replay_values_in_50_digits, 0u);
}

// A phase limit inside the replay ends the run as event by event: the same
// phase count, termination and last phase.
TEST(CycleReplay, PhaseLimitInsideTheReplay) {
  Model model;
  model.friction = 0.8;
  model.x0 = 0.25;
  SolveOptions options = replay_after(1);
  options.max_phases = 1001;
  ExactEngine replaying(model, 1e3 * 2 * M_PI, options);
  const std::vector<Phase> b = phases_of(replaying);
  options.replay_min_cycles = 0;
  ExactEngine event_by_event(model, 1e3 * 2 * M_PI, options);
  const std::vector<Phase> a = phases_of(event_by_event);
  ASSERT_EQ(a.size(), 1001u);
  ASSERT_EQ(b.size(), 1001u);
  EXPECT_GT(replaying.summary().replayed_phases, 900u);
  EXPECT_EQ(replaying.summary().termination, Termination::phase_limit);
  EXPECT_EQ(event_by_event.summary().termination, Termination::phase_limit);
  EXPECT_EQ(a.back().kind, b.back().kind);
  EXPECT_NEAR(a.back().t_end, b.back().t_end, 1e-12 * a.back().t_end);
  EXPECT_EQ(replaying.summary().final_state.t, b.back().t_end);
  EXPECT_EQ(replaying.summary().final_state.x, b.back().x_end);
}

// Models of the tests' random stream that slide continuously (0 <= lambda <
// lambda*, and lambda* (1 +- 10^-u), the stream's own masses, frequencies,
// starts and offsets), over
// 100 to 200 forcing periods: long enough for the reversals to come within
// 2^-44 rad of their fixed point and replay (docs/theory.md 3.10), unless
// lambda is so small that they converge too slowly, or the start's |w t0| so
// large that the work type's reversal times never get that close.
bool may_slide(const testing::RandomModel& r) {
  return r.family == testing::LambdaFamily::continuous ||
         r.family == testing::LambdaFamily::near_star;  // half of them below lambda*
}

testing::RandomModel sliding(testing::RandomModel r, std::mt19937_64& random) {
  r.periods = 100 + 100 * static_cast<double>(random() >> 11) * 0x1.0p-53;
  r.t_end = r.model.t0 + r.periods * 2 * testing::kPiDouble / r.model.omega;
  return r;
}

// Continuous sliding, replayed from a reversal near the fixed point on and
// event by event: the same phases, and every value where the two differ is
// the correctly rounded exact one (the 50-digit engine from the base
// reversal). Four shards of 1,000 consecutive models of one stream.
class SlidingReplayShard : public ::testing::TestWithParam<int> {};

TEST_P(SlidingReplayShard, SameEventsAsEventByEventOnRandomModels) {
  constexpr int kShardSize = 1000;
  testing::ModelStream stream(1111);
  std::mt19937_64 random(1112);
  int seen = 0;
  Counts counts;
  while (counts.models < kShardSize && !HasFatalFailure()) {
    const testing::RandomModel r = stream.next();
    if (!may_slide(r)) continue;
    const testing::RandomModel s = sliding(r, random);
    if (seen++ / kShardSize != GetParam()) continue;
    compare(s, false, counts);
  }
  print(counts);
  EXPECT_GT(counts.sliding_models, kShardSize / 4);
  EXPECT_GT(counts.differing, 0u);
  RecordProperty("differing", std::to_string(counts.differing));
}

INSTANTIATE_TEST_SUITE_P(CycleReplay, SlidingReplayShard, ::testing::Values(0, 1, 2, 3));

// Every value of every replayed phase of 40 models that slide continuously.
TEST(CycleReplay, EverySlidingValueIsCorrectlyRounded) {
  testing::ModelStream stream(1113);
  std::mt19937_64 random(1114);
  Counts counts;
  for (int i = 0; i < 100000 && counts.sliding_models < 40 && !HasFatalFailure(); ++i) {
    const testing::RandomModel r = stream.next();
    if (may_slide(r)) compare(sliding(r, random), true, counts);
  }
  print(counts);
  EXPECT_EQ(counts.sliding_models, 40u);
}

// Every value of three long continuous runs, replayed long past the point
// where kappa^k is dropped (below 2^-400: after some 390 reversals at
// lambda = 0.3, 1,400 at 0.1) and x and |a| are decided once per parity, against
// the 50-digit engine from the base reversal.
TEST(CycleReplay, EveryValueOfLongSlidingRuns) {
  Counts counts;
  for (const double lambda : {0.3, 0.1, 0.5}) {
    testing::RandomModel r;
    r.model.friction = lambda;
    r.model.mass = 1.5;
    r.model.omega = 2.5;
    r.model.x0 = -0.75;
    r.periods = 2000;
    r.t_end = r.periods * 2 * testing::kPiDouble / r.model.omega;
    compare(r, true, counts);
  }
  print(counts);
  EXPECT_EQ(counts.sliding_models, 3u);
  EXPECT_GT(counts.replayed_phases, 11000u);
}

// The continuous replay's three ways to a value give the same doubles: the
// double-double sums where their bound decides (what the other tests
// check against the 50-digit engine), the 50-digit linear transient with
// its bound, and the reversal map iterated in 50 digits from the base. Every
// end of 300 reversals of 30 replaying models of the random stream, and the
// state at a horizon inside each of the first 40 slips and at their ends.
TEST(CycleReplay, SlidingFallbacksGiveTheSameValues) {
  testing::ModelStream stream(1115);
  std::mt19937_64 random(1116);
  int models = 0;
  std::uint64_t values = 0;
  for (int i = 0; i < 100000 && models < 30 && !HasFatalFailure(); ++i) {
    const testing::RandomModel r = stream.next();
    if (!may_slide(r)) continue;
    const testing::RandomModel s = sliding(r, random);
    std::optional<Loop> loop;
    try {
      loop.emplace(s.model, s.t_end, replay_after(1));
    } catch (const InvalidInput&) {
      continue;
    }
    const std::vector<Phase> phases = phases_of(*loop);
    const auto& replay = loop->family().cycle_replay();
    if (!replay.sliding()) continue;
    ++models;
    SCOPED_TRACE(testing::describe(s));
    const PhaseKind first = phases[phases.size() - loop->summary().replayed_phases].kind;
    const int direction = first == PhaseKind::slip_forward ? 1 : -1;
    std::vector<detail::ConvergingCycle> ways;
    for (int level = 0; level < 3; ++level) {
      std::optional<detail::ConvergingCycle> cycle = detail::ConvergingCycle::compute(s.model);
      ASSERT_TRUE(cycle);
      ASSERT_TRUE(cycle->start(replay.base_tau(), replay.base_x(), direction));
      cycle->force_fallback(level);
      ways.push_back(*cycle);
    }
    double t_before = phases[phases.size() - loop->summary().replayed_phases].t_begin;
    for (int k = 0; k < 300; ++k) {
      const detail::ConvergingCycle::End fast = ways[0].next_end();
      for (int level = 1; level < 3; ++level) {
        const detail::ConvergingCycle::End other = ways[level].next_end();
        ASSERT_EQ(fast.kind, other.kind) << "reversal " << k + 1 << ", level " << level;
        ASSERT_EQ(fast.t, other.t) << "reversal " << k + 1 << ", level " << level;
        ASSERT_EQ(fast.x, other.x) << "reversal " << k + 1 << ", level " << level;
        ASSERT_EQ(fast.acceleration, other.acceleration) << "reversal " << k + 1 << ", level " << level;
        values += 3;
      }
      if (k < 40) {
        // Inside the slip, and at its end (stopped there).
        for (const double t_end : {t_before + 0.37 * (fast.t - t_before), fast.t}) {
          const detail::ConvergingCycle::Horizon h0 = ways[0].horizon(t_end);
          for (int level = 1; level < 3; ++level) {
            const detail::ConvergingCycle::Horizon h = ways[level].horizon(t_end);
            ASSERT_EQ(h0.x, h.x) << "slip " << k << ", level " << level << ", t_end " << t_end;
            ASSERT_EQ(h0.v, h.v) << "slip " << k << ", level " << level << ", t_end " << t_end;
            ASSERT_EQ(h0.acceleration, h.acceleration) << "slip " << k << ", level " << level;
            values += 3;
          }
        }
      }
      t_before = fast.t;
      for (auto& way : ways) way.advance();
    }
  }
  std::cout << models << " models, " << values << " values compared\n";
  EXPECT_EQ(models, 30);
}

// The seed's continuous sliding (lambda = 0.3) over 10^4 periods, by
// default: everything after the reversals come within 2^-44 rad of their
// fixed point (some 45 of them) is replayed, to the horizon, with no value
// needing 50 digits; the last reversal is the exact fixed point's to within
// rounding (theory.md 5.4: tau1 = acos(0.3 pi / 2) + n pi).
TEST(CycleReplay, ContinuousSlidingReplaysLongRuns) {
  Model model;
  model.friction = 0.3;
  ExactEngine short_run(model, 100 * 2 * M_PI);
  phases_of(short_run);
  EXPECT_EQ(short_run.summary().replayed_phases, 0u);
  ExactEngine engine(model, 1e4 * 2 * M_PI);
  const std::vector<Phase> phases = phases_of(engine);
  const Summary& s = engine.summary();
  EXPECT_GE(s.replayed_phases, s.phases - 100);
  EXPECT_EQ(s.replay_values_in_50_digits, 0u);
  EXPECT_EQ(s.reversals, s.stops);
  EXPECT_GT(s.stops, 19990u);
  const Phase& last_reversal = phases[phases.size() - 2];
  const double tau1 = std::acos(0.3 * M_PI / 2);
  const double n = std::round((last_reversal.t_end - tau1) / M_PI);
  EXPECT_NEAR(last_reversal.t_end, tau1 + n * M_PI, 1e-11);
}

// No replay where the reversal map does not contract enough (lambda = 0:
// kappa = -1), where the force at the reversal barely beats friction (just
// below lambda*), or where the work type's reversal times stay farther
// than 2^-44 rad from the fixed point (|w t| near 1e9).
TEST(CycleReplay, ContinuousSlidingReplayGuards) {
  const auto replayed = [](double friction, double t0) {
    Model model;
    model.friction = friction;
    model.t0 = t0;
    ExactEngine engine(model, t0 + 3000 * 2 * M_PI, replay_after(1));
    phases_of(engine);
    return engine.summary().replayed_phases;
  };
  EXPECT_GT(replayed(0.3, 0), 5000u);
  EXPECT_EQ(replayed(0, 0), 0u);
  EXPECT_EQ(replayed(testing::kLambdaStar * (1 - 1e-9), 0), 0u);
  EXPECT_EQ(replayed(0.3, 1e9), 0u);
}

// A phase limit inside the continuous replay ends the run as event by event.
TEST(CycleReplay, PhaseLimitInsideTheSlidingReplay) {
  Model model;
  model.friction = 0.4;
  model.x0 = -3;
  SolveOptions options = replay_after(1);
  options.max_phases = 1001;
  ExactEngine replaying(model, 1e3 * 2 * M_PI, options);
  const std::vector<Phase> b = phases_of(replaying);
  options.replay_min_cycles = 0;
  ExactEngine event_by_event(model, 1e3 * 2 * M_PI, options);
  const std::vector<Phase> a = phases_of(event_by_event);
  ASSERT_EQ(a.size(), 1001u);
  ASSERT_EQ(b.size(), 1001u);
  EXPECT_GT(replaying.summary().replayed_phases, 900u);
  EXPECT_EQ(replaying.summary().termination, Termination::phase_limit);
  EXPECT_EQ(a.back().kind, b.back().kind);
  EXPECT_NEAR(a.back().t_end, b.back().t_end, 1e-12 * a.back().t_end);
  EXPECT_NEAR(a.back().x_end, b.back().x_end, 1e-12);
}

}  // namespace
}  // namespace frictionref
