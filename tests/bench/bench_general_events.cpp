// Events of the general model (docs/theory.md 7) over 10^3 forcing periods,
// in std::cos calls per event, beside the seed's BM_Events: the certified
// event search (first_zero.hpp) against the seed's closed-form pieces, on
// the cases of general_models.hpp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "cos_baseline.hpp"
#include "frictionref/exact_engine.hpp"
#include "general_models.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"

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
  const double t_end = kPeriods * 2 * M_PI;
  std::vector<Phase> slips;
  std::uint64_t phases = 0;
  {
    ExactEngine engine(model, t_end);
    Phase phase;
    while (engine.next(phase)) {
      ++phases;
      if (phase.kind != PhaseKind::stick) slips.push_back(phase);
    }
  }
  using Work = long double;
  const detail::Oscillator<Work> oscillator(model);
  const Work omega = model.omega;
  std::uint64_t events = 0;
  for (auto _ : state) {
    for (const Phase& p : slips) {
      const Work begin = omega * Work(p.t_begin), end = omega * Work(p.t_end);
      const int sign = p.kind == PhaseKind::slip_forward ? 1 : -1;
      const detail::LinearSlipLaw<Work> law(oscillator, sign, begin, omega * Work(p.x_begin),
                                            Work(p.v_begin));
      benchmark::DoNotOptimize(law.point(begin));
      benchmark::DoNotOptimize(law.point((begin + end) / 2));
      benchmark::DoNotOptimize(law.point(end));
    }
    events += phases;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(events));
  state.counters["cos_calls_per_event"] = cos_calls_per(events);
}
BENCHMARK(BM_GeneralEventFloor)->Apply(each_general_case)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
