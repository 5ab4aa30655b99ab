// Bad input from Python: the library's InvalidInput becomes ValueError with
// the one-line message the command line prints (model_input.hpp), and the
// long loops stay interruptible with Ctrl-C.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <utility>

#include "frictionref/error.hpp"
#include "frictionref/model_input.hpp"

namespace frictionref::python {

namespace py = pybind11;

[[noreturn]] void value_error(const std::string& message);
[[noreturn]] void type_error(const std::string& message);

// Calls f(); an InvalidInput it throws becomes ValueError, named by `inputs`
// ("--t-end = 0: must be > t0 = 0").
template <class F>
decltype(auto) naming(const TypedInputs& inputs, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InvalidInput& error) {
    value_error(input_message(error, inputs));
  }
}

// For loops that run without the GIL: every `stride` calls, takes the GIL
// and raises KeyboardInterrupt (or whatever a signal handler raised) as
// py::error_already_set, so a long run can be stopped.
class SignalCheck {
 public:
  explicit SignalCheck(std::uint64_t stride = 1 << 10) : stride_(stride) {}
  void operator()() {
    if (++calls_ % stride_ == 0) check();
  }
  static void check();

 private:
  std::uint64_t stride_;
  std::uint64_t calls_ = 0;
};

// Refuses a result of `rows` rows of `row_bytes` bytes that would take more
// than an eighth of this machine's memory (the arrays are built in memory, unlike
// the CLI's streamed files): ValueError "<what>: <rows> rows of <bytes> bytes
// ... use <instead>".
void require_memory(double rows, std::size_t row_bytes, const std::string& what,
                    const std::string& instead);
// The largest row count require_memory accepts.
std::uint64_t memory_rows(std::size_t row_bytes);

}  // namespace frictionref::python
