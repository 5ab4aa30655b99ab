// The cost of the event search in function evaluations, on fixed cases: a
// regression guard. Each count is what the engine needed when the ceiling
// was set (docs/benchmarks.md); the test fails if a change makes it go up.
// Lower is welcome: then lower the ceiling too.
//
// root_function_calls counts evaluations of s v (one sin_cos each) inside
// root finding; sign_tests the evaluations at piece ends (closed form at
// critical times, one full evaluation at the horizon).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "frictionref/exact_engine.hpp"

namespace frictionref {
namespace {

struct CountCase {
  const char* name;
  double lambda;
  double v0;
  double t_end;
  std::uint64_t max_root_calls;  // ceilings, as measured when set
  std::uint64_t max_sign_tests;
};

constexpr double kThousandPeriods = 2000 * M_PI;

const CountCase kCases[] = {
    {"seed 10.1 (lambda 0.3), 1000 periods", 0.3, 0, kThousandPeriods, 2064, 4000},
    {"seed 10.2 (lambda 0.7), 1000 periods", 0.7, 0, kThousandPeriods, 2013, 4000},
    {"lambda 0.9, 1000 periods", 0.9, 0, kThousandPeriods, 2019, 4000},
    {"seed 10.3 (lambda 1.01, v0 -1), t = 30", 1.01, -1, 30, 13, 1},
    {"lambda 0.5 from v0 = 5, 100 periods", 0.5, 5, 200 * M_PI, 253, 395},
};

TEST(RootCalls, DoNotGoUpOnFixedCases) {
  for (const CountCase& c : kCases) {
    SCOPED_TRACE(c.name);
    Model model;
    model.friction = c.lambda;
    model.v0 = c.v0;
    ExactEngine engine(model, c.t_end);
    Phase phase;
    while (engine.next(phase)) {
    }
    const Summary& s = engine.summary();
    std::printf("[ counts   ] %-42s stops %6llu  root calls %6llu  sign tests %6llu  predicted %6llu\n",
                c.name, static_cast<unsigned long long>(s.stops),
                static_cast<unsigned long long>(s.root_function_calls),
                static_cast<unsigned long long>(s.sign_tests),
                static_cast<unsigned long long>(s.predicted_stops));
    EXPECT_EQ(s.termination, Termination::reached_end);
    EXPECT_LE(s.root_function_calls, c.max_root_calls);
    EXPECT_LE(s.sign_tests, c.max_sign_tests);
  }
}

// In a steady state every stop is predicted and settles in one evaluation:
// over 10^4 periods the root calls per stop stay within 1% of one.
TEST(RootCalls, SteadyStateCostsOneEvaluationPerStop) {
  for (const double lambda : {0.3, 0.7, 0.9}) {
    SCOPED_TRACE(lambda);
    Model model;
    model.friction = lambda;
    ExactEngine engine(model, 20000 * M_PI);
    Phase phase;
    while (engine.next(phase)) {
    }
    const Summary& s = engine.summary();
    ASSERT_GT(s.stops, 19000u);
    EXPECT_LE(static_cast<double>(s.root_function_calls), 1.01 * static_cast<double>(s.stops));
    EXPECT_GE(static_cast<double>(s.predicted_stops), 0.999 * static_cast<double>(s.stops));
  }
}

}  // namespace
}  // namespace frictionref
