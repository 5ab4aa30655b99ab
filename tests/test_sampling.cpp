// Dense output (sampling.hpp): the uniform grid, event rows, sample_at and
// GridOptions validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/sampling.hpp"
#include "hand_made_record.hpp"

namespace frictionref {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using testing::expect_invalid;

// Seed model: m = B = w = 1, friction R (lambda = R).
Model seed_model(double friction, double t0 = 0, double v0 = 0, double x0 = 0) {
  Model model;
  model.friction = friction;
  model.t0 = t0;
  model.v0 = v0;
  model.x0 = x0;
  return model;
}

std::vector<State> all_rows(const Model& model, const GridOptions& grid) {
  UniformSampler sampler(model, grid);
  std::vector<State> rows;
  State state;
  while (sampler.next(state)) {
    rows.push_back(state);
    if (rows.size() > 10000000) {
      ADD_FAILURE() << "runaway sampler";
      break;
    }
  }
  // Once finished it stays finished.
  EXPECT_FALSE(sampler.next(state));
  return rows;
}

// The documented plain grid, built here: t0 + i dt (i as a double times dt)
// while below t_end - 1e-9 dt, then t_end.
std::vector<double> documented_grid(double t0, double t_end, double dt) {
  std::vector<double> times;
  for (std::uint64_t i = 0;; ++i) {
    const double t = t0 + static_cast<double>(i) * dt;
    if (!(t < t_end - 1e-9 * dt)) break;
    times.push_back(t);
  }
  times.push_back(t_end);
  return times;
}

struct GridCase {
  double t0, t_end, dt;
};
// T a multiple of dt in decimal (30 / 0.1, 0.07 / 0.01, 2.1 / 0.7, 1.1 / 0.1),
// not a multiple (10 / 0.3, 4.5 + 3 / 0.25 shifted), a negative t0, and a
// horizon a hair (below 1e-9 dt) beyond a grid point.
const GridCase kGridCases[] = {
    {0.0, 30.0, 0.1},        {0.0, 0.07, 0.01}, {0.0, 2.1, 0.7},
    {0.0, 1.1, 0.1},         {0.25, 10.0, 0.3}, {-3.0, 4.5, 0.25},
    {0.0, 3.0 + 1e-12, 1.0}, {1.0, 8.0, 0.5},   {0.0, 9.87, 1.0},
};

TEST(UniformSampler, RowsAreExactGridTimesThenTEndOnce) {
  for (const GridCase& g : kGridCases) {
    SCOPED_TRACE("t0=" + std::to_string(g.t0) + " t_end=" + std::to_string(g.t_end) +
                 " dt=" + std::to_string(g.dt));
    const Model model = seed_model(0.3, g.t0);
    const std::vector<State> rows = all_rows(model, {g.t_end, g.dt, false});
    const std::vector<double> expected = documented_grid(g.t0, g.t_end, g.dt);
    ASSERT_EQ(rows.size(), expected.size());
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].t, expected[i]) << "row " << i;
    // Strictly increasing, ends at t_end, and no near-duplicate of t_end.
    for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_LT(rows[i - 1].t, rows[i].t);
    EXPECT_EQ(rows.back().t, g.t_end);
    ASSERT_GE(rows.size(), 2u);
    EXPECT_GT(rows.back().t - rows[rows.size() - 2].t, 1e-9 * g.dt);
  }
}

TEST(UniformSampler, ThirtyByPointOneHasNoNearDuplicateOfThirty) {
  const std::vector<State> rows = all_rows(seed_model(0.3), {30.0, 0.1, false});
  ASSERT_EQ(rows.size(), 301u);  // t = 0, 0.1, ..., 29.9 and 30
  EXPECT_EQ(rows[299].t, 299 * 0.1);
  EXPECT_EQ(rows[300].t, 30.0);
  EXPECT_NEAR(rows[300].t - rows[299].t, 0.1, 1e-12);
}

