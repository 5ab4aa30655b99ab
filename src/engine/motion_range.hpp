// The range of motions the engine accepts (docs/theory.md 4.12): every model
// is refused, with a message naming a parameter, whose motion could leave the
// range of double (a priori bounds on |a|, |v| and |x| over the horizon, from
// the family), or whose forces are so small that positions, velocities and
// accelerations would be subnormal doubles without their relative precision.
#pragma once

#include <cmath>
#include <string>

#include "engine/scalar_traits.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/model.hpp"

namespace frictionref::detail {

// A priori bounds of the motion over [t0, t_end], from the family's closed forms.
template <class Work>
struct MotionBounds {
  Work acceleration = 0;  // max |a|
  Work speed = 0;         // max |v|
  Work travel = 0;        // max |x|
};

// Throws InvalidInput if a bound leaves [0, largest_motion). The velocity and
// acceleration are blamed on the amplitude B with the velocity scale
// `velocity_scale` (named `scale_name`, e.g. "B/(m w)") quoted, the position
// on t_end.
template <class Real, class Work>
void check_motion_bounds(const BasicModel<Real>& model, const Real& t_end,
                         const MotionBounds<Work>& bounds, const Work& velocity_scale,
                         const char* scale_name) {
  using std::isfinite;
  const Work limit(MotionLimits::largest_motion);
  if (!(isfinite(bounds.acceleration) && bounds.acceleration < limit &&
        isfinite(bounds.speed) && bounds.speed < limit))
    throw InvalidInput("amplitude", to_text(model.amplitude),
                       "with this mass, omega and friction the velocity or acceleration "
                       "(" + std::string(scale_name) + " = " +
                           to_text(Real(velocity_scale)) + ") would leave the range of double");
  if (!(isfinite(bounds.travel) && bounds.travel < limit))
    throw InvalidInput("t_end", to_text(t_end),
                       "the position could leave the range of double before t_end (|x| up "
                       "to " + to_text(Real(bounds.travel)) + ")");
}

// Throws InvalidInput if the motion as a whole is too small for double: for
// each force P acting at angular frequency W (its own for a harmonic, the
// model's w for a constant force) its motion scale is min(P/m, P/(m W),
// P/(m W^2)); the largest of these must be at least smallest_motion. (A
// force far below the others is harmless: it only perturbs the motion.)
// The message names the largest force.
template <class Real, class Work>
void check_motion_scales(const BasicModel<Real>& model) {
  using std::fabs;
  const Work m(model.mass);
  struct Largest {
    std::string name;
    const char* symbol = "";
    Real force = 0;
    Work scale = -1;
  } largest;
  const auto consider = [&](const std::string& name, const char* symbol, const Real& force,
                            const Real& frequency) {
    if (force == 0) return;
    const Work acceleration = fabs(Work(force)) / m;
    const Work speed = acceleration / Work(frequency);
    const Work length = speed / Work(frequency);
    Work scale = acceleration < speed ? acceleration : speed;
    if (length < scale) scale = length;
    if (scale > largest.scale) largest = {name, symbol, force, scale};
  };
  consider("amplitude", "min(B/m, B/(m w), B/(m w^2))", model.amplitude, model.omega);
  consider("friction", "min(R/m, R/(m w), R/(m w^2))", model.friction, model.omega);
  if (model.static_friction)
    consider("static_friction", "min(Rs/m, Rs/(m w), Rs/(m w^2))", *model.static_friction,
             model.omega);
  consider("force_offset", "min(|F0|/m, |F0|/(m w), |F0|/(m w^2))", model.force_offset,
           model.omega);
  for (std::size_t i = 0; i < model.harmonics.size(); ++i)
    consider("harmonics[" + std::to_string(i) + "].amplitude",
             "min(|B_i|/m, |B_i|/(m w_i), |B_i|/(m w_i^2))", model.harmonics[i].amplitude,
             model.harmonics[i].omega);
  if (largest.scale < 0 || !(largest.scale < Work(MotionLimits::smallest_motion))) return;
  throw InvalidInput(largest.name, to_text(largest.force),
                     std::string("the motion is too small for double: the largest force's "
                                 "scale ") +
                         largest.symbol + " = " + to_text(Real(largest.scale)) +
                         " is below 2^-969 = 2.0e-292, where doubles lose their relative "
                         "precision (docs/theory.md 4.12)");
}

// Throws InvalidInput if a spring is so weak that the static deflection P/k
// of the largest force P (|F0|, R, Rs, B, |B_i|) is beyond largest_motion:
// the closed forms hold the motion as that deflection plus transients, so
// they would overflow (or cancel to nothing) although the motion itself may
// be small (found by the fuzzer: k = 5e-312 with F0 = 2e159).
template <class Real, class Work>
void check_static_deflection(const BasicModel<Real>& model) {
  using std::fabs;
  if (!(model.stiffness > 0)) return;
  Work force = fabs(Work(model.force_offset));
  const auto consider = [&force](const Work& p) {
    if (p > force) force = p;
  };
  consider(Work(model.friction));
  consider(Work(model.static_limit()));
  consider(fabs(Work(model.amplitude)));
  for (const auto& h : model.harmonics) consider(fabs(Work(h.amplitude)));
  const Work deflection = force / Work(model.stiffness);
  if (deflection < Work(MotionLimits::largest_motion)) return;
  throw InvalidInput("stiffness", to_text(model.stiffness),
                     "with forces up to " + to_text(Real(force)) +
                         " the spring's static deflection (largest force)/k is beyond 1e300, "
                         "outside the range the closed forms can hold (a spring this weak: "
                         "give stiffness 0; docs/theory.md 4.12)");
}

// Throws InvalidInput if a time scale of the model other than the forcing's
// is too short for the engine's time resolution, 8 ulps of max(1, |w t|) in
// the forcing's phase, i.e. 8 eps max(1/w, |t|) in time: a harmonic's w_i,
// the spring's natural sqrt(k/m) or the damper's rate c/m, times
// T = max(1/w, |t0|, |t_end|), must stay below max_forcing_phase = 1e10
// (the same bound the event loop puts on w t). Beyond it a velocity zero
// would be resolved to worse than ~1e-5 of that time scale, or the motion's
// fast transients would hide below the resolution.
template <class Real, class Work>
void check_time_scales(const BasicModel<Real>& model, const Real& t_end) {
  using std::fabs;
  using std::sqrt;
  Work t = Work(1) / Work(model.omega);
  for (const Work& candidate : {fabs(Work(model.t0)), fabs(Work(t_end))})
    if (candidate > t) t = candidate;
  const Work limit(MotionLimits::max_forcing_phase);
  const std::string span = "max(1/w, |t0|, |t_end|) (here " + to_text(Real(t)) + ")";
  for (std::size_t i = 0; i < model.harmonics.size(); ++i) {
    const Work phase = Work(model.harmonics[i].omega) * t;
    if (model.harmonics[i].amplitude != 0 && phase > limit)
      throw InvalidInput("harmonics[" + std::to_string(i) + "].omega",
                         to_text(model.harmonics[i].omega),
                         "must satisfy w_i " + span + " <= 1e10 rad: the engine's time resolution "
                         "(8 ulps of max(1, |w t|) / w) cannot resolve it (docs/theory.md 4.12)");
  }
  const Work natural = sqrt(Work(model.stiffness) / Work(model.mass)) * t;
  if (natural > limit)
    throw InvalidInput("stiffness", to_text(model.stiffness),
                       "with this mass the natural frequency times " + span + " is " +
                           to_text(Real(natural)) + " rad, above 1e10: the engine's time "
                           "resolution (8 ulps of max(1, |w t|) / w) cannot resolve its "
                           "oscillation (docs/theory.md 4.12)");
  const Work rate = Work(model.damping) / Work(model.mass) * t;
  if (rate > limit)
    throw InvalidInput("damping", to_text(model.damping),
                       "with this mass the damping rate c/m times " + span + " is " +
                           to_text(Real(rate)) + ", above 1e10: the engine's time resolution "
                           "(8 ulps of max(1, |w t|) / w) cannot resolve its transients "
                           "(docs/theory.md 4.12)");
}

}  // namespace frictionref::detail
