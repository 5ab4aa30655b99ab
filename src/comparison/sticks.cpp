#include "sticks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionref {
namespace {

// Where |v| crosses `threshold` between two samples on either side of it.
double crossing(double ta, double a, double tb, double b, double threshold) {
  if (a == b) return ta;
  const double fraction = std::clamp((a - threshold) / (a - b), 0.0, 1.0);
  return ta + fraction * (tb - ta);
}

// The start of a rest beginning at row i >= 1. A slip ends with a nonzero
// deceleration, so v is close to linear on the moving side: the zero of the
// line through the last two moving samples, if |v| falls along it, kept
// between the last moving and the first resting sample. This is what makes
// stop times at coarse sampling follow the true stop smoothly (a threshold
// crossing interpolated across the kink at the stop jumps by up to a whole
// sample spacing). Otherwise the interpolated threshold crossing.
double stop_time(const std::vector<double>& t, const std::vector<double>& v, std::size_t i,
                 double threshold) {
  double estimate = crossing(t[i - 1], std::fabs(v[i - 1]), t[i], std::fabs(v[i]), threshold);
  if (i >= 2 && (v[i - 2] > 0) == (v[i - 1] > 0) && std::fabs(v[i - 2]) > std::fabs(v[i - 1]))
    estimate = t[i - 1] + v[i - 1] * (t[i - 1] - t[i - 2]) / (v[i - 2] - v[i - 1]);
  return std::clamp(estimate, t[i - 1], t[i]);
}

}  // namespace

std::vector<StickInterval> detect_sticks(const std::vector<double>& t, const std::vector<double>& v,
                                         double threshold, double min_duration) {
  std::vector<StickInterval> sticks;
  const std::size_t n = std::min(t.size(), v.size());
  const auto at_rest = [&](std::size_t i) { return std::fabs(v[i]) < threshold; };
  for (std::size_t i = 0; i < n;) {
    if (!at_rest(i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && at_rest(j + 1)) ++j;
    StickInterval stick;
    stick.first_row = i;
    stick.last_row = j;
    stick.start = i == 0 ? t[0] : stop_time(t, v, i, threshold);
    stick.end = j + 1 == n
                    ? t[n - 1]
                    : crossing(t[j], std::fabs(v[j]), t[j + 1], std::fabs(v[j + 1]), threshold);
    if (stick.duration() >= min_duration) sticks.push_back(stick);
    i = j + 1;
  }
  return sticks;
}

namespace comparison {

std::vector<StickInterval> stick_phases(const std::vector<Phase>& phases, double t_last) {
  std::vector<StickInterval> sticks;
  for (const Phase& phase : phases) {
    if (phase.kind != PhaseKind::stick || !(phase.t_begin < t_last)) continue;
    StickInterval stick;
    stick.start = phase.t_begin;
    stick.end = std::fmin(phase.t_end, t_last);
    sticks.push_back(stick);
  }
  return sticks;
}

void match_sticks(ComparisonReport& r) {
  const double widen = r.stop_time_margin;
  std::size_t i = 0, j = 0, k = 0;
  while (i < r.exact_sticks.size() || j < r.candidate_sticks.size()) {
    if (j == r.candidate_sticks.size()) {
      r.missed.push_back(r.exact_sticks[i++]);
      continue;
    }
    if (i == r.exact_sticks.size()) {
      r.extra.push_back(r.candidate_sticks[j++]);
      continue;
    }
    const StickInterval& e = r.exact_sticks[i];
    const StickInterval& c = r.candidate_sticks[j];
    if (e.end + widen < c.start) {
      r.missed.push_back(r.exact_sticks[i++]);
    } else if (c.end + widen < e.start) {
      r.extra.push_back(r.candidate_sticks[j++]);
    } else {
      MatchedStick m;
      m.number = i + 1;
      m.exact = e;
      m.candidate = c;
      m.start_error = c.start - e.start;
      m.end_error = c.end - e.end;
      m.phase_start = m.phase_end = std::numeric_limits<double>::quiet_NaN();
      // The engine's stick phase with the largest overlap.
      while (k < r.exact_phases.size() && r.exact_phases[k].end < e.start) ++k;
      double best = 0;
      for (std::size_t p = k; p < r.exact_phases.size() && r.exact_phases[p].start <= e.end; ++p) {
        const double overlap =
            std::min(e.end, r.exact_phases[p].end) - std::max(e.start, r.exact_phases[p].start);
        if (overlap > best) {
          best = overlap;
          m.phase_start = r.exact_phases[p].start;
          m.phase_end = r.exact_phases[p].end;
        }
      }
      r.matched.push_back(m);
      ++i;
      ++j;
    }
  }
}

RowRange rows_inside(const ComparisonReport& r, const std::vector<double>& t, double begin,
                     double end) {
  const double lo = begin <= r.t_first ? begin : begin + r.stop_time_margin;
  const double hi = end >= r.t_last ? end : end - r.stop_time_margin;
  if (!(lo <= hi)) return {};
  const auto first = std::lower_bound(t.begin(), t.end(), lo);
  const auto last = std::upper_bound(first, t.end(), hi);
  return {static_cast<std::size_t>(first - t.begin()), static_cast<std::size_t>(last - t.begin())};
}

std::size_t measure_creep(ComparisonReport& r, const std::vector<double>& t,
                          const std::vector<double>& v) {
  const std::size_t none = r.exact_phases.size();
  std::size_t where = none;
  for (std::size_t p = 0; p < r.exact_phases.size(); ++p) {
    const RowRange rows = rows_inside(r, t, r.exact_phases[p].start, r.exact_phases[p].end);
    for (std::size_t n = rows.first; n < rows.last; ++n) {
      ++r.creep_samples;
      const double speed = std::fabs(v[n]);
      if (where == none || speed > r.creep_max_velocity) {
        r.creep_max_velocity = speed;
        r.creep_time = t[n];
        where = p;
      }
    }
  }
  return where;
}

}  // namespace comparison
}  // namespace frictionref
