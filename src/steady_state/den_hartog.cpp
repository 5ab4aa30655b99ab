// Den Hartog's non-stop solution (docs/theory.md 8.2). In units of the static
// deflection B / k and the forcing phase tau, with beta = w / w_n, nu = 1/beta,
// r = R / B and the half cycle starting at the forward reversal (x = -X, v = 0):
//
//   x(tau) = V sin(tau + phi) - r + r cos(nu tau) + r T sin(nu tau),
//   T = tan(nu pi / 2),  V = 1 / (1 - beta^2),
//   V cos(phi) = -r U,  U = nu T,  X = -V sin(phi) = sqrt(V^2 - r^2 U^2),
//
// which meets x(0) = -X, x(pi) = X and v = 0 at both ends (the four
// conditions fix X, phi and the two homogeneous constants). The net force at
// the reversal is N = B beta^2 X (in these units), so the mass leaves at once
// iff beta^2 X > Rs / B.
#include "frictionref/den_hartog.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>

#include "engine/scalar_traits.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "numeric/first_zero.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref {
namespace {

using Long = long double;

constexpr double kStableRadius = 1 - 1e-6;

struct HalfCycle {
  Long beta, nu, r, v, tan_half, phi, amplitude;
  bool exists = false;
};

HalfCycle half_cycle(Long beta, Long r) {
  const Long pi = boost::math::constants::pi<Long>();
  HalfCycle h;
  h.beta = beta;
  h.nu = 1 / beta;
  h.r = r;
  h.v = 1 / ((1 - beta) * (1 + beta));
  h.tan_half = std::tan(h.nu * pi / 2);
  const Long u = h.nu * h.tan_half;
  const Long square = (h.v - r * u) * (h.v + r * u);
  if (!(square > 0) || !std::isfinite(square)) return h;
  h.exists = true;
  h.amplitude = std::sqrt(square);
  // sin(phi) = -X / V, cos(phi) = -r U / V.
  h.phi = std::atan2(-h.amplitude / h.v, -r * u / h.v);
  return h;
}

// The velocity dx/dtau of the half cycle (in B/k per radian), as a function
// for the certified zero search: is it positive on (0, pi)?
struct VelocityProbe {
  const HalfCycle& h;
  std::uint64_t evaluations = 0;

