// The phase table: one row per stick or slip phase, as the CLI's `events`
// CSV (phase, t_begin, t_end, x_begin, x_end, v_begin, v_end).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>

#include "frictionref/exact_engine.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::python {

namespace py = pybind11;

struct PhaseRow {
  double t_begin, t_end, x_begin, x_end, v_begin, v_end;
  char32_t phase[5];  // "stick", "slip+", "slip-"
  std::uint32_t padding;
};

PhaseRow phase_row(const Phase& phase);
py::dtype phase_dtype();

// The engine's summary as the CLI's `events --summary` keys: termination,
// phases, stick, slip+, slip-, stops, reversals, breakaways, t, x, v, a, phase.
py::dict summary_dict(const Summary& summary);

// An engine that stopped on a broken invariant: RuntimeError, as the CLI's
// exit code 4 ("internal error: ...").
void require_no_failure(const Summary& summary);

}  // namespace frictionref::python
