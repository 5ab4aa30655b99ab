// The steady state by simulation (classification.hpp, docs/theory.md 8.3):
// the exact engine runs period after period of the forcing; the state at
// t0 + k T is compared with the states p = 1..max_multiplicity periods
// earlier, and once the motion has repeated with the same p at two
// consecutive period marks it is periodic with multiplicity p. The last p
// periods are then measured, over a window shifted into the longest
// event-free gap of the motion so that no event can fall on a window edge
// and be counted twice or never.
#include "steady_state/periodic_simulation.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::detail {
namespace {

struct Mark {
  double x = 0, v = 0;
  PhaseKind kind = PhaseKind::stick;
};

// Force scale of the model, for the tolerances: the largest force it has.
double force_scale(const Model& model) {
  double f = std::max({std::fabs(model.amplitude), std::fabs(model.force_offset),
                       std::fabs(model.friction), std::fabs(model.static_limit())});
  for (const Harmonic& h : model.harmonics) f = std::max(f, std::fabs(h.amplitude));
  return f;
}

// max |v| over [a, b] inside a slip phase: the best of a scan, refined by
// Brent's minimizer around it.
double peak_speed(const Model& model, const Phase& phase, double a, double b) {
  const PhaseEvaluator law(model, phase);
  constexpr int kSamples = 64;
  double best_t = a, best = 0;
  for (int i = 0; i <= kSamples; ++i) {
    const double t = a + (b - a) * i / kSamples;
    const double speed = std::fabs(law(t).v);
    if (speed > best) best = speed, best_t = t;
  }
  const double step = (b - a) / kSamples;
  std::uintmax_t iterations = 100;
  const auto found = boost::math::tools::brent_find_minima(
      [&](double t) { return -std::fabs(law(t).v); }, std::max(a, best_t - step),
      std::min(b, best_t + step), 40, iterations);
  return std::max(best, -found.second);
}

}  // namespace

