// Events per second of the exact engine over 10^4 forcing periods, and the
// cost of one event in std::cos calls (docs/benchmarks.md): as the engine
// runs by default (the steady motion replayed: with dead bands the cycle from
// 50 digits after the first one, docs/theory.md 3.9; sliding continuously the
// fixed cycle and its transient from a reversal near it, 3.10) and event by
// event (SolveOptions::replay_min_cycles = 0).
#include <benchmark/benchmark.h>

#include <cmath>

#include "cos_baseline.hpp"
#include "frictionref/exact_engine.hpp"

namespace frictionref::bench {
namespace {

constexpr double kPeriods = 1e4;

// lambda = state.range(0) / 100: 0.3 slides continuously (reversals only),
// 0.7 and 0.9 have dead bands (stop, stick, breakaway).
void run_events(benchmark::State& state, const SolveOptions& options) {
  Model model;
  model.friction = static_cast<double>(state.range(0)) / 100;
  const double t_end = kPeriods * 2 * M_PI;
  std::uint64_t events = 0;
  std::uint64_t root_calls = 0;
  std::uint64_t sign_tests = 0;
  std::uint64_t replayed = 0;
  std::uint64_t in_50_digits = 0;
  for (auto _ : state) {
    ExactEngine engine(model, t_end, options);
    Phase phase;
    while (engine.next(phase)) benchmark::DoNotOptimize(phase);
    const Summary& s = engine.summary();
    events += s.phases;
    root_calls += s.root_function_calls;
    sign_tests += s.sign_tests;
    replayed += s.replayed_phases;
    in_50_digits += s.replay_values_in_50_digits;
  }
  const auto per_event = [&](std::uint64_t n) {
    return static_cast<double>(n) / static_cast<double>(events);
  };
  state.SetItemsProcessed(static_cast<std::int64_t>(events));
  state.counters["cos_calls_per_event"] = cos_calls_per(events);
  state.counters["root_calls_per_event"] = per_event(root_calls);
  state.counters["sign_tests_per_event"] = per_event(sign_tests);
  // The events replayed, and of their times and positions (two per event)
  // the share the double-double bound left to 50 digits.
  state.counters["replayed_share"] = per_event(replayed);
  state.counters["in_50_digits_share"] =
      replayed ? static_cast<double>(in_50_digits) / (2.0 * static_cast<double>(replayed)) : 0.0;
}

void BM_Events(benchmark::State& state) { run_events(state, SolveOptions{}); }
BENCHMARK(BM_Events)->Arg(30)->Arg(70)->Arg(90)->Unit(benchmark::kMillisecond);

void BM_EventsEventByEvent(benchmark::State& state) {
  SolveOptions options;
  options.replay_min_cycles = 0;
  run_events(state, options);
}
BENCHMARK(BM_EventsEventByEvent)->Arg(30)->Arg(70)->Arg(90)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