TEST(GridOptions, GridRowsInSimpleExactCases) {
  EXPECT_EQ((GridOptions{1.0, 0.25, false}).grid_rows(0.0), 5u);  // 0 .25 .5 .75 1
  EXPECT_EQ((GridOptions{1.1, 0.25, false}).grid_rows(0.0), 6u);  // ... 1 and 1.1
  EXPECT_EQ((GridOptions{30.0, 0.1, false}).grid_rows(0.0), 301u);
  EXPECT_EQ((GridOptions{3.0, 1.0, false}).grid_rows(-2.0), 6u);  // -2 -1 0 1 2 3
  EXPECT_EQ((GridOptions{1.0, 2.0, false}).grid_rows(0.0), 2u);   // 0 and 1
}

TEST(GridOptions, GridRowsSaturates) {
  EXPECT_EQ((GridOptions{1e300, 1e-300, false}).grid_rows(0.0),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ((GridOptions{1e30, 1.0, false}).grid_rows(-1e30),
            std::numeric_limits<std::uint64_t>::max());
}

// grid_rows(t0) documents "Rows of the plain grid: t0, t0 + dt, ... below
// t_end, and t_end itself": the number of rows UniformSampler produces without
// events (the CLI prints it as metadata and uses it for its row limit).
TEST(GridOptions, GridRowsEqualsTheSamplerRowCount) {
  for (const GridCase& g : kGridCases) {
    SCOPED_TRACE("t0=" + std::to_string(g.t0) + " t_end=" + std::to_string(g.t_end) +
                 " dt=" + std::to_string(g.dt));
    const GridOptions grid{g.t_end, g.dt, false};
    const std::vector<State> rows = all_rows(seed_model(0.3, g.t0), grid);
    EXPECT_EQ(grid.grid_rows(g.t0), rows.size());
  }
}

// ---- events ----------------------------------------------------------------

// The interior phase boundaries of the exact solution up to t_end.
std::vector<double> interior_boundaries(const Solution& solution) {
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < solution.phases.size(); ++k)
    times.push_back(solution.phases[k].t_end);
  return times;
}

// Checks the event-grid rows against the plain grid merged with the
// boundaries, each row against state_at, and boundary rows against the phase
// that starts there.
void check_event_rows(const Model& model, const GridOptions& grid) {
  const Solution solution = solve(model, grid.t_end);
  const std::vector<double> boundaries = interior_boundaries(solution);
  ASSERT_FALSE(boundaries.empty());
  std::vector<double> expected = documented_grid(model.t0, grid.t_end, grid.dt);
  expected.insert(expected.end(), boundaries.begin(), boundaries.end());
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());

  const std::vector<State> rows = all_rows(model, grid);
  ASSERT_EQ(rows.size(), expected.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].t, expected[i]) << "row " << i;
    // The same state as the whole solution gives at that time.
    const State reference = solution.state_at(rows[i].t);
    EXPECT_EQ(rows[i].x, reference.x) << "t=" << rows[i].t;
    EXPECT_EQ(rows[i].v, reference.v) << "t=" << rows[i].t;
    EXPECT_EQ(rows[i].a, reference.a) << "t=" << rows[i].t;
    EXPECT_EQ(rows[i].phase, reference.phase) << "t=" << rows[i].t;
  }
  // At every interior boundary: the new phase, its start state and its
  // acceleration (B sin(w t) - s R) / m, the right limit.
  for (std::size_t k = 0; k < boundaries.size(); ++k) {
    const auto row = std::find_if(rows.begin(), rows.end(),
                                  [&](const State& s) { return s.t == boundaries[k]; });
    ASSERT_NE(row, rows.end());
    const Phase& next = solution.phases[k + 1];
    const int s = slip_sign(next.kind);
    EXPECT_EQ(row->phase, next.kind) << "boundary " << k << " t=" << row->t;
    EXPECT_EQ(row->x, next.x_begin);
    EXPECT_EQ(row->v, next.v_begin);
    const double a =
        s == 0
            ? 0.0
            : (model.amplitude * std::sin(model.omega * row->t) - s * model.friction) / model.mass;
    EXPECT_NEAR(row->a, a, 1e-14) << "boundary " << k << " t=" << row->t;
  }
  // The last row: t_end in the last phase with its stored end state.
  EXPECT_EQ(rows.back().t, grid.t_end);
  EXPECT_EQ(rows.back().phase, solution.phases.back().kind);
  EXPECT_EQ(rows.back().x, solution.phases.back().x_end);
  EXPECT_EQ(rows.back().v, solution.phases.back().v_end);
}

