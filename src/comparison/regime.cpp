#include "regime.hpp"

#include <algorithm>
#include <cmath>

namespace frictionref::comparison {
namespace {

struct Shown {
  Regime regime = Regime::stops;
  double stops_per_period = 0;
};

// Stops if at rest throughout the window, dead bands if any stick reaches into
// it, continuous otherwise.
Shown shown_regime(const std::vector<double>& t, const std::vector<double>& v,
                   const std::vector<StickInterval>& sticks, double window_start, double threshold,
                   double window_periods) {
  bool at_rest = true;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= window_start && !(std::fabs(v[i]) < threshold)) at_rest = false;
  Shown shown;
  if (at_rest) return shown;
  const auto count = std::count_if(sticks.begin(), sticks.end(),
                                   [&](const StickInterval& s) { return s.end > window_start; });
  shown.regime = count > 0 ? Regime::dead_bands : Regime::continuous;
  shown.stops_per_period = static_cast<double>(count) / window_periods;
  return shown;
}

}  // namespace

void read_regime(ComparisonReport& r, const std::vector<double>& t,
                 const std::vector<double>& v_exact, const std::vector<double>& v) {
  const double record = r.t_last - r.t_first;
  const double window = std::min(r.options.regime_window * r.scales.period, record);
  r.regime_window_start = r.t_last - window;
  if (r.model.ground_motion) {
    // The ground is still after the record's last sample, so friction brings
    // the block to rest in a finite time and it stays there: the steady state
    // is known in closed form without classify (which refuses a transient).
    r.exact_regime = Regime::stops;
    r.exact_regime_method = ClassificationMethod::closed_form;
  } else {
    const Classification steady = classify(r.model);
    r.exact_regime = steady.regime;
    r.exact_regime_method = steady.method;
  }
  const Shown exact = shown_regime(t, v_exact, r.exact_sticks, r.regime_window_start,
                                   r.stick_velocity, window / r.scales.period);
  const Shown candidate = shown_regime(t, v, r.candidate_sticks, r.regime_window_start,
                                       r.stick_velocity, window / r.scales.period);
  r.exact_shown_regime = exact.regime;
  r.exact_stops_per_period = exact.stops_per_period;
  r.candidate_regime = candidate.regime;
  r.candidate_stops_per_period = candidate.stops_per_period;
}

}  // namespace frictionref::comparison
