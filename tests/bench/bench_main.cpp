// Measures the cos-call unit before any benchmark runs, so every ratio in the
// table comes from the same process and machine state.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "cos_baseline.hpp"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const double cos_ns = frictionref::bench::cos_call_seconds() * 1e9;
  benchmark::AddCustomContext("cos_call_ns", std::to_string(cos_ns));
  std::fprintf(stderr, "one std::cos call: %.3f ns (the unit of the cos_calls_per_* counters)\n",
               cos_ns);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
