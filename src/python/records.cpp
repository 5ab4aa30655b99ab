#include "records.hpp"

namespace frictionref::python {

py::dtype record_dtype(const std::vector<Field>& fields, std::size_t itemsize) {
  py::list names, formats, offsets;
  for (const Field& field : fields) {
    names.append(field.name);
    formats.append(field.format);
    offsets.append(field.offset);
  }
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = itemsize;
  return py::dtype::from_args(spec);
}

}  // namespace frictionref::python
