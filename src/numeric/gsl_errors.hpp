// GSL's default error handler aborts the process. We switch it off once and
// turn GSL status codes into our own results.
#pragma once

namespace frictionref::detail {

// Idempotent and thread-safe.
void disable_gsl_abort_handler();

}  // namespace frictionref::detail
