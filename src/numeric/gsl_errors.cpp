#include "gsl_errors.hpp"

#include <gsl/gsl_errno.h>

#include <mutex>

namespace frictionref::detail {

void disable_gsl_abort_handler() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

}  // namespace frictionref::detail
