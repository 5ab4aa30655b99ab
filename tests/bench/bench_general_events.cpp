// Events of the general model (docs/theory.md 7) over 10^3 forcing periods,
// in std::cos calls per event, beside the seed's BM_Events: the certified
// event search (first_zero.hpp) against the seed's closed-form pieces, on
// the cases of general_models.hpp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "cos_baseline.hpp"
#include "engine_slips.hpp"
#include "frictionref/exact_engine.hpp"
#include "general_models.hpp"

namespace frictionref::bench {
namespace {

constexpr double kPeriods = 1e3;

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
BENCHMARK(BM_GeneralEvents)->Apply(each_general_case)->Unit(benchmark::kMillisecond);

// The floor of this design's general event (docs/benchmarks.md, "Floors,
// measured"): for each slip of the same run, the slip's law built at its
// start and evaluated with error bounds three times (at its start, middle
// and end), the least the certified search does for a slip (theory.md 7.4,
// the counter evaluations_per_event above); no search, no root, no stick.
// In cos calls per event of the run (every phase, as BM_GeneralEvents
// counts), a lower bound on an event of this design.
void BM_GeneralEventFloor(benchmark::State& state) {
  const Model model = general_model(state.range(0));
  const EngineSlips run = engine_slips(model, kPeriods * 2 * M_PI);
  const detail::Oscillator<GeneralWork> oscillator(model);
  std::uint64_t events = 0;
  for (auto _ : state) {
    for (const Phase& slip : run.slips) {
      const auto law = general_law_at_start(oscillator, slip);
      const GeneralWork begin = law.tau_begin(), end = oscillator.omega() * GeneralWork(slip.t_end);
      benchmark::DoNotOptimize(law.point(begin));
      benchmark::DoNotOptimize(law.point((begin + end) / 2));
      benchmark::DoNotOptimize(law.point(end));
    }
    events += run.phases;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(events));
  state.counters["cos_calls_per_event"] = cos_calls_per(events);
}
BENCHMARK(BM_GeneralEventFloor)->Apply(each_general_case)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
