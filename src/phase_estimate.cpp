// The phase-count estimate of a run (phase_estimate.hpp).
#include "frictionref/phase_estimate.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace frictionref {

PhaseEstimate estimate_phases(const Model& model, double t_end) {
  const double span = t_end - model.t0;
  // The forcing's fastest angular frequency (w counts even with B = 0, as it
  // always has), and the natural one sqrt(k/m) of the spring.
  double forcing = model.omega;
  for (const Harmonic& h : model.harmonics)
    if (h.amplitude != 0) forcing = std::max(forcing, h.omega);
  const double natural = std::sqrt(model.stiffness / model.mass);
  const double per_period = 4 / boost::math::double_constants::two_pi;
  PhaseEstimate estimate;
  const bool spring_faster = natural > forcing;
  estimate.phases = span * std::max(forcing, natural) * per_period + 4;
  estimate.basis = spring_faster ? "4 per natural period 2 pi sqrt(m/k)" : "4 per forcing period";
  if (model.ground_motion) {
    const std::vector<double>& t = model.ground_motion->t;
    const auto first = std::lower_bound(t.begin(), t.end(), model.t0);
    const auto last = std::upper_bound(t.begin(), t.end(), t_end);
    const double intervals = static_cast<double>(std::max<std::ptrdiff_t>(last - first, 1));
    if (4 * intervals > estimate.phases) estimate.basis = "4 per record sample";
    estimate.phases += 4 * intervals;
  }
  return estimate;
}

}  // namespace frictionref
