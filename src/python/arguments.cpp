#include "arguments.hpp"

#include <cmath>
#include <cstdlib>

#include "errors.hpp"
#include "frictionref/detail/number_text.hpp"

namespace frictionref::python {
namespace {

std::string type_name(py::handle object) {
  return py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
}

bool is_bool(py::handle object) {
  if (PyBool_Check(object.ptr())) return true;
  const py::module_ numpy = py::module_::import("numpy");
  return py::isinstance(object, numpy.attr("bool_"));
}

bool is_complex(py::handle object) {
  if (PyComplex_Check(object.ptr())) return true;
  const py::module_ numpy = py::module_::import("numpy");
  return py::isinstance(object, numpy.attr("complexfloating"));
}

[[noreturn]] void not_a_number(py::handle object, const std::string& keyword) {
  type_error(keyword + " must be a real number (int or float), not " + type_name(object));
}

}  // namespace

std::string number_text(double value) { return detail::shortest_text(value); }

Number number(py::handle object, const std::string& keyword) {
  if (object.is_none() || is_bool(object) || is_complex(object) || PyUnicode_Check(object.ptr()) ||
      PyBytes_Check(object.ptr()))
    not_a_number(object, keyword);
  if (PyLong_Check(object.ptr())) {
    // Its decimal digits, read as the command line reads them (strtod
    // rounds correctly; beyond the range of double it gives +-inf, refused
    // by the finite rules with the number as given).
    std::string text;
    try {
      // int() first: an int subclass (an IntEnum) may print otherwise.
      text = py::str(py::int_(py::reinterpret_borrow<py::object>(object))).cast<std::string>();
    } catch (const py::error_already_set&) {
      // Python refuses to print integers of more than 4300 digits.
      text = PyObject_RichCompareBool(object.ptr(), py::int_(0).ptr(), Py_LT) == 1 ? "-1e4300"
                                                                                   : "1e4300";
    }
    return {std::strtod(text.c_str(), nullptr), text};
  }
  double value = 0;
  try {
    value = py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
  } catch (const py::error_already_set&) {
    not_a_number(object, keyword);
  }
  return {value, number_text(value)};
}

Number whole(py::handle object, const std::string& keyword) {
  if (object.is_none() || is_bool(object) || is_complex(object) || PyUnicode_Check(object.ptr()) ||
      PyBytes_Check(object.ptr()))
    type_error(keyword + " must be a whole number (int), not " + type_name(object));
  return number(object, keyword);
}

bool flag(py::handle object, const std::string& keyword) {
  if (!is_bool(object))
    type_error(keyword + " must be True or False, not " + type_name(object));
  return py::cast<bool>(py::bool_(py::reinterpret_borrow<py::object>(object)));
}

std::string path(py::handle object, const std::string& keyword, const std::string& option) {
  const py::module_ os = py::module_::import("os");
  if (!PyUnicode_Check(object.ptr()) && !PyBytes_Check(object.ptr()) &&
      !py::isinstance(object, os.attr("PathLike")))
    type_error(keyword + " must be a path (str, bytes or os.PathLike), not " + type_name(object));
  // The file system's bytes (os.fsencode), which a name that is not UTF-8 keeps.
  const std::string text = os.attr("fsencode")(object).cast<py::bytes>();
  if (text == "-")
    value_error(option + " = -: standard input is read by the command line only; give a file");
  // The file system would stop at it and open another file.
  if (text.find('\0') != std::string::npos)
    value_error(option + ": a path cannot hold a NUL character");
  return text;
}

py::array_t<double> float_array(py::handle object, const std::string& keyword) {
  const py::module_ numpy = py::module_::import("numpy");
  py::array array;
  try {
    array = numpy.attr("asarray")(object);
  } catch (const py::error_already_set&) {
    type_error(keyword + " must be an array of real numbers, not " + type_name(object));
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    type_error(keyword + " must be an array of real numbers, not an array of dtype " +
               py::str(array.dtype()).cast<std::string>());
  if (array.ndim() != 1)
    value_error(keyword + " must be a one-dimensional array, not one with " +
                std::to_string(array.ndim()) + " dimensions");
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

std::function<void(std::size_t, std::size_t)> progress(py::handle callback) {
  py::object function;
  if (!callback.is_none()) {
    if (!PyCallable_Check(callback.ptr()))
      type_error("progress must be callable as progress(done, total), not " + type_name(callback));
    function = py::reinterpret_borrow<py::object>(callback);
  }
  // The study's threads run without the GIL; the callback runs on the
  // calling thread, which takes it here. The copy of `function` lives in the
  // std::function: its reference is released under the GIL by the caller.
  return [function](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (function) function(done, total);
  };
}

}  // namespace frictionref::python
