#include "exact_motion.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::comparison {

ExactMotion exact_motion(const Model& model, const std::vector<double>& t) {
  ExactMotion m;
  m.model = model;
  const double t_last = t.back();
  // A record shorter than the engine's time resolution still gets a horizon
  // the engine takes.
  const double last = resolvable_t_end(model, t_last);
  ExactEngine engine(model, last);
  Phase phase;
  const auto next = [&] {
    if (!engine.next(phase)) return false;
    if (phase.t_begin < t_last || m.phases.empty()) m.phases.push_back(phase);
    return true;
  };
  if (!next()) throw std::runtime_error("exact engine: " + engine.summary().message);
  std::optional<PhaseEvaluator> law(std::in_place, model, phase);
  m.states.resize(t.size());
  for (std::size_t i = 0; i < t.size();) {
    bool moved = false;
    while (t[i] >= phase.t_end && phase.t_end < last) {
      if (!next()) throw std::runtime_error("exact engine: " + engine.summary().message);
      moved = true;
    }
    if (moved) law = law->for_phase(phase);
    // This time and the following ones in the same phase, evaluated together
    // (four or eight at a time on the dense fast paths), as sample_at() does.
    std::size_t end = i + 1;
    while (end < t.size() && (t[end] < phase.t_end || phase.t_end >= last)) ++end;
    (*law)(&t[i], end - i, &m.states[i]);
    i = end;
  }
  while (next()) {
  }
  if (engine.summary().termination != Termination::reached_end)
    throw std::runtime_error("exact engine: " + engine.summary().message);
  return m;
}

State ExactMotion::at(double t) const {
  const double time = std::clamp(t, phases.front().t_begin, phases.back().t_end);
  // The last phase that begins at or before `time`.
  auto it = std::upper_bound(phases.begin(), phases.end(), time,
                             [](double value, const Phase& p) { return value < p.t_begin; });
  if (it != phases.begin()) --it;
  return evaluate(model, *it, std::min(time, it->t_end));
}

std::vector<double> ExactMotion::v() const {
  std::vector<double> out(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) out[i] = states[i].v;
  return out;
}

std::vector<double> ExactMotion::x() const {
  std::vector<double> out(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) out[i] = states[i].x;
  return out;
}

}  // namespace frictionref::comparison
