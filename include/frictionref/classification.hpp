// The steady state of any model (docs/theory.md 8): from a closed form where
// one exists (the seed's model, steady_state.hpp; Den Hartog's non-stop
// solution for spring + Coulomb without damping, den_hartog.hpp), otherwise
// by simulation with the exact engine: the motion is followed period by
// period of the forcing until it repeats (after p periods, p up to
// max_multiplicity), and the repeating stretch is measured.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "frictionref/den_hartog.hpp"
#include "frictionref/model.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

struct ClassifyOptions {
  // Forcing periods simulated at most before giving up on a repeating motion; >= 2.
  std::uint64_t max_periods = 400;
  // Longest repeating motion looked for, in forcing periods; >= 1.
  unsigned max_multiplicity = 8;
  // Two states one repetition apart agree when v differs by less than this
  // times the velocity scale and x by less than this times the length scale
  // (forces / (m w) and / (m w^2)); finite, > 0.
  double tolerance = 1e-9;
  // Use a closed form where one applies (else always simulate).
  bool closed_forms = true;

  // Throws InvalidInput naming the field and the rule.
  void validate() const;
};

enum class ClassificationMethod {
  closed_form,  // the seed's steady state or Den Hartog's non-stop solution
  simulation,   // the exact engine, period after period
};
// "closed-form", "simulation"
std::string_view to_string(ClassificationMethod method);
std::optional<ClassificationMethod> classification_method_from_string(std::string_view text);

struct Classification {
  Regime regime = Regime::stops;  // stops: at rest; dead-bands: sticks in the steady motion;
                                  // continuous: moving throughout; aperiodic: no repetition found
  ClassificationMethod method = ClassificationMethod::simulation;

  // The forcing's common period T [time] (the engine's 2 pi / w when the
  // force is constant); NaN when the harmonics have no common period of at
  // most 1000 periods of the first frequency (then the statistics are over
  // the last max_multiplicity periods of 2 pi / w, and regime is aperiodic
  // unless the mass came to rest).
  double forcing_period = 0;
  unsigned multiplicity = 0;  // the steady motion repeats after this many forcing periods; 0: none found
  std::uint64_t transient_periods = 0;  // periods simulated before the repetition was seen
                                        // (simulation; 0 for closed forms)

  // Per forcing period of the steady motion (over the measured stretch):
  double stops_per_period = 0;      // sticks of non-zero duration that begin
  double reversals_per_period = 0;  // direct reversals (slip to slip the other way, no rest)
  double stuck_fraction = 0;        // fraction of the time at rest
  double drift_per_period = 0;      // x(t + p T) - x(t), divided by p [length]
  double peak_velocity = 0;         // max |v| over the stretch [length / time]

  std::optional<SteadyState> seed;             // the seed's closed form, when it applies
  std::optional<DenHartogSolution> den_hartog; // Den Hartog's solution, when it applies

  std::string report() const;  // "name: value" lines for people
};

// Validates the model and options (InvalidInput). The seed's model needs
// B > 0 (as steady_state()); any other model is classified by simulation
// unless Den Hartog's non-stop solution holds.
Classification classify(const Model& model, const ClassifyOptions& options = {});

// The forcing's common period [time]: 2 pi / w_f, with w_f the largest
// frequency of which every forcing frequency (w when B != 0, each w_i with
// B_i != 0) is a whole multiple, each ratio recognised as a fraction with a
// denominator of at most 1000 (to 1e-12 relative); 2 pi / w for a constant
// force; nullopt when there is no such period, or it exceeds 1000 periods of
// the first forcing frequency.
std::optional<double> forcing_period(const Model& model);

}  // namespace frictionref
