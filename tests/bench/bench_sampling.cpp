// Dense samples per second as `frictionref curve` takes them (UniformSampler:
// grid rows plus event rows), in std::cos calls per sample, for the seed's
// model and the general model's cases; and the seed's
// dense formula alone on its fast path and on its long double path, in the
// same run (docs/benchmarks.md, "Dense samples in double-double").
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "cos_baseline.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"
#include "general_models.hpp"
#include "laws/harmonic_coulomb/phase_formula.hpp"
#include "laws/linear_oscillator/phase_formula.hpp"

namespace frictionref::bench {
namespace {

constexpr double kPi = 3.141592653589793;

// lambda = L / 100 over 100 periods, 1000 samples per period.
Model dense_model(std::int64_t lambda_percent) {
  Model model;
  model.friction = static_cast<double>(lambda_percent) / 100;
  return model;
}
GridOptions dense_grid() {
  GridOptions grid;
  grid.t_end = 100 * 2 * kPi;
  grid.dt = 2 * kPi / 1000;
  grid.include_events = true;
  return grid;
}

// Each phase of the engine with the grid times inside it (the rows a
// sampler evaluates in that phase).
template <class Visit>
void for_each_phase_rows(const Model& model, const GridOptions& grid, Visit visit) {
  ExactEngine engine(model, grid.t_end);
  Phase phase;
  std::vector<double> times;
  std::uint64_t i = 0;
  while (engine.next(phase)) {
    times.clear();
    for (double t = model.t0 + static_cast<double>(i) * grid.dt; t < phase.t_end;
         t = model.t0 + static_cast<double>(++i) * grid.dt)
      times.push_back(t);
    visit(phase, times);
  }
}

// The share of slip rows the fast path leaves to long double (Formula: the
// seed's or the general model's phase formula).
template <class Formula>
double fallback_share(const Model& model, const GridOptions& grid) {
  std::uint64_t slip_rows = 0, fallbacks = 0;
  for_each_phase_rows(model, grid, [&](const Phase& phase, const std::vector<double>& times) {
    if (phase.kind == PhaseKind::stick) return;
    const Formula formula(model, phase);
    for (double t : times) {
      State state;
      ++slip_rows;
      if (!formula.fast_at(t, state)) ++fallbacks;
    }
  });
  return slip_rows ? static_cast<double>(fallbacks) / static_cast<double>(slip_rows) : 0;
}

// Every row of the sampler on the dense grid, as often as the benchmark asks,
// taken as `frictionref curve` and the Python binding take them: a phase's
// rows at a time, as columns (next(StateRows&)).
void sample_all(benchmark::State& state, const Model& model) {
  std::uint64_t samples = 0;
  for (auto _ : state) {
    UniformSampler sampler(model, dense_grid());
    StateRows rows;
    while (sampler.next(rows)) {
      benchmark::DoNotOptimize(rows);
      benchmark::ClobberMemory();
      samples += rows.size;
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}

void BM_DenseSamples(benchmark::State& state) {
  const Model model = dense_model(state.range(0));
  sample_all(state, model);
  state.counters["fallback_share"] =
      fallback_share<detail::HarmonicCoulombFormula<double>>(model, dense_grid());
}
BENCHMARK(BM_DenseSamples)->Arg(30)->Arg(70)->Unit(benchmark::kMillisecond);

// The general model's cases (general_models.hpp) on the same grid.
void BM_GeneralDenseSamples(benchmark::State& state) {
  const Model model = general_model(state.range(0));
  sample_all(state, model);
  state.counters["fallback_share"] =
      fallback_share<detail::LinearOscillatorFormula<double>>(model, dense_grid());
}
BENCHMARK(BM_GeneralDenseSamples)->Apply(each_general_case)->Unit(benchmark::kMillisecond);

// The formula alone over the same rows: /L/1 the fast path with its fallback
// (at_many, as the sampler calls it), /L/0 the long double path for every
// row (the dense output before the fast path), /L/2 the fast path one row
// per call (one useful lane of four: the cost of a double-double evaluation
// that cannot be spread over lanes, as an event's chain could not). The
// engine's phases are computed once, outside the timing.
void BM_DenseFormula(benchmark::State& state) {
  const Model model = dense_model(state.range(0));
  const std::int64_t mode = state.range(1);
  std::vector<Phase> phases;
  std::vector<std::vector<double>> rows;
  for_each_phase_rows(model, dense_grid(), [&](const Phase& phase, const std::vector<double>& t) {
    phases.push_back(phase);
    rows.push_back(t);
  });
  std::vector<State> out(1000);
  std::uint64_t samples = 0;
  for (auto _ : state) {
    for (std::size_t p = 0; p < phases.size(); ++p) {
      const detail::HarmonicCoulombFormula<double> formula(model, phases[p]);
      const std::vector<double>& t = rows[p];
      if (out.size() < t.size()) out.resize(t.size());
      if (mode == 1) {
        formula.at_many(t.data(), t.size(), out.data());
      } else if (mode == 2) {
        for (std::size_t i = 0; i < t.size(); ++i) out[i] = formula.at(t[i]);
      } else {
        for (std::size_t i = 0; i < t.size(); ++i) out[i] = formula.long_double_at(t[i]);
      }
      benchmark::DoNotOptimize(out.data());
      samples += t.size();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["cos_calls_per_sample"] = cos_calls_per(samples);
}
BENCHMARK(BM_DenseFormula)
    ->ArgNames({"lambda", "fast"})
    ->Args({30, 0})
    ->Args({30, 1})
    ->Args({70, 0})
    ->Args({70, 1})
    ->Args({30, 2})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frictionref::bench