  detail::Jet<Long> jet(const Long& tau) {
    ++evaluations;
    const Long eps = std::numeric_limits<Long>::epsilon();
    const SinCos<Long> forced = sin_cos(tau + h.phi);
    const SinCos<Long> free = sin_cos(h.nu * tau);
    const Long a = h.r * h.nu, t = h.tan_half;
    detail::Jet<Long> j;
    j.f = h.v * forced.cos - a * free.sin + a * t * free.cos;
    j.d1 = -h.v * forced.sin - a * h.nu * (free.cos + t * free.sin);
    j.d2 = -h.v * forced.cos + a * h.nu * h.nu * (free.sin - t * free.cos);
    const Long mag = std::fabs(h.v) + a * (1 + std::fabs(t)) * (1 + h.nu + h.nu * h.nu);
    j.e0 = j.e1 = j.e2 = 64 * eps * mag * (1 + std::fabs(tau) + h.nu * std::fabs(tau));
    return j;
  }
  Long third_bound(const Long&, const detail::Jet<Long>&, const Long&) const {
    return (std::fabs(h.v) + h.r * std::pow(h.nu, 4) * std::sqrt(1 + h.tan_half * h.tan_half)) *
           (1 + 1e-12L);
  }
  Long derivative(const Long& tau) { return jet(tau).d1; }
  Long second_derivative(const Long& tau) { return jet(tau).d2; }
  template <class F, class DF>
  detail::RootResult<Long> decreasing_root(const F& f, const DF& df, const Long& lo,
                                           const Long& hi) {
    return detail::ScalarTraits<double>::decreasing_root(f, df, lo, hi, evaluations);
  }
};

// "" if the non-stop solution is the motion, else the failed condition.
std::string failed_condition(const HalfCycle& h, Long rs) {
  if (!h.exists)
    return "no non-stop solution exists: (R/B)^2 U^2 >= V^2 (friction too high for this "
           "frequency ratio)";
  if (!(h.beta * h.beta * h.amplitude > rs))
    return "the net force at a reversal, k X beta^2, does not exceed the static friction Rs: the "
           "mass sticks there";
  const Long pi = boost::math::constants::pi<Long>();
  VelocityProbe probe{h};
  const Long blind = 1e-9L;
  const auto bracket = detail::FirstZeroSearch<Long>::run(probe, 0, [&] {
    auto j = probe.jet(0);
    j.f = 0;  // v = 0 at the reversal, exactly
    return j;
  }(), pi - blind, blind, 1e-15L);
  if (bracket.found) return "the velocity reaches zero between the reversals: the mass stops";
  return "";
}

// The exact half-cycle map of the model from a forward reversal at rest
// (x, t) to the next reversal, folded by the symmetry x -> -x, t -> t - T/2.
// Returns false if the motion does not reverse directly there (a stick, or no
// stop within a period).
bool half_cycle_map(const Model& model, double x, double t, double& x_next, double& t_next) {
  Model start = model;
  start.x0 = x;
  start.v0 = 0;
  start.t0 = t;
  const double half = boost::math::constants::pi<double>() / model.omega;
  ExactEngine engine(start, t + 4 * half);
  Phase phase;
  if (!engine.next(phase) || phase.kind != PhaseKind::slip_forward) return false;
  Phase after;
  if (!engine.next(after) || after.kind != PhaseKind::slip_backward) return false;
  x_next = -phase.x_end;
  t_next = phase.t_end - half;
  return true;
}

// Spectral radius of the Jacobian of half_cycle_map at its fixed point, by
// central differences (the map is smooth there: the reversals are
// transversal); NaN if a perturbed motion does not reverse directly.
double growth_factor(const Model& model, double x, double t) {
  const double hx = 1e-6 * std::max(std::fabs(x), 1e-300);
  const double ht = 1e-6 * boost::math::constants::pi<double>() / model.omega;
  double j[2][2];
  for (int column = 0; column < 2; ++column) {
    double plus[2], minus[2];
    const double dx = column == 0 ? hx : 0, dt = column == 1 ? ht : 0;
    if (!half_cycle_map(model, x + dx, t + dt, plus[0], plus[1]) ||
        !half_cycle_map(model, x - dx, t - dt, minus[0], minus[1]))
      return std::numeric_limits<double>::quiet_NaN();
    const double h = column == 0 ? hx : ht;
    for (int row = 0; row < 2; ++row) j[row][column] = (plus[row] - minus[row]) / (2 * h);
  }
  // Eigenvalues of a 2x2 matrix: trace / 2 +- sqrt((trace / 2)^2 - det).
  const double half_trace = (j[0][0] + j[1][1]) / 2;
  const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  const double disc = half_trace * half_trace - det;
  if (disc < 0) return std::sqrt(std::fabs(det));  // complex pair: |lambda|^2 = det
  const double root = std::sqrt(disc);
  return std::max(std::fabs(half_trace + root), std::fabs(half_trace - root));
}

}  // namespace

bool den_hartog_applies(const Model& model) {
  return model.stiffness > 0 && model.damping == 0 && model.force_offset == 0 &&
         model.amplitude > 0 && model.harmonics.empty();
}

