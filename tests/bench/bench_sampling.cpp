// Dense samples per second as `frictionref curve` takes them (UniformSampler:
// grid rows plus event rows), in std::cos calls per sample.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cos_baseline.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::bench {
namespace {

// lambda = state.range(0) / 100 over 100 periods, 1000 samples per period.
void BM_DenseSamples(benchmark::State& state) {
  Model model;
  model.friction = static_cast<double>(state.range(0)) / 100;
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
BENCHMARK(BM_DenseSamples)->Arg(30)->Arg(70)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
