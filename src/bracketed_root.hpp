// The zero of a strictly decreasing function on a bracket [lo, hi] with
// f(lo) > 0 >= f(hi): the end of a slip inside one monotone piece.
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
#include <type_traits>

namespace frictionref::detail {

// GSL Brent on [lo, hi] to a relative width of 1e-9 (f(lo), f(hi) of opposite signs, checked by the
// caller). Returns false if GSL reports an error; `root` is then unchanged.
bool gsl_brent(double (*f)(double, void*), void* params, double lo, double hi, double& root,
               std::uint64_t& calls);

template <class Work>
struct RootBracket {
  Work root;  // the best estimate, inside [lo, hi]
  Work lo;    // f(lo) > 0
  Work hi;    // f(hi) <= 0
  bool ok = true;
};

// Boost.Math TOMS 748 (Alefeld, Potra, Shi 1995) to the type's precision.
template <class Work, class F>
RootBracket<Work> toms748_root(const F& f, const Work& lo, const Work& hi, std::uint64_t& calls) {
  RootBracket<Work> result{lo, lo, hi, true};
  constexpr std::uintmax_t kMaxIterations = 400;
  std::uintmax_t iterations = kMaxIterations;
  const auto counted = [&](const Work& x) {
    ++calls;
    return f(x);
  };
  try {
    boost::math::tools::eps_tolerance<Work> tolerance(std::numeric_limits<Work>::digits - 2);
    const auto bracket = boost::math::tools::toms748_solve(counted, lo, hi, tolerance, iterations);
    result.lo = bracket.first;
    result.hi = bracket.second;
    result.root = counted(bracket.second) <= 0 ? bracket.second : bracket.first;
    result.ok = iterations < kMaxIterations;
  } catch (const std::exception&) {  // Boost reports a lost bracket as domain_error
    result.ok = false;
  }
  return result;
}

template <class F, class DF>
RootBracket<long double> brent_then_newton(const F& f, const DF& slope, long double lo,
                                           long double hi, std::uint64_t& calls) {
  RootBracket<long double> result{lo, lo, hi, true};

  // Stage 1: GSL Brent in double. The bracket ends are rounded to double;
  // if rounding loses the sign change (a root within a double ulp of an end),
  // stage 2 starts from the long double bracket directly.
  struct Params {
    const F* f;
    std::uint64_t* calls;
  } params{&f, &calls};
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
    if (gsl_brent(+f_double, &params, lo_d, hi_d, root_d, calls)) x = root_d;
  }

  // Stage 2: safeguarded Newton in long double.
  const long double eps = std::numeric_limits<long double>::epsilon();
  // Where f is flat at long double resolution (a near-grazing stop), Newton
  // creeps an ulp per step without crossing the root: after two steps that
  // did not halve |f| (or two sub-resolution probes), bisect to the end (64
  // steps at most). Converging Newton steps shrink |f| far faster than that.
  int sub_resolution_steps = 0;
  int stalled_steps = 0;
  long double previous_fx = HUGE_VALL;
  for (int iteration = 0; iteration < 200; ++iteration) {
    ++calls;
    const long double fx = f(x);
    stalled_steps = std::fabs(fx) > std::fabs(previous_fx) / 2 ? stalled_steps + 1 : 0;
    previous_fx = fx;
    if (fx > 0) {
      result.lo = x;
    } else {
      result.hi = x;
      if (fx == 0) break;
    }
    const long double width = result.hi - result.lo;
    if (width <= 2 * eps * std::fmax(1.0L, std::fabs(x))) break;
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
  return result;
}

// The zero of f on [lo, hi]: GSL + long double polish for long double, TOMS
// 748 for every other type.
template <class Work, class F, class DF>
RootBracket<Work> decreasing_root(const F& f, const DF& slope, const Work& lo, const Work& hi,
                                  std::uint64_t& calls) {
  // The caller has seen f(hi) <= 0. If f(lo) is not > 0 either, the zero is
  // at lo to within the evaluation noise (a slip shorter than rounding, e.g.
  // one that starts a hair before the force falls back to R): say so rather
  // than hand a non-bracket to the solvers.
  ++calls;
  if (!(f(lo) > 0)) return RootBracket<Work>{lo, lo, lo, true};
  if constexpr (std::is_same_v<Work, long double>) {
    return brent_then_newton(f, slope, lo, hi, calls);
  } else {
    (void)slope;
    return toms748_root(f, lo, hi, calls);
  }
}

}  // namespace frictionref::detail
