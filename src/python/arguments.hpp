// Python arguments to C++ values, with TypeError for a wrong type and the
// number kept as text for messages (the text the command line would show:
// an int as its decimal digits, a float as the shortest text that reads back
// to it, so "--mass = -1: must be > 0" is the same line either way).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <functional>
#include <string>

namespace frictionref::python {

namespace py = pybind11;

struct Number {
  double value = 0;
  std::string text;  // "-1", "0.7", "nan", "1e+300"
};

// A real number: int (not bool) or anything with __float__ (float, numpy
// floats and integers). TypeError naming `keyword` otherwise.
Number number(py::handle object, const std::string& keyword);
// The text of a number for messages and for the library's text rules.
std::string number_text(double value);

// A whole number >= 0 given as an int or a float with no fraction (1e5):
// TypeError for other types; the caller checks the range. Returns the value
// as a double (exact up to 2^53) with its text.
Number whole(py::handle object, const std::string& keyword);

// True or False (TypeError otherwise; numpy bools accepted).
bool flag(py::handle object, const std::string& keyword);

// A file's path: str, bytes or os.PathLike (TypeError otherwise), as the
// file system's bytes. "-", standard input for the command line, is refused
// (ValueError naming `option`): the module does not read the interpreter's
// standard input.
std::string path(py::handle object, const std::string& keyword, const std::string& option);

// A one-dimensional array of real numbers as contiguous float64 (copied only
// if it is not already): TypeError for other dtypes (strings, complex,
// objects, bools), ValueError for another number of dimensions.
py::array_t<double> float_array(py::handle object, const std::string& keyword);

// The progress callback of a study: called with the GIL as progress(done,
// total), after checking for signals (Ctrl-C stops the study). `callback`
// may be None; it must be callable otherwise (TypeError).
std::function<void(std::size_t, std::size_t)> progress(py::handle callback);

}  // namespace frictionref::python
