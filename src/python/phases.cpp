// frictionref.phases(): the engine as a Python iterator, for runs too long to
// keep (memory stays flat; the engine is itself a stream).
#include <pybind11/numpy.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "events.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"

namespace frictionref::python {
namespace {

// The namedtuple type frictionref.Phase, alive for the whole process.
PyObject* phase_type = nullptr;

class PhaseStream {
 public:
  PhaseStream(ExactEngine engine, std::size_t chunk) : engine_(std::move(engine)), chunk_(chunk) {}

  py::object next() {
    if (chunk_ == 0) {
      // One phase: too little work to be worth releasing the GIL, which also
      // keeps two Python threads from stepping the engine at once.
      Phase phase;
      if (!engine_.next(phase)) finish();
      return py::reinterpret_borrow<py::object>(phase_type)(
          std::string(to_string(phase.kind)), phase.t_begin, phase.t_end, phase.x_begin,
          phase.x_end, phase.v_begin, phase.v_end);
    }
    std::vector<PhaseRow> rows;
    rows.reserve(chunk_);
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      SignalCheck interrupt;
      Phase phase;
      while (rows.size() < chunk_ && engine_.next(phase)) {
        rows.push_back(phase_row(phase));
        interrupt();
      }
    }
    if (rows.empty()) finish();
    return records(std::move(rows), phase_dtype());
  }

  py::dict summary() {
    std::lock_guard<std::mutex> lock(mutex_);
    return summary_dict(engine_.summary());
  }

 private:
  void finish() {
    require_no_failure(engine_.summary());
    throw py::stop_iteration();
  }

  ExactEngine engine_;
  std::size_t chunk_;
  std::mutex mutex_;
};

std::unique_ptr<PhaseStream> phases(const PyModel& model, py::handle t_end_object,
                                    py::handle chunk_object, py::handle max_phases_object) {
  const Number t_end = number(t_end_object, "t_end");
  TypedInputs inputs = model.input.typed_inputs();
  inputs["t_end"] = {"--t-end", t_end.text};
  std::size_t chunk = 0;
  if (!chunk_object.is_none()) {
    const Number n = whole(chunk_object, "chunk");
    if (!(n.value >= 1) || n.value != std::floor(n.value) ||
        !(n.value <= static_cast<double>(memory_rows(sizeof(PhaseRow)))))
      value_error("chunk = " + n.text +
                  ": must be a whole number >= 1 (phases per array) that fits in memory");
    chunk = static_cast<std::size_t>(n.value);
  }
  SolveOptions options;
  if (!max_phases_object.is_none()) {
    const Number n = whole(max_phases_object, "max_phases");
    if (!(n.value >= 1) || n.value != std::floor(n.value) || !(n.value <= 1.8e19))
      value_error("max_phases = " + n.text + ": must be a whole number >= 1");
    options.max_phases = static_cast<std::uint64_t>(n.value);
  }
  return naming(inputs, [&] {
    return std::make_unique<PhaseStream>(ExactEngine(model.model, t_end.value, options), chunk);
  });
}

}  // namespace

void bind_phases(py::module_& m) {
  py::object phase = py::module_::import("collections")
                         .attr("namedtuple")("Phase", "phase t_begin t_end x_begin x_end v_begin v_end");
  phase.attr("__module__") = "frictionref";
  phase.attr("__doc__") =
      "One phase of the exact motion: phase ('stick', 'slip+', 'slip-'), t_begin, t_end, "
      "x_begin, x_end, v_begin, v_end.";
  m.attr("Phase") = phase;
  phase_type = phase.release().ptr();  // kept for the life of the process

  py::class_<PhaseStream>(m, "PhaseStream",
                          "An iterator over the phases of one run; see phases().")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", &PhaseStream::next)
      .def_property_readonly("summary", &PhaseStream::summary,
                             "The run so far, as summary() gives it at the end.");
  m.def("phases", &phases, py::arg("model"), py::arg("t_end"), py::kw_only(),
        py::arg("chunk") = py::none(), py::arg("max_phases") = py::none(),
        R"doc(Iterates over the exact phases from model.t0 to t_end, computing each when
asked: memory stays flat for any horizon.

Yields Phase namedtuples (phase, t_begin, t_end, x_begin, x_end, v_begin,
v_end), or with chunk=N structured arrays of up to N phases (the dtype of
events(); faster for long runs, computed without the GIL). After the loop,
.summary holds the counts and the final state.

    >>> stream = frictionref.phases(frictionref.Model(lambda_=0.3), 1e6, chunk=100000)
    >>> slid = sum(abs(c['x_end'] - c['x_begin']).sum() for c in stream)
)doc");
}

}  // namespace frictionref::python