TEST(UniformSamplerEvents, DeadBandsAddEveryStopAndBreakaway) {
  check_event_rows(seed_model(0.7), {20.0, 0.1, true});
}

TEST(UniformSamplerEvents, ContinuousAddsEveryReversal) {
  check_event_rows(seed_model(0.3), {30.0, 0.37, true});
}

TEST(UniformSamplerEvents, OffsetStartAndOtherUnits) {
  Model model;
  model.mass = 2;
  model.amplitude = 3;
  model.omega = 0.5;
  model.friction = 2;  // lambda = 2/3: dead bands
  model.t0 = -1.5;
  model.x0 = 0.25;
  check_event_rows(model, {60.0, 0.4, true});
}

TEST(UniformSamplerEvents, WithoutEventsNoBoundaryRowsUnlessOnTheGrid) {
  const Model model = seed_model(0.7);
  const std::vector<State> rows = all_rows(model, {20.0, 0.1, false});
  const std::vector<double> grid = documented_grid(0.0, 20.0, 0.1);
  ASSERT_EQ(rows.size(), grid.size());
  const Solution solution = solve(model, 20.0);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].t, grid[i]);
    EXPECT_EQ(rows[i].x, solution.state_at(rows[i].t).x);
    EXPECT_EQ(rows[i].v, solution.state_at(rows[i].t).v);
  }
}

// A grid point exactly on a stop (lambda = 0.7): dt = t_stop / 4, a power of
// two division, so 4 dt == t_stop exactly.
TEST(UniformSamplerEvents, BoundaryOnAGridPointAppearsOnceWithTheNewPhase) {
  const Model model = seed_model(0.7);
  const Solution long_run = solve(model, 20.0);
  ASSERT_GE(long_run.phases.size(), 3u);
  ASSERT_EQ(long_run.phases[1].kind, PhaseKind::slip_forward);
  ASSERT_EQ(long_run.phases[2].kind, PhaseKind::stick);
  const double t_stop = long_run.phases[1].t_end;  // ~3.2198
  const double dt = t_stop / 4;
  ASSERT_EQ(0.0 + 4.0 * dt, t_stop);

  for (bool events : {true, false}) {
    SCOPED_TRACE(events ? "with events" : "without events");
    const std::vector<State> rows = all_rows(model, {20.0, dt, events});
    EXPECT_EQ(
        std::count_if(rows.begin(), rows.end(), [&](const State& s) { return s.t == t_stop; }), 1);
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const State& s) { return s.t == t_stop; });
    ASSERT_NE(row, rows.end());
    // The new phase (stick) and its acceleration 0, not the slip's
    // sin(t_stop) - 0.7 (about -0.78).
    EXPECT_EQ(row->phase, PhaseKind::stick);
    EXPECT_EQ(row->a, 0.0);
    EXPECT_EQ(row->v, 0.0);
    EXPECT_EQ(row->x, long_run.phases[1].x_end);
    if (events) {
      check_event_rows(model, {20.0, dt, true});
    }
  }
}

// A grid point exactly on a reversal (lambda = 0.3): the acceleration jumps by
// 2 lambda there; the row must carry the backward slip's value sin t + 0.3.
TEST(UniformSamplerEvents, ReversalOnAGridPointCarriesTheRightLimit) {
  const Model model = seed_model(0.3);
  const Solution long_run = solve(model, 30.0);
  ASSERT_GE(long_run.phases.size(), 4u);
  ASSERT_EQ(long_run.phases[1].kind, PhaseKind::slip_forward);
  ASSERT_EQ(long_run.phases[2].kind, PhaseKind::slip_backward);
  const double t_rev = long_run.phases[1].t_end;  // ~4.43
  const double dt = t_rev / 64;
  ASSERT_EQ(0.0 + 64.0 * dt, t_rev);

  for (bool events : {true, false}) {
    SCOPED_TRACE(events ? "with events" : "without events");
    const std::vector<State> rows = all_rows(model, {30.0, dt, events});
    const auto n =
        std::count_if(rows.begin(), rows.end(), [&](const State& s) { return s.t == t_rev; });
    EXPECT_EQ(n, 1);
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const State& s) { return s.t == t_rev; });
    ASSERT_NE(row, rows.end());
    EXPECT_EQ(row->phase, PhaseKind::slip_backward);
    EXPECT_NEAR(row->a, std::sin(t_rev) + 0.3, 1e-15);
    EXPECT_EQ(row->v, 0.0);
    if (events) check_event_rows(model, {30.0, dt, true});
  }
}

