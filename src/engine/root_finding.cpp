#include "root_finding.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cfloat>
#include <memory>

#include "numeric/gsl_errors.hpp"

namespace frictionref::detail {
namespace {

// Brent only has to land where Newton converges at once: from a relative
// error of 1e-9, one Newton step reaches long double resolution (quadratic
// convergence), which is cheaper than Brent's last superlinear steps.
constexpr double kBrentTolerance = 1e-9;
constexpr int kMaxBrentSteps = 100;

}  // namespace

std::string_view to_string(RootStatus status) {
  switch (status) {
    case RootStatus::converged:
      return "converged";
    case RootStatus::iteration_cap:
      return "iteration_cap";
    case RootStatus::lost_bracket:
      return "lost_bracket";
  }
  return "?";
}

RootStatus gsl_brent(double (*f)(double, void*), void* params, double lo, double hi,
                     double& root, std::uint64_t& iterations) {
  disable_gsl_abort_handler();
  // Allocated per call: the solver state is a few words and this keeps the
  // engine free of shared mutable state (engines may run in parallel).
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) return RootStatus::lost_bracket;
  gsl_function function{f, params};
  if (gsl_root_fsolver_set(solver.get(), &function, lo, hi) != GSL_SUCCESS)
    return RootStatus::lost_bracket;
  for (iterations = 0; iterations < kMaxBrentSteps;) {
    ++iterations;
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) return RootStatus::lost_bracket;
    const double x_lo = gsl_root_fsolver_x_lower(solver.get());
    const double x_hi = gsl_root_fsolver_x_upper(solver.get());
    root = gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(x_lo, x_hi, kBrentTolerance, kBrentTolerance) != GSL_CONTINUE)
      return RootStatus::converged;
  }
  return RootStatus::iteration_cap;
}

}  // namespace frictionref::detail
