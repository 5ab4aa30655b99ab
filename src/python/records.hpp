// Tables as numpy structured arrays, handed over without a copy: the rows are
// filled in a std::vector of a plain struct (without the GIL), and the array
// then owns that vector's buffer.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frictionref/types.hpp"

namespace frictionref::python {

namespace py = pybind11;

struct Field {
  std::string name;
  const char* format;  // numpy: "<f8", "<u4", "<U10", ...
  std::size_t offset;
};

// A structured dtype with these fields, in this order, at these offsets.
py::dtype record_dtype(const std::vector<Field>& fields, std::size_t itemsize);

// Text in a numpy unicode field: UCS4, zero-padded (numpy's "<U" layout).
template <std::size_t N>
void put_text(char32_t (&field)[N], std::string_view text) {
  for (std::size_t i = 0; i < N; ++i) field[i] = i < text.size() ? static_cast<char32_t>(text[i]) : 0;
}

// "stick", "slip+", "slip-" (the CLI's spelling) in a U5 field.
inline void put_phase(char32_t (&field)[5], PhaseKind kind) { put_text(field, to_string(kind)); }

// A 1-D structured array that owns `rows` (moved, not copied).
template <class Row>
py::array records(std::vector<Row>&& rows, const py::dtype& dtype) {
  auto* owned = new std::vector<Row>(std::move(rows));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<Row>*>(p); });
  const auto size = static_cast<py::ssize_t>(owned->size());
  return py::array(dtype, {size}, {static_cast<py::ssize_t>(sizeof(Row))}, owned->data(), owner);
}

}  // namespace frictionref::python
