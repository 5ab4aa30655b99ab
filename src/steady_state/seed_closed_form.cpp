// Steady-state closed forms (docs/theory.md section 5). Computed in long
// double and rounded once, so the regime test against lambda* is exact for
// every double lambda.
#include "frictionref/steady_state.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "engine/scalar_traits.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"

namespace frictionref {
namespace {

using Long = long double;

Long threshold_long() {
  const Long pi = boost::math::constants::pi<Long>();
  return 2 / std::sqrt(4 + pi * pi);
}

// The end of the forward slip that starts at the breakaway alpha = asin(lambda):
// the zero of V(tau) = cos(alpha) - cos(tau) - lambda (tau - alpha) in
// [pi - alpha, pi + alpha], where V decreases from positive to <= 0 when
// lambda >= lambda*.
Long dead_band_stop(Long lambda, Long alpha) {
  const Long pi = boost::math::constants::pi<Long>();
  const auto speed = [&](Long tau) { return std::cos(alpha) - std::cos(tau) - lambda * (tau - alpha); };
  const auto slope = [&](Long tau) { return std::sin(tau) - lambda; };
  const Long lo = pi - alpha;
  const Long hi = pi + alpha;
  if (speed(hi) >= 0) return hi;  // lambda = lambda*: the dead band has zero length
  std::uint64_t calls = 0;
  return detail::ScalarTraits<double>::decreasing_root(speed, slope, lo, hi, calls).root;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double regime_threshold() { return static_cast<double>(threshold_long()); }

Regime regime_for(double lambda) {
  if (static_cast<Long>(lambda) < threshold_long()) return Regime::continuous;
  if (lambda < 1) return Regime::dead_bands;
  return Regime::stops;
}

SteadyState steady_state(const Model& model) {
  model.validate();
  {
    // The closed forms below are the seed's model's only (classify() takes any model).
    const char* rule = "must be 0 for the seed's closed-form steady state (classify() takes "
                       "every model)";
    if (model.stiffness != 0) throw InvalidInput("stiffness", detail::shortest_text(model.stiffness), rule);
    if (model.damping != 0) throw InvalidInput("damping", detail::shortest_text(model.damping), rule);
    if (model.force_offset != 0)
      throw InvalidInput("force_offset", detail::shortest_text(model.force_offset), rule);
    if (!model.harmonics.empty())
      throw InvalidInput("harmonics", std::to_string(model.harmonics.size()) + " terms",
                         "must be empty for the seed's closed-form steady state (classify() "
                         "takes every model)");
    if (model.static_limit() != model.friction)
      throw InvalidInput("static_friction", detail::shortest_text(model.static_limit()),
                         "must equal the sliding friction for the seed's closed-form steady "
                         "state (classify() takes every model)");
  }
  if (!(model.amplitude > 0)) {
    std::ostringstream value;
    value << model.amplitude;
    throw InvalidInput("amplitude", value.str(),
                       "must be > 0 for the steady state (the regime is a property of R / B)");
  }
  SteadyState s;
  const Long lambda = Long(model.friction) / Long(model.amplitude);
  s.lambda = static_cast<double>(lambda);
  s.threshold = regime_threshold();
  // Classified by the lambda the report shows (R/B rounded to double), so
  // regime_for(report.lambda) always agrees with it, even within an ulp of
  // lambda* (found by fuzzing).
  s.regime = regime_for(s.lambda);
  s.regime_by_quoted_threshold = s.lambda < regime_threshold_quoted ? Regime::continuous
                                 : s.lambda < 1                     ? Regime::dead_bands
                                                                    : Regime::stops;
  s.reversal_phase = s.breakaway_phase = s.stop_phase = kNaN;

  const Long pi = boost::math::constants::pi<Long>();
  const Long m = model.mass, w = model.omega, B = model.amplitude, R = model.friction;
  const Long velocity_unit = B / (m * w);        // V = v m w / B
  const Long length_unit = B / (m * w * w);      // X = x m w^2 / B
  switch (s.regime) {
    case Regime::continuous: {
      // Reversals every half period where cos(tau1) = lambda pi / 2.
      const Long tau1 = std::acos(lambda * pi / 2);
      const Long alpha = std::asin(lambda);
      const Long slide = 2 * std::sin(tau1);
      const Long peak = std::cos(tau1) + std::cos(alpha) - lambda * (pi - alpha - tau1);
      s.reversal_phase = static_cast<double>(tau1);
      s.stops_per_period = 0;
      s.stuck_fraction = 0;
      s.slide_per_half_period = static_cast<double>(slide * length_unit);
      s.peak_velocity = static_cast<double>(peak * velocity_unit);
      s.energy_per_period = static_cast<double>(R * 2 * slide * length_unit);
      break;
    }
    case Regime::dead_bands: {
      const Long alpha = std::asin(lambda);
      const Long stop = dead_band_stop(lambda, alpha);
      const Long h = stop - alpha;
      const Long slide = std::cos(alpha) * h - (std::sin(stop) - std::sin(alpha)) - lambda * h * h / 2;
      const Long peak = 2 * std::cos(alpha) - lambda * (pi - 2 * alpha);
      s.breakaway_phase = static_cast<double>(alpha);
      s.stop_phase = static_cast<double>(stop);
      s.stops_per_period = 2;
      s.stuck_fraction = static_cast<double>(1 - h / pi);
      s.slide_per_half_period = static_cast<double>(slide * length_unit);
      s.peak_velocity = static_cast<double>(peak * velocity_unit);
      s.energy_per_period = static_cast<double>(R * 2 * slide * length_unit);
      break;
    }
    case Regime::aperiodic:  // not a regime of the seed's closed form
    case Regime::stops:
      s.stops_per_period = 0;
      s.stuck_fraction = 1;
      s.slide_per_half_period = 0;
      s.peak_velocity = 0;
      s.energy_per_period = 0;
      break;
  }
  return s;
}

std::string SteadyState::report() const {
  std::ostringstream text;
  text.precision(17);
  text << "regime: " << to_string(regime) << "\n"
       << "lambda: " << lambda << "\n"
       << "threshold: " << threshold << "\n"
       << "threshold_quoted: " << threshold_quoted << "\n"
       << "regime_by_quoted_threshold: " << to_string(regime_by_quoted_threshold) << "\n"
       << "reversal_phase: " << reversal_phase << "\n"
       << "breakaway_phase: " << breakaway_phase << "\n"
       << "stop_phase: " << stop_phase << "\n"
       << "stops_per_period: " << stops_per_period << "\n"
       << "stuck_fraction: " << stuck_fraction << "\n"
       << "slide_per_half_period: " << slide_per_half_period << "\n"
       << "peak_velocity: " << peak_velocity << "\n"
       << "energy_per_period: " << energy_per_period << "\n";
  return text.str();
}

}  // namespace frictionref