// ---- sample_at -------------------------------------------------------------

// An evaluator reached by for_phase from the one before (as the samplers
// walk a model's phases, sharing the model's own laws) gives the states of an
// evaluator built afresh, bit for bit, in every family: the seed's, the
// general model's (with a fast path, over-damped, and with a record) and the
// rigid block's on a record.
// A model of each family: the seed's, the general model's (with a fast path,
// and over-damped) and the rigid block's on a record, with a spring (k = 4).
std::vector<Model> models_of_every_family() {
  std::vector<double> record_t, record_a;
  for (int i = 0; i <= 300; ++i) {
    record_t.push_back(0.01 * i);
    record_a.push_back(3 * std::sin(0.37 * i) + std::sin(1.3 * i));
  }
  std::vector<Model> models(5);
  models[0].friction = 0.3;
  models[1].friction = 0.4;
  models[1].static_friction = 0.6;
  models[1].stiffness = 1;
  models[1].damping = 0.1;
  models[1].harmonics.push_back({0.4, 2.5, 0.3});
  models[2].friction = 0.3;
  models[2].stiffness = 1;
  models[2].damping = 3;
  for (int k : {3, 4}) {
    models[k].amplitude = 0;
    models[k].friction = 1;
    models[k].ground_motion = testing::record(record_t, record_a);
  }
  models[4].stiffness = 20;
  return models;
}

bool same_state(const State& a, const State& b) {
  return std::memcmp(&a.x, &b.x, sizeof(double)) == 0 &&
         std::memcmp(&a.v, &b.v, sizeof(double)) == 0 &&
         std::memcmp(&a.a, &b.a, sizeof(double)) == 0 && a.t == b.t && a.phase == b.phase;
}

TEST(PhaseEvaluator, ForPhaseGivesTheStatesOfAFreshEvaluator) {
  const std::vector<Model> models = models_of_every_family();
  for (std::size_t k = 0; k < models.size(); ++k) {
    const double t_end = models[k].ground_motion ? 3 : 40;
    ExactEngine engine(models[k], t_end);
    Phase phase;
    ASSERT_TRUE(engine.next(phase));
    PhaseEvaluator walked(models[k], phase);
    int phases = 0, slips = 0;
    do {
      if (phases > 0) walked = walked.for_phase(phase);
      const PhaseEvaluator fresh(models[k], phase);
      for (int j = 0; j <= 8; ++j) {
        const double t = j == 8 ? phase.t_end : phase.t_begin + phase.duration() * j / 8;
        ASSERT_TRUE(same_state(walked(t), fresh(t)))
            << "model " << k << " phase " << phases << " t=" << t;
      }
      ++phases;
      slips += phase.kind != PhaseKind::stick;
    } while (engine.next(phase));
    EXPECT_GT(slips, 3) << "model " << k;
  }
}

// The columns of an evaluator are its states, bit for bit, at many times of
// each phase at once (a phase's ends among them) and of every family.
TEST(PhaseEvaluator, ColumnsAreTheStatesOneAtATime) {
  for (const Model& model : models_of_every_family()) {
    const double t_end = model.ground_motion ? 3 : 40;
    ExactEngine engine(model, t_end);
    Phase phase;
    int phases = 0;
    while (engine.next(phase)) {
      const PhaseEvaluator law(model, phase);
      std::vector<double> times;
      for (int j = 0; j <= 100; ++j)
        times.push_back(j == 100 ? phase.t_end : phase.t_begin + phase.duration() * j / 100);
      std::vector<double> x(times.size()), v(times.size()), a(times.size());
      law(times.data(), times.size(), x.data(), v.data(), a.data());
      for (std::size_t i = 0; i < times.size(); ++i)
        ASSERT_TRUE(same_state({times[i], x[i], v[i], a[i], phase.kind}, law(times[i])))
            << "phase " << phases << " t=" << times[i];
      ++phases;
    }
    EXPECT_GT(phases, 6);
  }
}

