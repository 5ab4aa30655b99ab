// Steady-state closed forms of the harmonically forced Coulomb oscillator
// (docs/theory.md section 5): the regime and, per regime, the reversal or
// breakaway/stop phases, the time fraction stuck, the slide per half period
// and the energy dissipated per period.
#pragma once

#include <string>

#include "frictionref/model.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

// lambda* = 2 / sqrt(4 + pi^2) = 0.53702927214631507685...: continuous motion
// iff lambda < lambda*.
double regime_threshold();
// The value quoted in the seed problem (from Tou & Schultheiss), for reporting.
constexpr double regime_threshold_quoted = 0.536;

// The regime for a given lambda = R / B >= 0.
Regime regime_for(double lambda);

struct SteadyState {
  Regime regime = Regime::stops;
  double lambda = 0;              // R / B
  double threshold = 0;           // lambda*, exact
  double threshold_quoted = regime_threshold_quoted;
  Regime regime_by_quoted_threshold = Regime::stops;  // what 0.536 would have said

  // Forcing phases (w t mod 2 pi, radians, in [0, 2 pi)); NaN where not applicable.
  double reversal_phase = 0;   // continuous: forward slip starts (v = 0, a > 0); cos = lambda pi / 2
  double breakaway_phase = 0;  // dead bands: forward breakaway, asin(lambda)
  double stop_phase = 0;       // dead bands: end of the forward slip (v = 0)

  double stops_per_period = 0;       // 0 continuous, 2 dead bands, 0 stops (after the transient)
  double stuck_fraction = 0;         // fraction of the period at rest: 0, (0, 1), 1
  double slide_per_half_period = 0;  // distance slid in one direction per half period [length]
  double peak_velocity = 0;          // max |v| over the period [length/time]
  double energy_per_period = 0;      // dissipated by friction per period: R * distance [energy]

  // Several lines of "name: value" for people.
  std::string report() const;
};

// Requires a valid model with amplitude > 0 (the regime is a property of
// R / B); throws InvalidInput otherwise. Independent of x0, v0, t0.
SteadyState steady_state(const Model& model);

}  // namespace frictionref
