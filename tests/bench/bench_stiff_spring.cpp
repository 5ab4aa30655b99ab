// Time steps per second of the stiff-spring (penalty) simulator at the seed's
// K_f = 1e7 and its automatic step, in std::cos calls per step.
#include <benchmark/benchmark.h>

#include "cos_baseline.hpp"
#include "frictionref/stiff_spring.hpp"

namespace frictionref::bench {
namespace {

void BM_StiffSpringSteps(benchmark::State& state) {
  Model model;
  model.friction = static_cast<double>(state.range(0)) / 100;
  const double t_end = 10;
  std::uint64_t steps = 0;
  for (auto _ : state) {
    StiffSpringSimulator simulator(model, t_end);
    StiffSample sample;
    while (simulator.next(sample)) benchmark::DoNotOptimize(sample);
    steps += simulator.steps_taken();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(steps));
  state.counters["cos_calls_per_step"] = cos_calls_per(steps);
}
BENCHMARK(BM_StiffSpringSteps)->Arg(30)->Arg(70)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
