// The machine-independent unit of the benchmarks: the time of one std::cos
// call on a double, measured in the same run as the benchmark it divides.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>

namespace frictionref::bench {

// Seconds per std::cos(double) call on arguments spread over [0, 2000 pi)
// (glibc's fast path; forcing phases of 1e4 periods lie there). Measured once,
// on first use, as the fastest of several timed loops (thread CPU time, as
// Google Benchmark's rates use).
double cos_call_seconds();

// A counter that Google Benchmark reports as the time per item in cos calls:
// rate-inverted, i.e. elapsed / (items * cos_call_seconds()).
inline benchmark::Counter cos_calls_per(std::uint64_t items) {
  return benchmark::Counter(static_cast<double>(items) * cos_call_seconds(),
                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace frictionref::bench
