#include "errors.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frictionref::python {

void value_error(const std::string& message) { throw py::value_error(message); }

void type_error(const std::string& message) { throw py::type_error(message); }

void SignalCheck::check() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

std::uint64_t memory_rows(std::size_t row_bytes) {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  // Unknown memory: assume 4 GB.
  double memory = pages > 0 && page_size > 0
                     ? static_cast<double>(pages) * static_cast<double>(page_size)
                     : 4e9;
  // A process limited to less address space (ulimit -v) has less.
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    memory = std::min(memory, static_cast<double>(limit.rlim_cur));
  // An eighth: a table that grows (std::vector doubling) may briefly hold
  // twice its size, and this machine runs other work too.
  return static_cast<std::uint64_t>(memory / 8 / static_cast<double>(row_bytes));
}

void require_memory(double rows, std::size_t row_bytes, const std::string& what,
                    const std::string& instead) {
  const auto limit = static_cast<double>(memory_rows(row_bytes));
  if (!(rows <= limit)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  ": about %.3g rows of %zu bytes, more than an eighth of this machine's memory "
                  "(%.3g rows); ",
                  rows, row_bytes, limit);
    value_error(what + text + instead);
  }
}

}  // namespace frictionref::python
