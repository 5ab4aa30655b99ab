// Events of the general model (docs/theory.md 7) over 10^3 forcing periods,
// in std::cos calls per event, beside the seed's BM_Events: the certified
// event search (first_zero.hpp) against the seed's closed-form pieces. And
// its dense samples as `frictionref curve` takes them, beside the seed's
// BM_DenseSamples (the same grid: 100 periods, 1000 samples per period).
//   0: the seed's model at lambda 0.7 run through the general laws (static
//      friction set a rounding above R, so that the general family is used);
//   1: static 0.6 > sliding 0.4 friction, k = 1, c = 0.1;
//   2: k = 1, c = 0.05, lambda 0.3, a second harmonic 0.4 sin(2.5 t + 0.3).
#include <benchmark/benchmark.h>

#include <cmath>

#include "cos_baseline.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::bench {
namespace {

constexpr double kPeriods = 1e3;

Model general_model(std::int64_t which) {
  Model m;
  switch (which) {
    case 0:
      m.friction = 0.7;
      m.static_friction = std::nextafter(0.7, 1.0);
      break;
    case 1:
      m.friction = 0.4;
      m.static_friction = 0.6;
      m.stiffness = 1;
      m.damping = 0.1;
      break;
    default:
      m.friction = 0.3;
      m.stiffness = 1;
      m.damping = 0.05;
      m.harmonics.push_back({0.4, 2.5, 0.3});
      break;
  }
  return m;
}

void BM_GeneralEvents(benchmark::State& state) {
  const Model model = general_model(state.range(0));
  const double t_end = kPeriods * 2 * M_PI;
  std::uint64_t events = 0, sign_tests = 0;
  for (auto _ : state) {
    ExactEngine engine(model, t_end);
    Phase phase;
    while (engine.next(phase)) benchmark::DoNotOptimize(phase);
    events += engine.summary().phases;
    sign_tests += engine.summary().sign_tests;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(events));
  state.counters["cos_calls_per_event"] = cos_calls_per(events);
  state.counters["evaluations_per_event"] =
      static_cast<double>(sign_tests) / static_cast<double>(events);
}
BENCHMARK(BM_GeneralEvents)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_GeneralDenseSamples(benchmark::State& state) {
  const Model model = general_model(state.range(0));
  GridOptions grid;
  grid.t_end = 100 * 2 * M_PI;
  grid.dt = 2 * M_PI / 1000;
  grid.include_events = true;
  std::uint64_t samples = 0;
  for (auto _ : state) {
    UniformSampler sampler(model, grid);
    State row;
    while (sampler.next(row)) {
      benchmark::DoNotOptimize(row);
      ++samples;
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}
BENCHMARK(BM_GeneralDenseSamples)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
