// The physical model: the general friction oscillator (docs/theory.md 1 and 7).
//
//   m x'' + c x' + k x = F(t) - f,
//   F(t) = F0 + B sin(w t) + sum_i B_i sin(w_i t + phi_i),
//
// starting from (x0, v0) at t0, all values in user units (any consistent set:
// force = mass * length / time^2). The friction force f follows Coulomb's law
// with a static limit Rs >= R (sliding friction R):
//
//   v != 0:  f = R sign(v)
//   v  = 0:  N(t) = F(t) - k x is the net non-friction force; the mass stays at
//            rest while |N| <= Rs and breaks away in the direction of N the
//            first time |N| > Rs. A slip that reaches v = 0 sticks if
//            |N| <= Rs there, else it goes on at once in the direction of N.
//
// With k = c = F0 = 0, no extra harmonics and Rs = R this is the seed's
// model (Tou & Schultheiss, USNRC problem 7): m x'' = B sin(w t) - R sign(v).
//
// Generic over the scalar type so the same engine runs in double and in a
// Boost.Multiprecision type (see multiprecision.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/ground_motion.hpp"

namespace frictionref {

// One extra term B_i sin(w_i t + phi_i) of the driving force.
template <class Real>
struct BasicHarmonic {
  Real amplitude = 0;  // B_i [force]; finite, either sign
  Real omega = 1;      // w_i [rad / time unit]; finite, > 0
  Real phase = 0;      // phi_i [rad]; finite

  bool operator==(const BasicHarmonic& other) const {
    return amplitude == other.amplitude && omega == other.omega && phase == other.phase;
  }
};

template <class Real>
struct BasicModel {
  Real mass = 1;       // m: mass; finite, > 0
  Real amplitude = 1;  // B: amplitude of the first harmonic B sin(w t); finite, >= 0
  Real omega = 1;      // w: its angular frequency [rad / time unit]; finite, > 0. Also the
                       // engine's clock: phases are resolved to 8 eps max(1, |w t|) / w.
  Real friction = 0;   // R: sliding (kinetic) friction force; finite, >= 0
  // Rs: static friction force, the largest |N| the mass resists at rest;
  // finite, >= friction. Unset: equal to friction (static = sliding).
  std::optional<Real> static_friction;
  Real stiffness = 0;     // k: restoring spring [force / length]; finite, >= 0
  Real damping = 0;       // c: viscous damper [force * time / length]; finite, >= 0
  Real force_offset = 0;  // F0: constant force [force]; finite, either sign
  std::vector<BasicHarmonic<Real>> harmonics;  // further terms of F(t)
  Real x0 = 0;                                 // initial position; finite
  Real v0 = 0;                                 // initial velocity; finite, either sign
  Real t0 = 0;  // initial time; finite, any sign (the force phase is w t, not w (t - t0))
  // A recorded ground motion (ground_motion.hpp): the ground's acceleration
  // a_g(t), linear between its samples and zero before the first and after
  // the last, enters as the force -m a_g(t); x and v are then relative to the
  // ground, in the record's units (its length unit, seconds). Shared: models
  // are copied by the million in sweeps, the samples never.
  std::shared_ptr<const GroundMotion> ground_motion;
  // With a ground motion: the block never moves towards negative x
  // (Newmark's one-way, downslope block: the slope holds it the other way).
  bool one_way = false;

  // lambda = R / B, the one dimensionless parameter of the seed's steady state.
  // +infinity when B = 0 < R; NaN when B = R = 0.
  Real lambda() const { return friction / amplitude; }

  // Rs: the static friction force (friction when not set).
  Real static_limit() const { return static_friction ? *static_friction : friction; }

  // True for the seed's model, m x'' = B sin(w t) - R sign(v) with Rs = R: no
  // spring, damper, offset or extra harmonics. The engine solves it with its
  // closed-form critical times (docs/theory.md 3); every other model goes
  // through the general phase laws (docs/theory.md 7).
  bool is_harmonic_coulomb() const {
    return stiffness == 0 && damping == 0 && force_offset == 0 && harmonics.empty() &&
           static_limit() == friction && !ground_motion;
  }

  // Throws InvalidInput("ground_motion", the record's file, rule) if the
  // model has a record: for what a transient record cannot have (a steady
  // state; the velocity scale B/(m w) of compare).
  void refuse_ground_motion(const std::string& rule) const {
    if (ground_motion) throw InvalidInput("ground_motion", ground_motion->file, rule);
  }

