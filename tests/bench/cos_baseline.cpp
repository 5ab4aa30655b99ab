#include "cos_baseline.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <vector>

namespace frictionref::bench {
namespace {

// Arguments as an engine meets them: spread over 1000 forcing periods, not
// constants the compiler could fold.
std::vector<double> cos_arguments() {
  std::vector<double> arguments(4096);
  for (std::size_t i = 0; i < arguments.size(); ++i)
    arguments[i] = 2000 * M_PI * static_cast<double>(i * 2654435761u % 4096) / 4096.0;
  return arguments;
}

// CPU time of this thread: what Google Benchmark divides its rates by.
double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double measure() {
  const std::vector<double> arguments = cos_arguments();
  double best = 1e9;
  for (int repeat = 0; repeat < 7; ++repeat) {
    constexpr int kRounds = 500;
    const double start = cpu_seconds();
    for (int round = 0; round < kRounds; ++round)
      for (double a : arguments) benchmark::DoNotOptimize(std::cos(a));
    const double elapsed = cpu_seconds() - start;
    best = std::min(best, elapsed / (kRounds * static_cast<double>(arguments.size())));
  }
  return best;
}

}  // namespace

double cos_call_seconds() {
  static const double seconds = measure();
  return seconds;
}

// The baseline itself, so the table shows what one unit is on this machine.
void BM_StdCos(benchmark::State& state) {
  const std::vector<double> arguments = cos_arguments();
  for (auto _ : state)
    for (double a : arguments) benchmark::DoNotOptimize(std::cos(a));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(arguments.size()));
  state.counters["cos_calls_per_item"] = cos_calls_per(state.iterations() * arguments.size());
}
BENCHMARK(BM_StdCos);

}  // namespace frictionref::bench
