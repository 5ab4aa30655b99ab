// The general model's benchmark cases (docs/benchmarks.md, "The general
// model"), for its events and its dense samples:
//   0: the seed's model at lambda 0.7 run through the general laws (static
//      friction set a rounding above R, so that the general family is used);
//   1: static 0.6 > sliding 0.4 friction, k = 1, c = 0.1;
//   2: k = 1, c = 0.05, lambda 0.3, a second harmonic 0.4 sin(2.5 t + 0.3);
//   3: case 2 without spring or damper (the seed's block, lambda 0.3, with
//      the second harmonic);
//   4: an over-damped spring, k = 1, c = 3 (damping ratio 1.5), lambda 0.3;
//   5: a damper alone, c = 0.2, lambda 0.3.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "frictionref/model.hpp"

namespace frictionref::bench {

inline constexpr int kGeneralCases = 6;

// Registers a benchmark once per case (its argument).
inline void each_general_case(benchmark::internal::Benchmark* b) {
  for (int which = 0; which < kGeneralCases; ++which) b->Arg(which);
}

inline Model general_model(std::int64_t which) {
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
    case 2:
      m.friction = 0.3;
      m.stiffness = 1;
      m.damping = 0.05;
      m.harmonics.push_back({0.4, 2.5, 0.3});
      break;
    case 3:
      m.friction = 0.3;
      m.harmonics.push_back({0.4, 2.5, 0.3});
      break;
    case 4:
      m.friction = 0.3;
      m.stiffness = 1;
      m.damping = 3;
      break;
    default:
      m.friction = 0.3;
      m.damping = 0.2;
      break;
  }
  return m;
}

}  // namespace frictionref::bench