  // The ground's acceleration a_g(t): linear between the record's samples,
  // 0 outside them and without a record (at a sample, its value).
  Real ground_acceleration(const Real& t) const {
    if (!ground_motion) return Real(0);
    const std::vector<double>& ts = ground_motion->t;
    const std::vector<double>& as = ground_motion->a;
    if (ts.empty() || t < Real(ts.front()) || t > Real(ts.back())) return Real(0);
    // The last sample time <= t.
    const std::size_t i = static_cast<std::size_t>(
        std::upper_bound(ts.begin(), ts.end(), t,
                         [](const Real& value, double sample) { return value < Real(sample); }) -
        ts.begin() - 1);
    if (i + 1 >= ts.size()) return Real(as.back());
    const Real h = Real(ts[i + 1]) - Real(ts[i]);
    return Real(as[i]) + (Real(as[i + 1]) - Real(as[i])) * ((t - Real(ts[i])) / h);
  }

  // The driving force F(t) (without the spring, damper and friction): with a
  // ground motion, -m a_g(t) included.
  Real force(const Real& t) const {
    using std::sin;
    Real f = force_offset + amplitude * sin(omega * t);
    for (const auto& h : harmonics) f += h.amplitude * sin(h.omega * t + h.phase);
    if (ground_motion) f -= mass * ground_acceleration(t);
    return f;
  }

  // Throws InvalidInput naming the first field that breaks its rule
  // (harmonic fields as "harmonics[i].omega", 0-based).
  void validate() const {
    require_finite("mass", mass);
    require_finite("amplitude", amplitude);
    require_finite("omega", omega);
    require_finite("friction", friction);
    if (static_friction) require_finite("static_friction", *static_friction);
    require_finite("stiffness", stiffness);
    require_finite("damping", damping);
    require_finite("force_offset", force_offset);
    for (std::size_t i = 0; i < harmonics.size(); ++i) {
      const std::string name = "harmonics[" + std::to_string(i) + "].";
      require_finite((name + "amplitude").c_str(), harmonics[i].amplitude);
      require_finite((name + "omega").c_str(), harmonics[i].omega);
      require_finite((name + "phase").c_str(), harmonics[i].phase);
      if (!(harmonics[i].omega > 0))
        fail((name + "omega").c_str(), harmonics[i].omega, "must be > 0");
      // Beyond this the phase is reduced mod 2 pi to garbage (and means nothing:
      // the same limit as for w t, docs/theory.md 4.9).
      using std::fabs;
      if (!(fabs(harmonics[i].phase) <= Real(1e10)))
        fail((name + "phase").c_str(), harmonics[i].phase,
             "must satisfy |PHI| <= 1e10 rad (a double cannot resolve a phase beyond that)");
    }
    require_finite("x0", x0);
    require_finite("v0", v0);
    require_finite("t0", t0);
    if (!(mass > 0)) fail("mass", mass, "must be > 0");
    if (!(amplitude >= 0)) fail("amplitude", amplitude, "must be >= 0");
    if (!(omega > 0)) fail("omega", omega, "must be > 0");
    if (!(friction >= 0)) fail("friction", friction, "must be >= 0");
    if (static_friction && !(*static_friction >= friction))
      fail("static_friction", *static_friction,
           ("must be >= the sliding friction R = " + text_of(friction)).c_str());
    if (!(stiffness >= 0)) fail("stiffness", stiffness, "must be >= 0");
    if (!(damping >= 0)) fail("damping", damping, "must be >= 0");
    if (ground_motion) ground_motion->validate();
    if (one_way && !ground_motion)
      throw InvalidInput("one_way", "true",
                         "applies to a block under a ground motion (give a record)");
    if (one_way && v0 < 0)
      fail("v0", v0, "must be >= 0 for a one-way block (it never moves towards negative x)");
  }

 private:
  static std::string text_of(const Real& value) { return detail::to_text(value); }
  static void require_finite(const char* name, const Real& value) {
    using std::isfinite;
    if (!isfinite(value)) fail(name, value, "must be a finite number");
  }
  [[noreturn]] static void fail(const char* name, const Real& value, const char* rule) {
    throw InvalidInput(name, text_of(value), rule);
  }
};

using Model = BasicModel<double>;
using Harmonic = BasicHarmonic<double>;

// The same model in another scalar type (exact for double -> wider types).
template <class To, class From>
BasicModel<To> model_cast(const BasicModel<From>& m) {
  BasicModel<To> r;
  r.mass = To(m.mass);
  r.amplitude = To(m.amplitude);
  r.omega = To(m.omega);
  r.friction = To(m.friction);
  if (m.static_friction) r.static_friction = To(*m.static_friction);
  r.stiffness = To(m.stiffness);
  r.damping = To(m.damping);
  r.force_offset = To(m.force_offset);
  for (const auto& h : m.harmonics)
    r.harmonics.push_back({To(h.amplitude), To(h.omega), To(h.phase)});
  r.x0 = To(m.x0);
  r.v0 = To(m.v0);
  r.t0 = To(m.t0);
  r.ground_motion = m.ground_motion;
  r.one_way = m.one_way;
  return r;
}

}  // namespace frictionref