DenHartogSolution den_hartog(const Model& model) {
  model.validate();
  const auto refuse = [](const char* name, double value, const char* rule) {
    throw InvalidInput(name, detail::shortest_text(value), rule);
  };
  const char* why = "must be 0 for Den Hartog's non-stop solution (spring + Coulomb, no damper)";
  if (!(model.stiffness > 0)) refuse("stiffness", model.stiffness, "must be > 0 for Den Hartog's solution");
  if (model.damping != 0) refuse("damping", model.damping, why);
  if (model.force_offset != 0) refuse("force_offset", model.force_offset, why);
  if (!(model.amplitude > 0)) refuse("amplitude", model.amplitude, "must be > 0 for Den Hartog's solution");
  if (!model.harmonics.empty())
    throw InvalidInput("harmonics", std::to_string(model.harmonics.size()) + " terms",
                       "must be empty for Den Hartog's solution (one harmonic B sin(w t))");
  const Long m = model.mass, k = model.stiffness, B = model.amplitude, w = model.omega;
  const Long beta = w / std::sqrt(k / m);
  const HalfCycle h = half_cycle(beta, Long(model.friction) / B);
  DenHartogSolution s;
  s.frequency_ratio = static_cast<double>(beta);
  s.failed = failed_condition(h, Long(model.static_limit()) / B);
  s.non_stop = s.failed.empty();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.amplitude = h.exists ? static_cast<double>(h.amplitude * B / k) : nan;
  if (h.exists) {
    const Long two_pi = boost::math::constants::two_pi<Long>();
    Long phase = std::fmod(h.phi, two_pi);
    if (phase < 0) phase += two_pi;
    s.reversal_phase = static_cast<double>(phase);
  } else {
    s.reversal_phase = nan;
  }
  if (s.non_stop) {
    const double x = -s.amplitude;
    const double t = s.reversal_phase / model.omega;
    s.growth = growth_factor(model, x, t);
    // Asymptotically stable with a margin: near beta = 1/2 the radius tends
    // to 1 (the free mode at 2 w repeats each half cycle) and motions from
    // elsewhere do not settle on the solution in any practical time.
    s.stable = s.growth <= kStableRadius;
    if (!s.stable)
      s.failed = "the non-stop solution exists but does not attract nearby motions (the "
                 "half-cycle map's spectral radius is " + detail::shortest_text(s.growth) +
                 ", not below " + detail::shortest_text(kStableRadius) + ")";
  }
  s.peak_velocity = nan;
  if (s.non_stop) {
    // max of dx/dtau over the half cycle, where it is positive and smooth:
    // the best of a scan finer than both frequencies, refined by Brent's
    // minimizer on the neighbouring samples.
    const Long pi = boost::math::constants::pi<Long>();
    VelocityProbe probe{h};
    const int samples = 256 + static_cast<int>(64 * h.nu);
    int best = 1;
    Long best_value = 0;
    for (int i = 1; i < samples; ++i) {
      const Long value = probe.jet(pi * i / samples).f;
      if (value > best_value) best_value = value, best = i;
    }
    const auto negative = [&](Long tau) { return -probe.jet(tau).f; };
    std::uintmax_t iterations = 200;
    const auto peak = boost::math::tools::brent_find_minima(
        negative, pi * (best - 1) / samples, pi * (best + 1) / samples,
        std::numeric_limits<Long>::digits / 2, iterations);
    // dx/dt = w dx/dtau, in units of B/k.
    s.peak_velocity = static_cast<double>(-peak.second * w * B / k);
  }
  return s;
}

double den_hartog_boundary(double frequency_ratio, double static_ratio) {
  if (!(frequency_ratio > 0) || !std::isfinite(frequency_ratio))
    throw InvalidInput("frequency_ratio", detail::shortest_text(frequency_ratio), "must be > 0");
  if (!(static_ratio >= 1) || !std::isfinite(static_ratio))
    throw InvalidInput("static_ratio", detail::shortest_text(static_ratio), "must be >= 1");
  const Long beta = frequency_ratio;
  const auto holds = [&](Long r) {
    const HalfCycle h = half_cycle(beta, r);
    return failed_condition(h, static_ratio * r).empty();
  };
  // Small lambda gives non-stop motion; the existence limit |V / U| bounds
  // the boundary from above (0 where U is infinite: beta = 1/(2j+1), j >= 1).
  const HalfCycle unit = half_cycle(beta, 0);
  const Long u = unit.nu * unit.tan_half;
  if (!std::isfinite(u)) return 0;
  Long hi = u != 0 ? std::fabs(unit.v / u) : Long(1e6);
  if (!(hi < 1e6L)) hi = 1e6L;
  if (holds(hi * (1 - 1e-12L))) return static_cast<double>(hi);
  Long lo = 0;
  while (hi - lo > 1e-12L * hi) {
    const Long mid = (lo + hi) / 2;
    (holds(mid) ? lo : hi) = mid;
  }
  return static_cast<double>(lo);
}

}  // namespace frictionref