Classification simulate_steady_state(const Model& model, const ClassifyOptions& options) {
  const double two_pi = boost::math::constants::two_pi<double>();
  Classification c;
  c.method = ClassificationMethod::simulation;
  const std::optional<double> common = forcing_period(model);
  const double period = common ? *common : two_pi / model.omega;
  c.forcing_period = common ? *common : std::numeric_limits<double>::quiet_NaN();
  const double force = force_scale(model);
  const double v_scale = force > 0 ? force / (model.mass * model.omega) : 1;
  const double x_scale = v_scale / model.omega;
  const double v_tolerance = options.tolerance * std::max(v_scale, std::fabs(model.v0));
  const double x_tolerance = options.tolerance * std::max(x_scale, std::fabs(model.x0));
  const bool drifts = model.stiffness == 0;  // without a spring x may shift by a constant

  const std::uint64_t periods = options.max_periods;
  const auto mark_time = [&](std::uint64_t k) {
    return model.t0 + static_cast<double>(k) * period;
  };
  ExactEngine engine(model, mark_time(periods + 1));
  // Phases of the last max_multiplicity + 2 periods (the measured stretch and
  // one more period for the shifted window).
  std::deque<Phase> recent;
  std::vector<Mark> marks;  // state at t0 + k T, k = 0, 1, ...
  marks.push_back({model.x0, model.v0, PhaseKind::stick});
  Phase phase;
  bool have = engine.next(phase);
  if (have) recent.push_back(phase);

  const auto state_at = [&](double t) {
    // The phase holding t (the last one also owns its end).
    while (have && phase.t_end <= t && engine.next(phase)) recent.push_back(phase);
    for (auto it = recent.rbegin(); it != recent.rend(); ++it)
      if (it->t_begin <= t && t <= it->t_end) return evaluate(model, *it, t);
    return evaluate(model, recent.back(), recent.back().t_end);
  };
  const auto repeats = [&](std::size_t k, unsigned p) {
    if (k < 2 * static_cast<std::size_t>(p)) return false;
    const Mark& now = marks[k];
    const Mark& then = marks[k - p];
    if (now.kind != then.kind || std::fabs(now.v - then.v) > v_tolerance) return false;
    const double shift = now.x - then.x;
    if (!drifts) return std::fabs(shift) <= x_tolerance;
    return std::fabs(shift - (then.x - marks[k - 2 * p].x)) <= x_tolerance;
  };

  // The smallest p that repeats at two consecutive marks. A p > 1 found
  // first may be a slowly converging motion of a divisor of p (an
  // alternating approach repeats sooner over two periods than over one), so
  // the run goes on as long again as it took, for the divisors to settle.
  unsigned multiplicity = 0;
  std::uint64_t k = 0;
  std::uint64_t settle_until = 0;
  const auto holds = [&](std::uint64_t at, unsigned p) { return repeats(at, p) && repeats(at - 1, p); };
  for (k = 1; k <= periods; ++k) {
    const State s = state_at(mark_time(k));
    marks.push_back({s.x, s.v, s.phase});
    const double keep_from = mark_time(k >= options.max_multiplicity + 1
                                           ? k - options.max_multiplicity - 1
                                           : 0);
    while (recent.size() > 1 && recent.front().t_end < keep_from) recent.pop_front();
    if (!common) continue;  // no period to repeat with
    if (multiplicity) {
      for (unsigned p = 1; p < multiplicity; ++p)
        if (multiplicity % p == 0 && holds(k, p)) {
          multiplicity = p;
          break;
        }
      if (multiplicity == 1 || k >= settle_until) break;
      continue;
    }
    for (unsigned p = 1; p <= options.max_multiplicity; ++p) {
      if (holds(k, p)) {
        multiplicity = p;
        settle_until = std::min<std::uint64_t>(2 * k, periods);
        break;
      }
    }
    if (multiplicity == 1) break;
  }
  if (engine.summary().termination == Termination::numerical_failure)
    throw std::runtime_error("exact engine: " + engine.summary().message);
  if (k > periods) k = periods;
  c.multiplicity = multiplicity;
  c.transient_periods = multiplicity ? k - multiplicity : k;

  // The measured stretch: the last p periods (max_multiplicity when none
  // repeated), shifted by `offset` into the longest gap between events.
  const unsigned p = multiplicity ? multiplicity
                                  : static_cast<unsigned>(std::min<std::uint64_t>(
                                        options.max_multiplicity, k));
  const double a0 = mark_time(k - p), b0 = mark_time(k);
  state_at(mark_time(k + 1));  // one more period for the shifted window
  std::vector<double> events;
  for (const Phase& ph : recent)
    if (ph.t_begin >= a0 && ph.t_begin < a0 + period) events.push_back(ph.t_begin - a0);
  double offset = 0;
  if (!events.empty()) {
    std::sort(events.begin(), events.end());
    double best_gap = events.front() + period - events.back();  // wrapping around
    offset = std::fmod(events.back() + best_gap / 2, period);
    for (std::size_t i = 1; i < events.size(); ++i) {
      const double gap = events[i] - events[i - 1];
      if (gap > best_gap) best_gap = gap, offset = events[i - 1] + gap / 2;
    }
  }
  const double a = a0 + offset, b = b0 + offset;

  double stuck = 0;
  std::uint64_t stops = 0, reversals = 0;
  double peak = 0;
  bool at_rest_throughout = true;
  const Phase* previous = nullptr;
  for (const Phase& ph : recent) {
    const double lo = std::max(ph.t_begin, a), hi = std::min(ph.t_end, b);
    if (hi > lo) {
      if (ph.kind == PhaseKind::stick) {
        stuck += hi - lo;
      } else {
        at_rest_throughout = false;
        peak = std::max(peak, peak_speed(model, ph, lo, hi));
      }
    }
    if (previous && ph.t_begin >= a && ph.t_begin < b) {
      const bool from_slip = previous->kind != PhaseKind::stick;
      if (ph.kind == PhaseKind::stick && from_slip) ++stops;
      if (ph.kind != PhaseKind::stick && from_slip && ph.kind != previous->kind) ++reversals;
    }
    previous = &ph;
  }
  const double span = b - a;
  c.stops_per_period = static_cast<double>(stops) / p;
  c.reversals_per_period = static_cast<double>(reversals) / p;
  c.stuck_fraction = span > 0 ? stuck / span : 1;
  c.peak_velocity = peak;
  c.drift_per_period = (state_at(b).x - state_at(a).x) / p;
  if (at_rest_throughout) {
    c.regime = Regime::stops;
  } else if (!multiplicity) {
    c.regime = Regime::aperiodic;
  } else {
    c.regime = stops > 0 ? Regime::dead_bands : Regime::continuous;
  }
  return c;
}

}  // namespace frictionref::detail
