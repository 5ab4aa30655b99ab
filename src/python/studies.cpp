#include "studies.hpp"

#include <pybind11/stl.h>

#include <cmath>

#include "errors.hpp"
#include "frictionref/model_input.hpp"

namespace frictionref::python {

std::uint64_t whole_number(const Number& number, const std::string& option, double max,
                           const char* max_text) {
  if (!(number.value >= 1) || number.value != std::floor(number.value))
    value_error(option + " = " + number.text + ": must be a whole number >= 1");
  if (!(number.value <= max))
    value_error(option + " = " + number.text + ": must be <= " + max_text);
  return static_cast<std::uint64_t>(number.value);
}

unsigned threads(py::handle object) {
  if (object.is_none()) return 0;
  return static_cast<unsigned>(whole_number(whole(object, "threads"), "--threads", 256, "256"));
}

Shard shard(py::handle object) {
  if (object.is_none()) return Shard{};
  std::string text;
  if (PyUnicode_Check(object.ptr())) {
    text = object.cast<std::string>();
  } else if (py::isinstance<py::tuple>(object) || py::isinstance<py::list>(object)) {
    const py::sequence parts = py::reinterpret_borrow<py::sequence>(object);
    if (parts.size() != 2) type_error("shard must be (I, N) or \"I/N\"");
    text = whole(parts[0], "shard[0]").text + "/" + whole(parts[1], "shard[1]").text;
  } else {
    type_error("shard must be (I, N) or \"I/N\", not " +
               py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>());
  }
  try {
    return Shard::parse(text, "--shard");
  } catch (const InvalidInput& error) {
    value_error(input_message(error));
  }
}

}  // namespace frictionref::python