// next(StateRows&) gives the rows of next(State&): each row as sample_at gives
// it at the same times (another path through the engine and the formulas),
// in blocks of one phase of at most 64 rows; and next(State&) and
// next(StateRows&) mixed on one sampler give the same rows in order.
TEST(UniformSampler, RowsAsColumnsAreTheRowsOfSampleAt) {
  for (const Model& model : models_of_every_family()) {
    for (const bool events : {false, true}) {
      GridOptions grid;
      grid.t_end = model.ground_motion ? 3 : 40;
      grid.dt = model.ground_motion ? 0.00037 : 0.013;
      grid.include_events = events;
      const std::vector<State> one_at_a_time = all_rows(model, grid);
      std::vector<State> blocks, mixed;
      UniformSampler sampler(model, grid);
      StateRows rows;
      std::size_t longest = 0;
      while (sampler.next(rows)) {
        ASSERT_GT(rows.size, 0u);
        ASSERT_LE(rows.size, 64u);
        longest = std::max(longest, rows.size);
        for (std::size_t i = 0; i < rows.size; ++i) blocks.push_back(rows[i]);
      }
      EXPECT_FALSE(sampler.next(rows));
      EXPECT_EQ(longest, 64u);  // the grid is fine enough for whole blocks
      UniformSampler alternating(model, grid);
      State state;
      for (int k = 0;; ++k) {
        if (k % 3 == 0) {
          if (!alternating.next(state)) break;
          mixed.push_back(state);
        } else {
          if (!alternating.next(rows)) break;
          for (std::size_t i = 0; i < rows.size; ++i) mixed.push_back(rows[i]);
        }
      }
      std::vector<double> times;
      for (const State& row : one_at_a_time) times.push_back(row.t);
      const std::vector<State> reference = sample_at(model, times);
      ASSERT_EQ(blocks.size(), reference.size());
      ASSERT_EQ(mixed.size(), reference.size());
      ASSERT_EQ(one_at_a_time.size(), reference.size());
      for (std::size_t i = 0; i < reference.size(); ++i) {
        ASSERT_TRUE(same_state(blocks[i], reference[i])) << "row " << i << " t=" << times[i];
        ASSERT_TRUE(same_state(mixed[i], reference[i])) << "row " << i;
        ASSERT_TRUE(same_state(one_at_a_time[i], reference[i])) << "row " << i;
      }
    }
  }
}

TEST(SampleAt, AgreesWithSolutionStateAt) {
  const Model model = seed_model(0.7, 0.0, 0.0, 1.5);
  const std::vector<double> times{0.0, 0.5, 1.7, 1.7, 3.0, 5.0, 9.25, 12.25};
  const std::vector<State> states = sample_at(model, times);
  ASSERT_EQ(states.size(), times.size());
  const Solution solution = solve(model, 12.25);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const State reference = solution.state_at(times[i]);
    EXPECT_EQ(states[i].t, times[i]);
    EXPECT_EQ(states[i].x, reference.x) << "t=" << times[i];
    EXPECT_EQ(states[i].v, reference.v) << "t=" << times[i];
    EXPECT_EQ(states[i].a, reference.a) << "t=" << times[i];
    EXPECT_EQ(states[i].phase, reference.phase) << "t=" << times[i];
  }
  // Before the first breakaway asin(0.7) = 0.775...: stuck at x0.
  EXPECT_EQ(states[1].phase, PhaseKind::stick);
  EXPECT_EQ(states[1].x, 1.5);
  EXPECT_EQ(states[1].v, 0.0);
}

