// The general family's sticks on a record skip the segments that a test in
// double proves well inside the band (LinearOscillatorFamily::stick_band).
// The skip must change nothing but the cost: random spring, damper,
// static-friction, offset, harmonic and one-way models on random records,
// run through the family with and without it, give the same phases bit for
// bit. The way without the skip is the engine before it (every segment
// through the at-rest rule and the certified search in long double), an
// independent check of each decision the double test takes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "engine/event_loop.hpp"
#include "frictionref/error.hpp"
#include "frictionref/model.hpp"
#include "hand_made_record.hpp"
#include "laws/linear_oscillator/family.hpp"

namespace frictionref {
namespace {

struct Outcome {
  std::vector<Phase> phases;
  Summary summary;
  bool invalid = false;
};

template <bool kSkip>
Outcome run(const Model& model, double t_end) {
  Outcome r;
  try {
    detail::EventLoop<double, detail::LinearOscillatorFamily<double, kSkip>> engine(model, t_end,
                                                                                    {});
    Phase phase;
    while (engine.next(phase)) r.phases.push_back(phase);
    r.summary = engine.summary();
  } catch (const InvalidInput&) {
    r.invalid = true;
  }
  return r;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same(const Phase& a, const Phase& b) {
  return a.kind == b.kind && same_bits(a.t_begin, b.t_begin) && same_bits(a.t_end, b.t_end) &&
         same_bits(a.x_begin, b.x_begin) && same_bits(a.x_end, b.x_end) &&
         same_bits(a.v_begin, b.v_begin) && same_bits(a.v_end, b.v_end);
}

// A record of three random sines and noise, uniform or jittered steps.
std::shared_ptr<const GroundMotion> random_record(std::mt19937_64& rng, double& duration) {
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 100 + static_cast<int>(u(rng) * 1400);
  const double dt = 0.005 + 0.045 * u(rng);
  const bool jitter = u(rng) < 0.3;
  double amplitude[3], frequency[3], phase[3];
  for (int j = 0; j < 3; ++j) {
    amplitude[j] = 0.5 + 3 * u(rng);
    frequency[j] = 0.5 + 15 * u(rng);
    phase[j] = 6.28 * u(rng);
  }
  const double noise = u(rng) < 0.5 ? 0.3 * u(rng) : 0;
  std::vector<double> t, a;
  double time = u(rng) < 0.2 ? u(rng) : 0;
  for (int i = 0; i < n; ++i) {
    double value = noise * (2 * u(rng) - 1);
    for (int j = 0; j < 3; ++j)
      value += amplitude[j] * std::sin(frequency[j] * time + phase[j]) *
               std::exp(-0.3 * (time - 2) * (time - 2) / (1 + n * dt));
    t.push_back(time);
    a.push_back(value);
    time += jitter ? dt * (0.5 + u(rng)) : dt;
  }
  duration = t.back();
  return testing::record(t, a);
}

TEST(GeneralRecordSkip, SamePhasesWithAndWithoutTheSkipOnRandomModels) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(0, 1);
  int models = 0, skipped = 0, invalid = 0;
  std::uint64_t phases = 0;
  for (int i = 0; i < 1500; ++i) {
    Model m;
    double duration = 0;
    m.ground_motion = random_record(rng, duration);
    m.amplitude = 0;
    m.mass = 0.5 + 2 * u(rng);
    m.friction = m.mass * (0.05 + 2 * u(rng));
    m.static_friction = m.friction * (u(rng) < 0.5 ? 1 : 1 + 0.5 * u(rng));
    const double natural = u(rng) < 0.8 ? 0.5 + 20 * u(rng) : 0;
    m.stiffness = m.mass * natural * natural;
    m.damping = u(rng) < 0.7 ? 2 * m.mass * (natural > 0 ? natural : 1) * 0.3 * u(rng) : 0;
    if (u(rng) < 0.3) m.force_offset = m.mass * (2 * u(rng) - 1);
    if (u(rng) < 0.3 || (m.stiffness == 0 && m.damping == 0))
      m.harmonics.push_back({m.mass * 0.5 * u(rng), 0.5 + 10 * u(rng), 6.28 * u(rng)});
    m.one_way = u(rng) < 0.3;
    if (u(rng) < 0.2) m.v0 = 2 * u(rng) - 1;
    if (u(rng) < 0.2) m.x0 = 0.1 * (2 * u(rng) - 1);
    const double t_end = duration + 2 * u(rng) + 0.1;
    const Outcome fast = run<true>(m, t_end);
    const Outcome full = run<false>(m, t_end);
    ASSERT_EQ(fast.invalid, full.invalid) << "model " << i;
    if (full.invalid) {
      ++invalid;
      continue;
    }
    ++models;
    ASSERT_EQ(fast.summary.termination, full.summary.termination) << "model " << i;
    ASSERT_EQ(fast.phases.size(), full.phases.size()) << "model " << i;
    for (std::size_t k = 0; k < full.phases.size(); ++k)
      ASSERT_TRUE(same(fast.phases[k], full.phases[k])) << "model " << i << " phase " << k;
    phases += full.phases.size();
    // A skipped segment counts one sign test where the full way counts
    // none (the search's early exit) or several (a search).
    skipped += fast.summary.sign_tests != full.summary.sign_tests;
  }
  std::printf("%d models (%d refused as input), %llu phases, the skip taken in %d\n", models,
              invalid, static_cast<unsigned long long>(phases), skipped);
  EXPECT_GE(models, 1400);
  EXPECT_GE(skipped, models / 2);  // the test exercises the skip
}

}  // namespace
}  // namespace frictionref
