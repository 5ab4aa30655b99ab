// frictionref._frictionref: the library for Python (docs/python.md). The
// package python/frictionref/ re-exports it with the pure-Python helpers.
#include "module.hpp"

#include "frictionref/version.hpp"

PYBIND11_MODULE(_frictionref, m) {
  namespace python = frictionref::python;
  m.doc() = "The exact motion of a mass with Coulomb friction (frictionref's C++ library).";
  m.attr("__version__") = frictionref::version;
  python::bind_model(m);
  python::bind_events(m);
  python::bind_phases(m);
  python::bind_curve(m);
  python::bind_classify(m);
  python::bind_stiff(m);
  python::bind_compare(m);
  python::bind_sweep(m);
  python::bind_map(m);
  python::bind_newmark(m);
}
