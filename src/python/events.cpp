// frictionref.events() and frictionref.summary(): the CLI's `events`.
#include "events.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/phase_estimate.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"

namespace frictionref::python {
namespace {

// The CLI's guard (phase_estimate.hpp): at most 10^9 estimated phases
// without force.
void require_phase_estimate(const Model& model, const Number& t_end, bool force) {
  const PhaseEstimate estimate = estimate_phases(model, t_end.value);
  if (!force && !(estimate.phases <= 1e9)) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", estimate.phases);
    value_error("--t-end = " + t_end.text + ": about " + text + " phases (" + estimate.basis +
                "), more than 10^9; pass --force to run anyway");
  }
}

struct EngineRequest {
  TypedInputs inputs;
  Number t_end;
  SolveOptions options;
};

EngineRequest engine_request(const PyModel& model, py::handle t_end, py::handle max_phases) {
  EngineRequest request;
  request.t_end = number(t_end, "t_end");
  request.inputs = model.input.typed_inputs();
  request.inputs["t_end"] = {"--t-end", request.t_end.text};
  if (!max_phases.is_none()) {
    const Number n = whole(max_phases, "max_phases");
    if (!(n.value >= 1) || n.value != std::floor(n.value) || !(n.value <= 1.8e19))
      value_error("max_phases = " + n.text + ": must be a whole number >= 1");
    request.options.max_phases = static_cast<std::uint64_t>(n.value);
  }
  return request;
}

py::array events(const PyModel& model, py::handle t_end, py::handle max_phases, py::handle force) {
  const EngineRequest request = engine_request(model, t_end, max_phases);
  const bool forced = flag(force, "force");
  ExactEngine engine = naming(request.inputs, [&] {
    return ExactEngine(model.model, request.t_end.value, request.options);
  });
  require_phase_estimate(model.model, request.t_end, forced);
  if (request.options.max_phases == SolveOptions{}.max_phases)
    require_memory(estimate_phases(model.model, request.t_end.value).phases, sizeof(PhaseRow),
                   "--t-end = " + request.t_end.text,
                   "stream them with frictionref.phases(), or pass max_phases");
  const std::uint64_t memory_cap = memory_rows(sizeof(PhaseRow));
  const std::uint64_t cap = std::min(request.options.max_phases, memory_cap);
  std::vector<PhaseRow> rows;
  bool more = false;
  {
    py::gil_scoped_release release;
    SignalCheck interrupt;
    Phase phase;
    while (rows.size() < cap && engine.next(phase)) {
      rows.push_back(phase_row(phase));
      interrupt();
    }
    more =
        rows.size() == memory_cap && memory_cap < request.options.max_phases && engine.next(phase);
  }
  if (more)
    value_error("--t-end = " + request.t_end.text + ": more than " + std::to_string(memory_cap) +
                " phases, more than an eighth of this machine's memory; stream them with "
                "frictionref.phases(), or pass max_phases");
  require_no_failure(engine.summary());
  return records(std::move(rows), phase_dtype());
}

py::dict summary(const PyModel& model, py::handle t_end, py::handle force) {
  const EngineRequest request = engine_request(model, t_end, py::none());
  const bool forced = flag(force, "force");
  ExactEngine engine =
      naming(request.inputs, [&] { return ExactEngine(model.model, request.t_end.value); });
  require_phase_estimate(model.model, request.t_end, forced);
  {
    py::gil_scoped_release release;
    SignalCheck interrupt;
    Phase phase;
    while (engine.next(phase)) interrupt();
  }
  require_no_failure(engine.summary());
  return summary_dict(engine.summary());
}

}  // namespace

PhaseRow phase_row(const Phase& phase) {
  PhaseRow row{
      phase.t_begin, phase.t_end, phase.x_begin, phase.x_end, phase.v_begin, phase.v_end, {}, 0};
  put_phase(row.phase, phase.kind);
  return row;
}

py::dtype phase_dtype() {
  return record_dtype({{"phase", "<U5", offsetof(PhaseRow, phase)},
                       {"t_begin", "<f8", offsetof(PhaseRow, t_begin)},
                       {"t_end", "<f8", offsetof(PhaseRow, t_end)},
                       {"x_begin", "<f8", offsetof(PhaseRow, x_begin)},
                       {"x_end", "<f8", offsetof(PhaseRow, x_end)},
                       {"v_begin", "<f8", offsetof(PhaseRow, v_begin)},
                       {"v_end", "<f8", offsetof(PhaseRow, v_end)}},
                      sizeof(PhaseRow));
}

py::dict summary_dict(const Summary& summary) {
  py::dict d;
  d["termination"] = std::string(to_string(summary.termination));
  d["phases"] = summary.phases;
  d["stick"] = summary.count(PhaseKind::stick);
  d["slip+"] = summary.count(PhaseKind::slip_forward);
  d["slip-"] = summary.count(PhaseKind::slip_backward);
  d["stops"] = summary.stops;
  d["reversals"] = summary.reversals;
  d["breakaways"] = summary.breakaways;
  const State& end = summary.final_state;
  d["t"] = end.t;
  d["x"] = end.x;
  d["v"] = end.v;
  d["a"] = end.a;
  d["phase"] = std::string(to_string(end.phase));
  return d;
}

void require_no_failure(const Summary& summary) {
  if (summary.termination == Termination::numerical_failure)
    throw std::runtime_error("internal error: " + std::string(to_string(summary.termination)) +
                             ": " + summary.message);
}

void bind_events(py::module_& m) {
  m.def("events", &events, py::arg("model"), py::arg("t_end"), py::kw_only(),
        py::arg("max_phases") = py::none(), py::arg("force") = false,
        R"doc(The exact stick/slip phases from model.t0 to t_end (the CLI's `events`).

Returns a numpy structured array, one row per phase, with the fields
phase ('stick', 'slip+', 'slip-'), t_begin, t_end, x_begin, x_end, v_begin,
v_end. The last phase is cut at t_end. max_phases stops after that many
phases. The run is refused with ValueError above an estimated 10^9 phases
(4 per forcing period) unless force=True, and when the table would not fit
in half of this machine's memory: stream long runs with phases().

    >>> table = frictionref.events(frictionref.Model(lambda_=0.7), 30)
    >>> table[1]['phase'], table[1]['t_begin']        # asin(0.7)
    ('slip+', 0.775397496610753)
)doc");
  m.def("summary", &summary, py::arg("model"), py::arg("t_end"), py::kw_only(),
        py::arg("force") = false,
        R"doc(The CLI's `events --summary` as a dict, in constant memory: termination,
phases, stick, slip+, slip-, stops (every v = 0 before t_end, reversals
included), reversals, breakaways, and the state at t_end: t, x, v, a, phase.
Same checks as events().

    >>> frictionref.summary(frictionref.Model(lambda_=0.7), 30)['stops']
    9
)doc");
}

}  // namespace frictionref::python
