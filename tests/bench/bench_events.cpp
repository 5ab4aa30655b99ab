// Events per second of the exact engine over 10^4 forcing periods, and the
// cost of one event in std::cos calls (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cmath>

#include "cos_baseline.hpp"
#include "frictionref/exact_engine.hpp"

namespace frictionref::bench {
namespace {

constexpr double kPeriods = 1e4;

// lambda = state.range(0) / 100: 0.3 slides continuously (reversals only),
// 0.7 and 0.9 have dead bands (stop, stick, breakaway).
void BM_Events(benchmark::State& state) {
  Model model;
  model.friction = static_cast<double>(state.range(0)) / 100;
  const double t_end = kPeriods * 2 * M_PI;
  std::uint64_t events = 0;
  std::uint64_t root_calls = 0;
  std::uint64_t sign_tests = 0;
  for (auto _ : state) {
    ExactEngine engine(model, t_end);
    Phase phase;
    while (engine.next(phase)) benchmark::DoNotOptimize(phase);
    events += engine.summary().phases;
    root_calls += engine.summary().root_function_calls;
    sign_tests += engine.summary().sign_tests;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(events));
  state.counters["cos_calls_per_event"] = cos_calls_per(events);
  state.counters["root_calls_per_event"] =
      static_cast<double>(root_calls) / static_cast<double>(events);
  state.counters["sign_tests_per_event"] =
      static_cast<double>(sign_tests) / static_cast<double>(events);
}
BENCHMARK(BM_Events)->Arg(30)->Arg(70)->Arg(90)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
