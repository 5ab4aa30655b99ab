// frictionref.curve(): the exact state at given times, or on the CLI's
// uniform grid (`curve --t-end T --dt H [--include-events]`).
#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "events.hpp"
#include "frictionref/sampling.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"

namespace frictionref::python {
namespace {

struct StateRow {
  double t, x, v, a;
  char32_t phase[5];
  std::uint32_t padding;
};

py::dtype state_dtype() {
  return record_dtype({{"t", "<f8", offsetof(StateRow, t)},
                       {"x", "<f8", offsetof(StateRow, x)},
                       {"v", "<f8", offsetof(StateRow, v)},
                       {"a", "<f8", offsetof(StateRow, a)},
                       {"phase", "<U5", offsetof(StateRow, phase)}},
                      sizeof(StateRow));
}

StateRow state_row(const State& s) {
  StateRow row{s.t, s.x, s.v, s.a, {}, 0};
  put_phase(row.phase, s.phase);
  return row;
}

// The state at each time of `t` (any order), written straight into the rows
// in the order given. The phase walk is sample_at()'s (sampling.cpp) over
// the times sorted: a time on a phase boundary gets the phase that starts
// there, and the last time the last phase.
py::array at_times(const PyModel& model, py::handle t_object) {
  const py::array_t<double> t = float_array(t_object, "t");
  const auto n = static_cast<std::size_t>(t.size());
  const double* times = t.data();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = "t[" + std::to_string(i) + "]";
    if (!std::isfinite(times[i]))
      value_error(name + " = " + number_text(times[i]) + ": must be a finite number");
    if (times[i] < model.model.t0)
      value_error(name + " = " + number_text(times[i]) +
                  ": must be >= t0 = " + number_text(model.model.t0));
  }
  std::vector<StateRow> rows(n);
  if (n == 0) return records(std::move(rows), state_dtype());
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
  const double t_max = times[order.back()];
  TypedInputs inputs = model.input.typed_inputs();
  inputs["t_end"] = {"max(t)", number_text(t_max)};
  // The engine's horizon is the last time, as for compare() and the grid
  // (the same numbers, bit for bit): a last time on a phase boundary gets
  // the phase that ends there, like the grid's row at t_end.
  const double last = resolvable_t_end(model.model, t_max);
  ExactEngine engine = naming(inputs, [&] { return ExactEngine(model.model, last); });
  {
    py::gil_scoped_release release;
    SignalCheck interrupt;
    Phase phase;
    engine.next(phase);
    std::optional<PhaseEvaluator> law(std::in_place, model.model, phase);
    // The times of one phase are evaluated together (the seed's fast path
    // takes four or eight at a time; the answers are those of one call per time).
    constexpr std::size_t kBatch = 64;
    double batch_times[kBatch];
    State batch_states[kBatch];
    for (std::size_t k = 0; k < n;) {
      bool moved = false;
      while (times[order[k]] >= phase.t_end && phase.t_end < last) {
        if (!engine.next(phase)) break;
        moved = true;
      }
      if (moved) law = law->for_phase(phase);
      std::size_t count = 0;
      do {
        batch_times[count] = std::min(times[order[k + count]], phase.t_end);
        ++count;
      } while (count < kBatch && k + count < n &&
               (times[order[k + count]] < phase.t_end || phase.t_end >= last));
      (*law)(batch_times, count, batch_states);
      for (std::size_t j = 0; j < count; ++j) rows[order[k + j]] = state_row(batch_states[j]);
      k += count;
      interrupt();
    }
  }
  require_no_failure(engine.summary());
  return records(std::move(rows), state_dtype());
}

py::array on_grid(const PyModel& model, py::handle t_end_object, py::handle dt_object,
                  bool include_events, bool force) {
  const Number t_end = number(t_end_object, "t_end");
  const Number dt = number(dt_object, "dt");
  TypedInputs inputs = model.input.typed_inputs();
  inputs["t_end"] = {"--t-end", t_end.text};
  inputs["dt"] = {"--dt", dt.text};
  GridOptions grid;
  grid.t_end = t_end.value;
  grid.dt = dt.value;
  grid.include_events = include_events;
  naming(inputs, [&] { grid.validate(model.model.t0); });
  const std::uint64_t grid_rows = grid.grid_rows(model.model.t0);
  if (!force && grid_rows > 1'000'000'000)
    value_error("--dt = " + dt.text + ": the grid up to --t-end = " + t_end.text + " has " +
                std::to_string(grid_rows) +
                " rows, more than 10^9; pass --force to write them anyway");
  require_memory(
      static_cast<double>(grid_rows), sizeof(StateRow), "--dt = " + dt.text,
      "pass a coarser dt or a shorter t_end, or sample chosen times with curve(model, t)");
  UniformSampler sampler = naming(inputs, [&] { return UniformSampler(model.model, grid); });
  std::vector<StateRow> rows;
  {
    py::gil_scoped_release release;
    rows.reserve(grid_rows);
    SignalCheck interrupt;
    StateRows block;
    while (sampler.next(block)) {
      for (std::size_t i = 0; i < block.size; ++i) rows.push_back(state_row(block[i]));
      interrupt();
    }
  }
  require_no_failure(sampler.engine_summary());
  return records(std::move(rows), state_dtype());
}

py::array curve(const PyModel& model, py::handle t, py::handle t_end, py::handle dt,
                py::handle include_events, py::handle force) {
  const bool events = flag(include_events, "include_events");
  const bool forced = flag(force, "force");
  const bool grid = !t_end.is_none() || !dt.is_none();
  if (!t.is_none() && grid) type_error("curve() takes either t, or t_end and dt, not both");
  if (!t.is_none()) {
    if (events) type_error("curve(): include_events goes with t_end and dt, not with t");
    return at_times(model, t);
  }
  if (t_end.is_none() || dt.is_none()) type_error("curve() needs t, or t_end and dt");
  return on_grid(model, t_end, dt, events, forced);
}

}  // namespace

void bind_curve(py::module_& m) {
  m.def("curve", &curve, py::arg("model"), py::arg("t") = py::none(), py::kw_only(),
        py::arg("t_end") = py::none(), py::arg("dt") = py::none(),
        py::arg("include_events") = false, py::arg("force") = false,
        R"doc(The exact state: curve(model, t) at the times t (an array, any order,
each >= model.t0), or curve(model, t_end=T, dt=H, include_events=False) on the
CLI's grid t0, t0 + H, ... (t0 + i H, never accumulated, below T - 1e-9 H)
and T itself, plus every phase boundary with include_events.

Returns a numpy structured array with the fields t, x, v, a, phase: at a
phase boundary the row carries the phase that starts there and its
acceleration (right limit), except at the last time, which carries the
phase that ends there (the horizon). Grids above 10^9 rows need force=True.

    >>> c = frictionref.curve(frictionref.Model(lambda_=0.7), t_end=30, dt=0.01)
    >>> len(c), c['t'][-1]
    (3001, 30.0)
)doc");
}

}  // namespace frictionref::python
