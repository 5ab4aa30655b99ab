// The zero of a strictly monotone function on a bracket: the end of a slip or
// of a stick once the event search (docs/theory.md 3.4, 7.4) has isolated it.
//
// Every solver returns the bracket it closed, the iterations it used and a
// status that says whether it converged, hit its iteration cap or lost the
// bracket (Boost.Math's max_iter comes back as the count used; "converged"
// after hitting the cap would hide a failure).
//
// long double (the work type of the double engine): GSL's Brent solver
// brings the bracket to double resolution, then a safeguarded Newton polish
// in long double (it keeps a sign bracket and bisects whenever a Newton step
// would leave it) reaches long double resolution, so event times chained over
// long horizons stay accurate to the rounding of t.
// Other types (Boost.Multiprecision): Boost.Math TOMS 748 to full precision.
//
// Tolerances are relative to the time scale, as in SUNDIALS cvRootfind:
// the bracket is closed to a few ulps of max(1, |tau|) of the work type.
#pragma once

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace frictionref::detail {

enum class RootStatus {
  converged,      // the bracket is closed to the solver's tolerance
  iteration_cap,  // the solver ran out of iterations; root is the best bracket end
  lost_bracket,   // the function values did not keep a sign change (an invariant broken)
};

std::string_view to_string(RootStatus status);

template <class Work>
struct RootResult {
  Work root;  // the best estimate, inside [lo, hi]; f(root) <= 0 for a decreasing f
  Work lo;    // f(lo) > 0
  Work hi;    // f(hi) <= 0
  std::uint64_t iterations = 0;  // function evaluations made by the solver
  RootStatus status = RootStatus::converged;

  bool ok() const { return status == RootStatus::converged; }
};

// GSL Brent on [lo, hi] to a relative width of 1e-9 (f(lo), f(hi) of
// opposite signs, checked by the caller). `iterations` counts Brent steps.
// Returns lost_bracket if GSL reports an error (`root` is then unchanged) and
// iteration_cap after 100 steps.
RootStatus gsl_brent(double (*f)(double, void*), void* params, double lo, double hi,
                     double& root, std::uint64_t& iterations);

// Boost.Math TOMS 748 (Alefeld, Potra, Shi 1995) to the type's precision.
template <class Work, class F>
RootResult<Work> toms748_root(const F& f, const Work& lo, const Work& hi) {
  RootResult<Work> result{lo, lo, hi};
  constexpr std::uintmax_t kMaxIterations = 400;
  std::uintmax_t iterations = kMaxIterations;
  const auto counted = [&](const Work& x) {
    ++result.iterations;
    return f(x);
  };
  try {
    boost::math::tools::eps_tolerance<Work> tolerance(std::numeric_limits<Work>::digits - 2);
    const auto bracket = boost::math::tools::toms748_solve(counted, lo, hi, tolerance, iterations);
    result.lo = bracket.first;
    result.hi = bracket.second;
    result.root = counted(bracket.second) <= 0 ? bracket.second : bracket.first;
    if (iterations >= kMaxIterations) result.status = RootStatus::iteration_cap;
  } catch (const std::exception&) {  // Boost reports a lost bracket as domain_error
    result.status = RootStatus::lost_bracket;
  }
  return result;
}

// GSL Brent in double, then a safeguarded Newton polish in long double.
// slope(x) is f'(x); it may be inaccurate (it only steers Newton).
template <class F, class DF>
RootResult<long double> brent_then_newton(const F& f, const DF& slope, long double lo,
                                          long double hi) {
  RootResult<long double> result{lo, lo, hi};

  // Stage 1: GSL Brent in double. The bracket ends are rounded to double;
  // if rounding loses the sign change (a root within a double ulp of an end),
  // stage 2 starts from the long double bracket directly.
  struct Params {
    const F* f;
    std::uint64_t* calls;
  } params{&f, &result.iterations};
  const auto f_double = [](double x, void* p) -> double {
    auto* q = static_cast<Params*>(p);
    ++*q->calls;
    return static_cast<double>((*q->f)(static_cast<long double>(x)));
  };
  // Round the bracket ends inward, so the double bracket lies inside [lo, hi].
  double lo_d = static_cast<double>(lo);
  double hi_d = static_cast<double>(hi);
  if (lo_d < lo) lo_d = std::nextafter(lo_d, HUGE_VAL);
  if (hi_d > hi) hi_d = std::nextafter(hi_d, -HUGE_VAL);
  long double x = lo + (hi - lo) / 2;
  if (lo_d < hi_d) {
    double root_d = 0;
    std::uint64_t brent_steps = 0;
    // A lost or capped Brent stage only costs a worse start for the polish,
    // which keeps its own bracket.
    if (gsl_brent(+f_double, &params, lo_d, hi_d, root_d, brent_steps) == RootStatus::converged)
      x = root_d;
  }

  // Stage 2: safeguarded Newton in long double.
  const long double eps = std::numeric_limits<long double>::epsilon();
  // Where f is flat at long double resolution (a near-grazing stop), Newton
  // creeps an ulp per step without crossing the root: after two steps that
  // did not halve |f| (or two sub-resolution probes), bisect to the end (64
  // steps at most). Converging Newton steps shrink |f| far faster than that.
  constexpr int kMaxPolishSteps = 200;
  int sub_resolution_steps = 0;
  int stalled_steps = 0;
  long double previous_fx = HUGE_VALL;
  bool closed = false;
  for (int iteration = 0; iteration < kMaxPolishSteps; ++iteration) {
    ++result.iterations;
    const long double fx = f(x);
    stalled_steps = std::fabs(fx) > std::fabs(previous_fx) / 2 ? stalled_steps + 1 : 0;
    previous_fx = fx;
    if (fx > 0) {
      result.lo = x;
    } else {
      result.hi = x;
      if (fx == 0) {
        closed = true;
        break;
      }
    }
    const long double width = result.hi - result.lo;
    if (width <= 2 * eps * std::fmax(1.0L, std::fabs(x))) {
      closed = true;
      break;
    }
    const long double d = slope(x);
    const bool newton = d < 0 && sub_resolution_steps < 2 && stalled_steps < 2;
    long double next = newton ? x - fx / d : result.lo + width / 2;
    // A Newton step below the resolution: test the neighbour across the root
    // instead, which closes the bracket next iteration if f is not flat.
    if (next == x) {
      ++sub_resolution_steps;
      next = fx > 0 ? std::nextafter(x, result.hi) : std::nextafter(x, result.lo);
    }
    if (!(next > result.lo && next < result.hi)) next = result.lo + width / 2;
    x = next;
  }
  result.root = result.hi;
  if (!closed) result.status = RootStatus::iteration_cap;
  return result;
}

// The zero of a strictly decreasing f on [lo, hi] with f(hi) <= 0 (seen by
// the caller), by `solve(f, slope, lo, hi)` (one of the solvers above, chosen
// by ScalarTraits). Counts every evaluation of f in `calls`.
template <class Work, class Solver, class F, class DF>
RootResult<Work> decreasing_root(const Solver& solve, const F& f, const DF& slope, const Work& lo,
                                 const Work& hi, std::uint64_t& calls) {
  // If f(lo) is not > 0 either, the zero is at lo to within the evaluation
  // noise (a slip shorter than rounding, e.g. one that starts a hair before
  // the force falls back to R): say so rather than hand a non-bracket to the
  // solvers.
  ++calls;
  if (!(f(lo) > 0)) return RootResult<Work>{lo, lo, lo, 1};
  RootResult<Work> result = solve(f, slope, lo, hi);
  calls += result.iterations;
  ++result.iterations;  // the test at lo
  return result;
}

}  // namespace frictionref::detail
