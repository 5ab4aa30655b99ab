// What the compare() tests share: the exact motion sampled on a grid (the
// candidate that must pass) and the lookup of one check in a report.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/model.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref::testing {

// Sample times t0 + i dt up to t_end (i counted, never accumulated).
inline std::vector<double> grid(double t0, double t_end, double dt) {
  std::vector<double> t;
  const auto n = static_cast<std::int64_t>(std::llround((t_end - t0) / dt));
  for (std::int64_t i = 0; i <= n; ++i) t.push_back(t0 + static_cast<double>(i) * dt);
  return t;
}

// The exact motion itself, sampled with step dt from model.t0.
inline TimeHistory exact_history(const Model& model, double t_end, double dt) {
  TimeHistory history;
  history.t = grid(model.t0, t_end, dt);
  history.x.emplace();
  for (const State& s : sample_at(model, history.t)) {
    history.v.push_back(s.v);
    history.x->push_back(s.x);
  }
  history.source = "exact";
  return history;
}

// An independent stiff-spring code (THEORY.md, "the stiff-spring model"), the
// candidate of the compare tests: friction -K_f (x - z) through a spring in
// series with a Coulomb slider z, clipped to +-R (return mapping); explicit
// central differences under the force `force(t)` (called at increasing t).
// Archives t, v (the mean of the two half-step velocities) and x every
// `archive` time from model.t0.
template <class Force>
TimeHistory stiff_spring_history(const Model& m, double t_end, Force&& force, double k_f, double dt,
                                 double archive, const char* source) {
  const auto every = static_cast<std::int64_t>(std::llround(archive / dt));
  const auto steps = static_cast<std::int64_t>(std::llround((t_end - m.t0) / dt));
  double x = m.x0, z = m.x0;
  double f = 0;                                                  // friction force on the mass
  double v_half = m.v0 - 0.5 * dt * (force(m.t0) + f) / m.mass;  // v at t0 - dt/2
  TimeHistory history;
  history.x.emplace();
  for (std::int64_t n = 0; n <= steps; ++n) {
    const double t = m.t0 + static_cast<double>(n) * dt;
    const double trial = -k_f * (x - z);
    if (std::fabs(trial) > m.friction) {
      f = std::copysign(m.friction, trial);
      z = x + f / k_f;  // the slider slips so the spring carries exactly R
    } else {
      f = trial;
    }
    const double v_next = v_half + dt * (force(t) + f) / m.mass;
    if (n % every == 0) {
      history.t.push_back(m.t0 + static_cast<double>(n / every) * archive);
      history.v.push_back(0.5 * (v_half + v_next));
      history.x->push_back(x);
    }
    x += dt * v_next;
    v_half = v_next;
  }
  history.source = source;
  return history;
}

// The report's check of this kind, or nullptr.
inline const Check* find_check(const ComparisonReport& report, CheckKind kind) {
  for (const Check& check : report.checks)
    if (check.kind == kind) return &check;
  return nullptr;
}

}  // namespace frictionref::testing