TEST(SampleAt, AtPhaseBoundariesGivesTheNewPhase) {
  const Model model = seed_model(0.3);
  const Solution solution = solve(model, 25.0);
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < solution.phases.size(); ++k)
    times.push_back(solution.phases[k].t_end);
  ASSERT_GE(times.size(), 5u);
  times.push_back(25.0);
  const std::vector<State> states = sample_at(model, times);
  ASSERT_EQ(states.size(), times.size());
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const Phase& next = solution.phases[k + 1];
    EXPECT_EQ(states[k].phase, next.kind) << "boundary " << k;
    EXPECT_EQ(states[k].x, next.x_begin);
    EXPECT_EQ(states[k].v, 0.0);
    const int s = slip_sign(next.kind);
    EXPECT_NEAR(states[k].a, s == 0 ? 0.0 : std::sin(times[k]) - 0.3 * s, 1e-15);
  }
  EXPECT_EQ(states.back().phase, solution.phases.back().kind);
  EXPECT_EQ(states.back().x, solution.phases.back().x_end);
  EXPECT_EQ(states.back().v, solution.phases.back().v_end);
}

TEST(SampleAt, EmptyTimesGiveNoStates) { EXPECT_TRUE(sample_at(seed_model(0.3), {}).empty()); }

TEST(SampleAt, SingleTimeEqualToT0) {
  // Moving forward at t0 = 1 (v0 = 1): the first phase is slip+ and a = sin(1) - 0.3.
  const Model moving = seed_model(0.3, 1.0, 1.0, 2.0);
  std::vector<State> states;
  ASSERT_NO_THROW(states = sample_at(moving, {1.0}));
  ASSERT_EQ(states.size(), 1u);
  EXPECT_EQ(states[0].t, 1.0);
  EXPECT_EQ(states[0].x, 2.0);
  EXPECT_EQ(states[0].v, 1.0);
  EXPECT_EQ(states[0].phase, PhaseKind::slip_forward);
  // mpmath: sin(1) - mpf(0.3) = 0.5414709848078965177547326
  EXPECT_NEAR(states[0].a, 0.5414709848078965177547326, 2e-16);

  // At rest with |F| < R at t0 = 0: stuck, a = 0; repeated time allowed.
  const Model resting = seed_model(0.7, 0.0, 0.0, -4.0);
  ASSERT_NO_THROW(states = sample_at(resting, {0.0, 0.0}));
  ASSERT_EQ(states.size(), 2u);
  for (const State& s : states) {
    EXPECT_EQ(s.t, 0.0);
    EXPECT_EQ(s.x, -4.0);
    EXPECT_EQ(s.v, 0.0);
    EXPECT_EQ(s.a, 0.0);
    EXPECT_EQ(s.phase, PhaseKind::stick);
  }
}

TEST(SampleAt, DecreasingTimesRejected) {
  const InvalidInput error = expect_invalid([] {
    sample_at(seed_model(0.3), {0.0, 2.0, 1.0, 3.0});
  });
  EXPECT_EQ(error.parameter(), "times[2]");
  EXPECT_NE(error.rule().find(">="), std::string::npos);
}

TEST(SampleAt, TimesBeforeT0Rejected) {
  const Model model = seed_model(0.3, 1.0);
  EXPECT_EQ(expect_invalid([&] { sample_at(model, {0.5, 2.0}); }).parameter(), "times[0]");
  EXPECT_EQ(expect_invalid([&] { sample_at(model, {std::nextafter(1.0, 0.0)}); }).parameter(),
            "times[0]");
}

TEST(SampleAt, NonFiniteTimesRejected) {
  const Model model = seed_model(0.3);
  for (double bad : {kNaN, kInf, -kInf}) {
    const InvalidInput error = expect_invalid([&] { sample_at(model, {0.5, bad, 2.0}); });
    EXPECT_EQ(error.parameter(), "times[1]") << bad;
    EXPECT_EQ(error.rule(), "must be a finite number") << bad;
  }
  // NaN last as well (no comparison with NaN may let it through).
  EXPECT_EQ(expect_invalid([&] { sample_at(model, {0.5, kNaN}); }).parameter(), "times[1]");
  EXPECT_EQ(expect_invalid([&] { sample_at(model, {kNaN}); }).parameter(), "times[0]");
}

// ---- GridOptions::validate -------------------------------------------------

TEST(GridOptionsValidate, DefaultsAreValid) {
  const GridOptions grid{};
  EXPECT_NO_THROW(grid.validate(0.0));
  EXPECT_EQ(grid.t_end, 1.0);
  EXPECT_EQ(grid.dt, 0.01);
  EXPECT_FALSE(grid.include_events);
  EXPECT_EQ(grid.grid_rows(0.0), 101u);
}

