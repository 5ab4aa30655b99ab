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

// The report's check of this kind, or nullptr.
inline const Check* find_check(const ComparisonReport& report, CheckKind kind) {
  for (const Check& check : report.checks)
    if (check.kind == kind) return &check;
  return nullptr;
}

}  // namespace frictionref::testing
