// Ground-motion records (docs/theory.md 9), in std::cos calls per record
// sample: the exact engine streamed over a record of 10^4 samples
// (BM_RecordSamples), the whole Newmark analysis around it (permanent
// displacement, peak relative velocity: BM_NewmarkSamples), SLAMMER's
// trapezoidal algorithm on the same record (BM_SlammerSamples), one-way
// (Arg 1) and two-way (Arg 0); a spring-damper block on the same record
// (BM_GeneralRecordSamples: the general laws); and the batch of the speed issue, 100 records
// x 20 yield accelerations x 2 polarities of 10^4 samples each on 2 threads
// (BM_NewmarkBatch, wall time).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "cos_baseline.hpp"
#include "engine_slips.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/newmark.hpp"
#include "frictionref/slammer_rigid_block.hpp"

namespace frictionref::bench {
namespace {

constexpr std::size_t kSamples = 10'000;
constexpr double kStep = 0.005;  // 50 s of record

// A synthetic accelerogram in g: eight sines of 0.5..8 Hz with random
// amplitudes and phases under a build-up / decay envelope, PGA about 0.4 g.
// `seed` picks the record (deterministic per seed).
std::shared_ptr<const GroundMotion> synthetic_record(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto uniform = [&random](double low, double high) {
    return low + (high - low) * (static_cast<double>(random() >> 11) * 0x1p-53);
  };
  double frequency[8], amplitude[8], phase[8];
  for (int k = 0; k < 8; ++k) {
    frequency[k] = uniform(0.5, 8.0);
    amplitude[k] = uniform(0.02, 0.1);
    phase[k] = uniform(0, 2 * M_PI);
  }
  auto record = std::make_shared<GroundMotion>();
  record->file = "synthetic-" + std::to_string(seed);
  record->dt = kStep;
  record->npts = kSamples;
  for (std::size_t i = 0; i < kSamples; ++i) {
    const double t = static_cast<double>(i) * kStep;
    const double envelope = t < 5 ? t / 5 : std::exp(-(t - 5) / 12);
    double a = 0;
    for (int k = 0; k < 8; ++k)
      a += amplitude[k] * std::sin(2 * M_PI * frequency[k] * t + phase[k]);
    record->t.push_back(t);
    record->a.push_back(envelope * a * record->gravity);
  }
  return record;
}

// The exact engine streamed over a model with the record of kSamples samples
// to t_end, per record sample, with the phase count per run.
void stream_per_sample(benchmark::State& state, const Model& model, double t_end) {
  std::uint64_t phases = 0;
  for (auto _ : state) {
    ExactEngine engine(model, t_end);
    Phase phase;
    while (engine.next(phase)) benchmark::DoNotOptimize(phase);
    phases += engine.summary().phases;
  }
  const auto samples = static_cast<std::uint64_t>(state.iterations()) * kSamples;
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
  state.counters["phases_per_run"] =
      static_cast<double>(phases) / static_cast<double>(state.iterations());
}

void BM_RecordSamples(benchmark::State& state) {
  const bool one_way = state.range(0) != 0;
  const Model model =
      newmark_model(newmark_record(synthetic_record(1), Polarity::normal), 0.1, one_way);
  const double t_end = newmark_horizon(model);
  stream_per_sample(state, model, t_end);
}
BENCHMARK(BM_RecordSamples)->ArgName("one_way")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// The same record driving a spring-damper block (natural frequency 2 Hz, 5 %
// of critical damping, KY = 0.1, two-way) through the general laws (theory.md
// 9.6), to 5 s after the record: per record sample.
Model general_record_model() {
  Model model =
      newmark_model(newmark_record(synthetic_record(1), Polarity::normal), 0.1, /*one_way=*/false);
  const double natural = 2 * M_PI * 2;  // rad/s
  model.stiffness = model.mass * natural * natural;
  model.damping = 2 * 0.05 * model.mass * natural;
  return model;
}
void BM_GeneralRecordSamples(benchmark::State& state) {
  const Model model = general_record_model();
  stream_per_sample(state, model, model.ground_motion->t.back() + 5);
}
BENCHMARK(BM_GeneralRecordSamples)->Unit(benchmark::kMillisecond);

// The floor of this design's record path (docs/benchmarks.md, "Floors,
// measured"): for each slip of the same run, each record interval inside it
// takes one law built from the state at its start and one evaluation with
// error bounds at its end (the proof that the velocity keeps its sign
// there), and nothing else: no search, no stick. Per record sample, as
// BM_GeneralRecordSamples: a lower bound on that path.
void BM_GeneralRecordFloor(benchmark::State& state) {
  const Model model = general_record_model();
  const EngineSlips run = engine_slips(model, model.ground_motion->t.back() + 5);
  const detail::Oscillator<GeneralWork> oscillator(model);
  for (auto _ : state) {
    for (const Phase& slip : run.slips) {
      const GeneralWork end = oscillator.omega() * GeneralWork(slip.t_end);
      auto law = general_law_at_start(oscillator, slip);
      for (;;) {
        const bool last = law.segment_end() >= end;
        const auto q = law.point(last ? end : law.segment_end());
        benchmark::DoNotOptimize(q);
        if (last) break;
        law = law.continued_from(q);
      }
    }
  }
  const auto samples = static_cast<std::uint64_t>(state.iterations()) * kSamples;
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}
BENCHMARK(BM_GeneralRecordFloor)->Unit(benchmark::kMillisecond);

void BM_NewmarkSamples(benchmark::State& state) {
  const bool one_way = state.range(0) != 0;
  const auto record = synthetic_record(1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        newmark_analysis(*record, 0.1, one_way, Polarity::normal, NewmarkMethod::exact));
  }
  const auto samples = static_cast<std::uint64_t>(state.iterations()) * kSamples;
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}
BENCHMARK(BM_NewmarkSamples)->ArgName("one_way")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

void BM_SlammerSamples(benchmark::State& state) {
  SlammerOptions options;
  options.yield_accel_g = 0.1;
  options.two_way = state.range(0) == 0;
  const auto record = synthetic_record(1);
  for (auto _ : state) benchmark::DoNotOptimize(slammer_rigid_block(*record, options));
  const auto samples = static_cast<std::uint64_t>(state.iterations()) * kSamples;
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}
BENCHMARK(BM_SlammerSamples)->ArgName("one_way")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// 100 records x 20 KY (0.01 to 0.2 g) x 2 polarities, one-way, 2 threads.
void BM_NewmarkBatch(benchmark::State& state) {
  std::vector<std::shared_ptr<const GroundMotion>> records;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) records.push_back(synthetic_record(seed));
  NewmarkOptions options;
  for (int k = 1; k <= 20; ++k) options.yield_accels_g.push_back(0.01 * k);
  options.polarities = {Polarity::normal, Polarity::inverse};
  options.threads = 2;
  for (auto _ : state) benchmark::DoNotOptimize(newmark_batch(records, options));
  const auto samples = static_cast<std::uint64_t>(state.iterations()) * 100 * 20 * 2 * kSamples;
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
}
BENCHMARK(BM_NewmarkBatch)->UseRealTime()->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
