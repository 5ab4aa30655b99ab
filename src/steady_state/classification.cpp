// classify(): the closed form where one applies, else the simulation
// (classification.hpp).
#include "frictionref/classification.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <sstream>

#include "enum_names.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "steady_state/periodic_simulation.hpp"

namespace frictionref {
namespace {

constexpr detail::EnumNames<ClassificationMethod, 2> kMethodNames{{
    {ClassificationMethod::closed_form, "closed-form"},
    {ClassificationMethod::simulation, "simulation"},
}};

// The seed's closed form as a classification.
Classification from_seed(const Model& model) {
  Classification c;
  c.method = ClassificationMethod::closed_form;
  c.seed = steady_state(model);
  const SteadyState& s = *c.seed;
  c.regime = s.regime;
  c.forcing_period = boost::math::constants::two_pi<double>() / model.omega;
  c.multiplicity = 1;
  c.stops_per_period = s.stops_per_period;
  c.reversals_per_period = s.regime == Regime::continuous ? 2 : 0;
  c.stuck_fraction = s.stuck_fraction;
  c.drift_per_period = 0;
  c.peak_velocity = s.peak_velocity;
  return c;
}

}  // namespace

std::string_view to_string(ClassificationMethod method) {
  return detail::name_of(kMethodNames, method);
}
std::optional<ClassificationMethod> classification_method_from_string(std::string_view text) {
  return detail::enum_from_name(kMethodNames, text);
}

void ClassifyOptions::validate() const {
  if (max_periods < 2)
    throw InvalidInput("max_periods", std::to_string(max_periods), "must be >= 2");
  if (max_multiplicity < 1)
    throw InvalidInput("max_multiplicity", std::to_string(max_multiplicity), "must be >= 1");
  if (!std::isfinite(tolerance))
    throw InvalidInput("tolerance", detail::shortest_text(tolerance), "must be a finite number");
  if (!(tolerance > 0))
    throw InvalidInput("tolerance", detail::shortest_text(tolerance), "must be > 0");
}

Classification classify(const Model& model, const ClassifyOptions& options) {
  model.validate();
  options.validate();
  model.refuse_ground_motion(
      "has no steady state to classify: a record is a transient (use events, curve or newmark)");
  if (options.closed_forms && model.is_harmonic_coulomb()) return from_seed(model);
  std::optional<DenHartogSolution> den_hartog_solution;
  if (den_hartog_applies(model)) {
    den_hartog_solution = den_hartog(model);
    if (options.closed_forms && den_hartog_solution->non_stop && den_hartog_solution->stable) {
      Classification c;
      c.method = ClassificationMethod::closed_form;
      c.regime = Regime::continuous;
      c.forcing_period = boost::math::constants::two_pi<double>() / model.omega;
      c.multiplicity = 1;
      c.stops_per_period = 0;
      c.reversals_per_period = 2;
      c.stuck_fraction = 0;
      c.drift_per_period = 0;
      c.peak_velocity = den_hartog_solution->peak_velocity;
      c.den_hartog = den_hartog_solution;
      return c;
    }
  }
  Classification c = detail::simulate_steady_state(model, options);
  c.den_hartog = den_hartog_solution;
  if (model.is_harmonic_coulomb() && model.amplitude > 0) c.seed = steady_state(model);
  return c;
}

std::string Classification::report() const {
  std::ostringstream text;
  text.precision(17);
  text << "regime: " << to_string(regime) << "\n"
       << "method: " << to_string(method) << "\n"
       << "forcing_period: " << forcing_period << "\n"
       << "multiplicity: " << multiplicity << "\n"
       << "transient_periods: " << transient_periods << "\n"
       << "stops_per_period: " << stops_per_period << "\n"
       << "reversals_per_period: " << reversals_per_period << "\n"
       << "stuck_fraction: " << stuck_fraction << "\n"
       << "drift_per_period: " << drift_per_period << "\n"
       << "peak_velocity: " << peak_velocity << "\n";
  return text.str();
}

}  // namespace frictionref
