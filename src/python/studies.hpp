// Options the parameter studies (sweep, map) share, checked as the CLI's
// sweep and map commands check them (src/cli/sweep.cpp, map.cpp), with their
// messages: counts, threads and the shard.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "arguments.hpp"
#include "frictionref/shard.hpp"

namespace frictionref::python {

namespace py = pybind11;

// A whole number in [1, max] ("--points = 0.5: must be a whole number >= 1",
// "--points = 1e8: must be <= 10^7").
std::uint64_t whole_number(const Number& number, const std::string& option, double max,
                           const char* max_text);

// threads=None: all cores (0); else 1 to 256 (--threads).
unsigned threads(py::handle object);

// shard=None: the whole study; (I, N) or "I/N": shard I of N (--shard).
Shard shard(py::handle object);

}  // namespace frictionref::python
