// The parts of the extension module frictionref._frictionref, one concept
// per file; module.cpp calls each.
#pragma once

#include <pybind11/pybind11.h>

namespace frictionref::python {

namespace py = pybind11;

void bind_model(py::module_& m);     // model.cpp: Model
void bind_events(py::module_& m);    // events.cpp: events(), summary()
void bind_phases(py::module_& m);    // phases.cpp: phases(), Phase
void bind_curve(py::module_& m);     // curve.cpp: curve()
void bind_classify(py::module_& m);  // classify.cpp: classify(), regime_threshold()
void bind_stiff(py::module_& m);     // stiff.cpp: stiff()
void bind_compare(py::module_& m);   // compare.cpp: compare()
void bind_sweep(py::module_& m);     // sweep.cpp: sweep()
void bind_map(py::module_& m);       // map.cpp: map()
void bind_newmark(py::module_& m);   // newmark.cpp: newmark()

}  // namespace frictionref::python
