// The steady state as JSON (frictionref/classification_json.hpp).
#include "frictionref/classification_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "frictionref/version.hpp"
#include "model_json.hpp"

namespace frictionref {
namespace {

using json = nlohmann::ordered_json;

// NaN marks a figure that does not apply to the regime: null.
json value_or_null(double value) {
  if (std::isnan(value)) return nullptr;
  return value;
}

json seed_json(const Model& model, const SteadyState& steady) {
  json out;
  out["regime"] = std::string(to_string(steady.regime));
  out["method"] = std::string(to_string(ClassificationMethod::closed_form));
  out["lambda"] = value_or_null(steady.lambda);
  out["threshold"] = value_or_null(steady.threshold);
  out["threshold_quoted"] = value_or_null(steady.threshold_quoted);
  out["regime_by_quoted_threshold"] = std::string(to_string(steady.regime_by_quoted_threshold));
  out["reversal_phase"] = value_or_null(steady.reversal_phase);
  out["breakaway_phase"] = value_or_null(steady.breakaway_phase);
  out["stop_phase"] = value_or_null(steady.stop_phase);
  out["stops_per_period"] = value_or_null(steady.stops_per_period);
  out["stuck_fraction"] = value_or_null(steady.stuck_fraction);
  out["slide_per_half_period"] = value_or_null(steady.slide_per_half_period);
  out["peak_velocity"] = value_or_null(steady.peak_velocity);
  out["energy_per_period"] = value_or_null(steady.energy_per_period);
  out["model"] = detail::model_json(model);
  out["version"] = version;
  return out;
}

}  // namespace

std::string steady_state_json(const Model& model, const SteadyState& steady) {
  return seed_json(model, steady).dump();
}

std::string classification_json(const Model& model, const Classification& c) {
  if (c.seed && c.method == ClassificationMethod::closed_form)
    return seed_json(model, *c.seed).dump();
  json out;
  out["regime"] = std::string(to_string(c.regime));
  out["method"] = std::string(to_string(c.method));
  out["forcing_period"] = value_or_null(c.forcing_period);
  out["multiplicity"] = c.multiplicity;
  out["transient_periods"] = c.transient_periods;
  out["stops_per_period"] = value_or_null(c.stops_per_period);
  out["reversals_per_period"] = value_or_null(c.reversals_per_period);
  out["stuck_fraction"] = value_or_null(c.stuck_fraction);
  out["drift_per_period"] = value_or_null(c.drift_per_period);
  out["peak_velocity"] = value_or_null(c.peak_velocity);
  if (c.den_hartog) {
    const DenHartogSolution& d = *c.den_hartog;
    out["den_hartog"] = {{"non_stop", d.non_stop},
                         {"stable", d.stable},
                         {"failed", d.failed},
                         {"frequency_ratio", value_or_null(d.frequency_ratio)},
                         {"amplitude", value_or_null(d.amplitude)},
                         {"reversal_phase", value_or_null(d.reversal_phase)},
                         {"peak_velocity", value_or_null(d.peak_velocity)},
                         {"growth", value_or_null(d.growth)}};
  } else {
    out["den_hartog"] = nullptr;
  }
  out["model"] = detail::model_json(model);
  out["version"] = version;
  return out.dump();
}

}  // namespace frictionref