TEST(GridOptionsValidate, TEndMustBeFiniteAndAfterT0) {
  for (double bad : {kNaN, kInf, -kInf}) {
    const InvalidInput error = expect_invalid([&] { GridOptions{bad, 0.1, false}.validate(0.0); });
    EXPECT_EQ(error.parameter(), "t_end") << bad;
    EXPECT_EQ(error.rule(), "must be a finite number") << bad;
  }
  for (double bad : {0.0, -1.0, std::nextafter(0.0, -1.0)}) {
    const InvalidInput error = expect_invalid([&] { GridOptions{bad, 0.1, false}.validate(0.0); });
    EXPECT_EQ(error.parameter(), "t_end") << bad;
  }
  EXPECT_EQ(expect_invalid([] {
              GridOptions{5.0, 0.1, false}.validate(5.0);
            }).parameter(),
            "t_end");
  EXPECT_EQ(expect_invalid([] {
              GridOptions{4.0, 0.1, false}.validate(5.0);
            }).parameter(),
            "t_end");
  EXPECT_NO_THROW((GridOptions{-4.0, 0.1, false}.validate(-5.0)));
}

TEST(GridOptionsValidate, DtMustBeFinitePositiveAndMoveT) {
  for (double bad : {kNaN, kInf, -kInf}) {
    const InvalidInput error = expect_invalid([&] { GridOptions{1.0, bad, false}.validate(0.0); });
    EXPECT_EQ(error.parameter(), "dt") << bad;
    EXPECT_EQ(error.rule(), "must be a finite number") << bad;
  }
  for (double bad : {0.0, -0.0, -0.1}) {
    const InvalidInput error = expect_invalid([&] { GridOptions{1.0, bad, false}.validate(0.0); });
    EXPECT_EQ(error.parameter(), "dt") << bad;
    EXPECT_EQ(error.rule(), "must be > 0") << bad;
  }
  // 1e9 + 1e-9 == 1e9: the grid would not move.
  EXPECT_EQ(expect_invalid([] {
              GridOptions{1e9 + 1, 1e-9, false}.validate(1e9);
            }).parameter(),
            "dt");
  // Also when only t_end is large.
  EXPECT_EQ(expect_invalid([] { GridOptions{1e9, 1e-9, false}.validate(0.0); }).parameter(), "dt");
  // A step that does move t is fine.
  EXPECT_NO_THROW((GridOptions{1e9 + 1, 1e-6, false}.validate(1e9)));
  // dt larger than the span is fine: rows t0 and t_end.
  EXPECT_NO_THROW((GridOptions{1.0, 5.0, false}.validate(0.0)));
}

TEST(GridOptionsValidate, SamplerConstructorValidates) {
  const Model model = seed_model(0.3);
  const auto construct = [](const Model& m, const GridOptions& grid) {
    UniformSampler sampler(m, grid);
    (void)sampler;
  };
  EXPECT_EQ(expect_invalid([&] { construct(model, {1.0, 0.0, false}); }).parameter(), "dt");
  EXPECT_EQ(expect_invalid([&] { construct(model, {1.0, -0.5, false}); }).parameter(), "dt");
  EXPECT_EQ(expect_invalid([&] { construct(model, {0.0, 0.1, false}); }).parameter(), "t_end");
  EXPECT_EQ(expect_invalid([&] { construct(model, {kNaN, 0.1, false}); }).parameter(), "t_end");
  Model bad = model;
  bad.mass = -1;
  EXPECT_EQ(expect_invalid([&] { construct(bad, {1.0, 0.1, false}); }).parameter(), "mass");
}

TEST(UniformSampler, DtLargerThanSpanGivesT0AndTEnd) {
  const Model model = seed_model(0.3, 0.5, 0.25, 1.0);
  const std::vector<State> rows = all_rows(model, {1.0, 5.0, false});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].t, 0.5);
  EXPECT_EQ(rows[0].x, 1.0);
  EXPECT_EQ(rows[0].v, 0.25);
  EXPECT_EQ(rows[1].t, 1.0);
}

}  // namespace
}  // namespace frictionref
