#include "diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report_format.hpp"
#include "sticks.hpp"

namespace frictionref::comparison {
namespace {

// A fit explains the error when it leaves at most this fraction of its RMS
// (91% of the squared error) and a candidate within the velocity tolerances.
constexpr double kExplainedRms = 0.3;
// Inside an exact stick, sign flips of v beyond this count are chattering;
// fewer, with |v| above the stick threshold, are creep while |v| stays under
// kCreepSpeed velocity scales (B/(m w)), a slide through the stick above it.
constexpr std::size_t kChatteringFlips = 3;
constexpr double kCreepSpeed = 0.1;
// An exact slip the candidate sits through must reach this many stick
// thresholds, so that sitting still is visibly wrong.
constexpr double kVisibleSlip = 10;

// Trapezoidal weights: sum w_i f_i is the integral of f over the record.
std::vector<double> trapezoid_weights(const std::vector<double>& t) {
  std::vector<double> w(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double h = t[i] - t[i - 1];
    w[i - 1] += h / 2;
    w[i] += h / 2;
  }
  return w;
}

struct Residual {
  double rms = 0;  // time-weighted
  double max = 0;
};

class Samples {
 public:
  Samples(const ComparisonReport& r, const TimeHistory& history, const ExactMotion& exact)
      : r_(r),
        t_(history.t),
        v_(history.v),
        exact_(exact),
        w_(trapezoid_weights(history.t)),
        total_(history.t.back() - history.t.front()) {}

  // The candidate's velocity less `model(i)`.
  template <class Model>
  Residual residual(Model model) const {
    Residual out;
    double sum = 0;
    for (std::size_t i = 0; i < t_.size(); ++i) {
      const double e = v_[i] - model(i);
      sum += w_[i] * e * e;
      out.max = std::max(out.max, std::fabs(e));
    }
    out.rms = std::sqrt(sum / total_);
    return out;
  }

  // Whether a fit that leaves `after` explains an error that was `before`.
  bool explains(const Residual& after, const Residual& before) const {
    const double scale = r_.scales.velocity;
    return after.rms <= kExplainedRms * before.rms &&
           after.rms <= r_.options.velocity_rms_tolerance * scale &&
           after.max <= r_.options.velocity_max_tolerance * scale;
  }

  // sum w_i f(i)
  template <class F>
  double integral(F f) const {
    double sum = 0;
    for (std::size_t i = 0; i < t_.size(); ++i) sum += w_[i] * f(i);
    return sum;
  }

  const std::vector<double>& t() const { return t_; }
  const std::vector<double>& v() const { return v_; }
  const ExactMotion& exact() const { return exact_; }
  double total() const { return total_; }

 private:
  const ComparisonReport& r_;
  const std::vector<double>& t_;
  const std::vector<double>& v_;
  const ExactMotion& exact_;
  std::vector<double> w_;
  double total_;
};

std::string rms_change(const ComparisonReport& r, const Residual& after, const Residual& before) {
  return "RMS velocity error " + g(after.rms / r.scales.velocity) + " " + r.scales.velocity_name +
         " (was " + g(before.rms / r.scales.velocity) + "), largest " +
         g(after.max / r.scales.velocity);
}

// v(t) = v_exact(t - shift): the linear estimate from the exact acceleration
// at the samples, then Gauss-Newton on the closed forms (only when the linear
// estimate already explains half the error: it costs a phase evaluation per
// sample and iteration). Samples whose shifted time leaves the exact motion's
// span are left out of the fit.
std::optional<Diagnosis> time_shift(const ComparisonReport& r, const Samples& s,
                                    const Residual& before) {
  const std::vector<State>& at = s.exact().states;
  const double den = s.integral([&](std::size_t i) { return at[i].a * at[i].a; });
  if (!(den > 0)) return std::nullopt;
  double shift = -s.integral([&](std::size_t i) { return at[i].a * (s.v()[i] - at[i].v); }) / den;
  if (!std::isfinite(shift) || shift == 0) return std::nullopt;
  const Residual linear = s.residual([&](std::size_t i) { return at[i].v - shift * at[i].a; });
  if (!(linear.rms * linear.rms <= 0.5 * before.rms * before.rms)) return std::nullopt;
  const double first = s.exact().phases.front().t_begin, last = s.exact().phases.back().t_end;
  std::vector<State> shifted(at.size());
  std::vector<char> inside(at.size());
  const auto evaluate_shifted = [&] {
    for (std::size_t i = 0; i < at.size(); ++i) {
      const double t = s.t()[i] - shift;
      inside[i] = t >= first && t <= last;
      shifted[i] = s.exact().at(t);
    }
  };
  for (int iteration = 0; iteration < 12; ++iteration) {
    evaluate_shifted();
    const double d =
        s.integral([&](std::size_t i) { return inside[i] ? shifted[i].a * shifted[i].a : 0.0; });
    if (!(d > 0)) break;
    double step = -s.integral([&](std::size_t i) {
      return inside[i] ? shifted[i].a * (s.v()[i] - shifted[i].v) : 0.0;
    }) / d;
    step = std::clamp(step, -0.25 * r.scales.period, 0.25 * r.scales.period);
    if (!std::isfinite(step)) break;
    shift += step;
    if (std::fabs(step) <= 1e-12 * r.scales.period + 1e-15 * std::fabs(shift)) break;
  }
  evaluate_shifted();
  const Residual after =
      s.residual([&](std::size_t i) { return inside[i] ? shifted[i].v : s.v()[i]; });
  if (!s.explains(after, before)) return std::nullopt;
  Diagnosis d;
  d.defect = Defect::time_shift;
  d.value = shift;
  d.evidence = "the candidate runs " + std::string(shift > 0 ? "late" : "early") + " by " +
               g(std::fabs(shift)) + " (" + g(std::fabs(shift) / r.scales.period) + " " +
               r.scales.period_unit + "): v(t) = v_exact(t " + (shift > 0 ? "- " : "+ ") +
               g(std::fabs(shift)) + ") leaves " + rms_change(r, after, before);
  if (!r.matched.empty()) {
    double sum = 0, lo = r.matched.front().start_error, hi = lo;
    for (const MatchedStick& m : r.matched)
      for (const double e : {m.start_error, m.end_error}) {
        sum += e;
        lo = std::min(lo, e);
        hi = std::max(hi, e);
      }
    d.evidence += "; the starts and ends of the " + std::to_string(r.matched.size()) +
                  " matched sticks move by " +
                  signed_g(sum / (2.0 * static_cast<double>(r.matched.size()))) +
                  " on average (from " + signed_g(lo) + " to " + signed_g(hi) + ")";
  }
  return d;
}

// v = s v_exact.
std::optional<Diagnosis> scale(const ComparisonReport& r, const Samples& s,
                               const Residual& before) {
  const std::vector<State>& at = s.exact().states;
  const double den = s.integral([&](std::size_t i) { return at[i].v * at[i].v; });
  if (!(den > 0)) return std::nullopt;
  const double factor = s.integral([&](std::size_t i) { return at[i].v * s.v()[i]; }) / den;
  // A factor near 0 "explains" a candidate at rest throughout: that is no
  // scale error but motion missed, for the phase scan to name.
  if (!std::isfinite(factor) || factor == 1 || !(std::fabs(factor) >= 1e-3)) return std::nullopt;
  const Residual after = s.residual([&](std::size_t i) { return factor * at[i].v; });
  if (!s.explains(after, before)) return std::nullopt;
  Diagnosis d;
  d.defect = Defect::scale;
  d.value = factor;
  d.evidence = "v = " + g(factor) + " v_exact: removing the factor leaves " +
               rms_change(r, after, before) +
               " (units, or the amplitude, mass or frequency of the model)";
  return d;
}

// v = v_exact + bias, with samples in exact slips (a record at rest
// throughout cannot tell a bias from creep).
std::optional<Diagnosis> velocity_bias(const ComparisonReport& r, const Samples& s,
                                       const Residual& before) {
  const std::vector<State>& at = s.exact().states;
  const double sliding =
      s.integral([&](std::size_t i) { return at[i].phase == PhaseKind::stick ? 0.0 : 1.0; });
  if (!(sliding >= 0.1 * s.total())) return std::nullopt;
  const double bias = s.integral([&](std::size_t i) { return s.v()[i] - at[i].v; }) / s.total();
  if (!std::isfinite(bias) || bias == 0) return std::nullopt;
  const Residual after = s.residual([&](std::size_t i) { return at[i].v + bias; });
  if (!s.explains(after, before)) return std::nullopt;
  Diagnosis d;
  d.defect = Defect::drift;
  d.value = bias;
  d.evidence = "a constant velocity error of " + signed_g(bias / r.scales.velocity) + " " +
               r.scales.velocity_name + " (" + signed_g(bias) +
               ") over the whole record, so the displacement "
               "error grows by " +
               g(std::fabs(bias) * s.total()) + " over it; removing it leaves " +
               rms_change(r, after, before);
  return d;
}

// What the candidate does inside the exact phases: the earliest anomaly.
struct Anomaly {
  Defect defect = Defect::unclassified;
  double start = 0, end = 0;  // the exact phase
  double speed = 0;           // the candidate's largest |v| in it (sticks) or the exact's (slips)
  double time = 0;            // where
  std::size_t flips = 0;      // sign changes of v (sticks)
};

std::optional<Diagnosis> phase_anomalies(const ComparisonReport& r, const Samples& s) {
  const std::vector<double>& t = s.t();
  const std::vector<double>& v = s.v();
  std::vector<Anomaly> found;
  std::size_t sticks_seen = 0, slips_seen = 0;
  for (const Phase& p : s.exact().phases) {
    // Read like the creep check: less the stop-time margin at event ends.
    const RowRange rows = rows_inside(r, t, p.t_begin, p.t_end);
    if (rows.first >= rows.last) continue;
    const std::size_t a = rows.first, b = rows.last;
    Anomaly anomaly;
    anomaly.start = p.t_begin;
    anomaly.end = p.t_end;
    if (p.kind == PhaseKind::stick) {
      ++sticks_seen;
      bool moving = false;
      for (std::size_t i = a; i < b; ++i) {
        const double speed = std::fabs(v[i]);
        moving = moving || speed >= r.stick_velocity;
        if (speed > anomaly.speed) {
          anomaly.speed = speed;
          anomaly.time = t[i];
        }
        const double floor = 0.1 * r.stick_velocity;
        if (i > a && std::fabs(v[i - 1]) >= floor && speed >= floor && (v[i] > 0) != (v[i - 1] > 0))
          ++anomaly.flips;
      }
      if (!moving) continue;
      anomaly.defect = anomaly.flips >= kChatteringFlips                 ? Defect::chattering
                       : anomaly.speed < kCreepSpeed * r.scales.velocity ? Defect::creep
                                                                         : Defect::missed_stop;
    } else {
      ++slips_seen;
      bool at_rest = true;
      for (std::size_t i = a; i < b; ++i) {
        at_rest = at_rest && std::fabs(v[i]) < r.stick_velocity;
        const double speed = std::fabs(s.exact().states[i].v);
        if (speed > anomaly.speed) {
          anomaly.speed = speed;
          anomaly.time = t[i];
        }
      }
      if (!at_rest || anomaly.speed < kVisibleSlip * r.stick_velocity) continue;
      anomaly.defect = Defect::missed_breakaway;
    }
    found.push_back(anomaly);
  }
  if (found.empty()) return std::nullopt;
  const Anomaly& e = found.front();  // the earliest: what follows may be its consequence
  Diagnosis d;
  d.defect = e.defect;
  d.value = static_cast<double>(std::count_if(
      found.begin(), found.end(), [&](const Anomaly& x) { return x.defect == e.defect; }));
  const std::string count = g(d.value);
  const std::string where = interval(e.start, e.end);
  const std::string speed = g(e.speed / r.scales.velocity) + " " + r.scales.velocity_name;
  switch (e.defect) {
    case Defect::chattering:
      d.evidence = "v changes sign " + std::to_string(e.flips) + " times inside the exact stick " +
                   where + " (|v| up to " + speed + "), and chatters in " + count + " of " +
                   std::to_string(sticks_seen) +
                   " exact sticks with samples: the friction force flips with the sign of v "
                   "instead of holding v = 0";
      break;
    case Defect::creep:
      d.evidence = "the candidate moves at up to " + speed + " (t = " + g(e.time) +
                   ") inside the exact stick " + where +
                   ", where the exact mass is at rest, "
                   "and creeps in " +
                   count + " of " + std::to_string(sticks_seen) +
                   " exact sticks with samples: friction that never holds v = 0 "
                   "(regularised, or a stick tolerance too loose)";
      break;
    case Defect::missed_stop:
      d.evidence = "the exact mass sticks over " + where + "; the candidate slides through it " +
                   "(|v| up to " + speed + " at t = " + g(e.time) + "), in " + count + " of " +
                   std::to_string(sticks_seen) + " exact sticks with samples";
      break;
    default:
      d.evidence = "the exact mass breaks away at t = " + g(e.start) + " and slides until " +
                   g(e.end) + " (|v| up to " + speed +
                   "); the candidate stays at rest throughout, "
                   "in " +
                   count + " of " + std::to_string(slips_seen) +
                   " exact slips with samples (a breakaway test that looks too rarely, or "
                   "static friction too high)";
      break;
  }
  const std::size_t others = found.size() - static_cast<std::size_t>(d.value);
  if (others > 0)
    d.evidence += "; " + std::to_string(others) + " later phase" + (others > 1 ? "s" : "") +
                  " of another kind differ too";
  return d;
}

// x = x_exact + c, or + c + rate (t - t_first).
std::optional<Diagnosis> displacement_line(const ComparisonReport& r, const TimeHistory& history,
                                           const Samples& s) {
  if (!history.x) return std::nullopt;
  const auto failed = std::find_if(r.checks.begin(), r.checks.end(), [](const Check& c) {
    return c.kind == CheckKind::displacement_max && !c.passed;
  });
  if (failed == r.checks.end()) return std::nullopt;
  const std::vector<double>& x = *history.x;
  const std::vector<State>& at = s.exact().states;
  const auto error = [&](std::size_t i) { return x[i] - at[i].x; };
  const double tolerance = r.options.displacement_max_tolerance * r.scales.displacement;
  const double mean = s.integral(error) / s.total();
  const double t_mean = s.integral([&](std::size_t i) { return s.t()[i]; }) / s.total();
  const double var = s.integral([&](std::size_t i) {
    const double dt = s.t()[i] - t_mean;
    return dt * dt;
  });
  const double rate =
      var > 0 ? s.integral([&](std::size_t i) { return (s.t()[i] - t_mean) * error(i); }) / var : 0;
  double offset_max = 0, line_max = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    offset_max = std::max(offset_max, std::fabs(error(i) - mean));
    line_max = std::max(line_max, std::fabs(error(i) - mean - rate * (s.t()[i] - t_mean)));
  }
  Diagnosis d;
  if (offset_max <= tolerance && offset_max <= kExplainedRms * r.displacement_max_error) {
    d.defect = Defect::offset;
    d.value = mean;
    d.evidence = "x = x_exact " + std::string(mean < 0 ? "- " : "+ ") + g(std::fabs(mean)) + " (" +
                 signed_g(mean / r.scales.displacement) + " " + r.scales.displacement_name +
                 ") throughout, within " + g(offset_max) +
                 ": the velocity is right; the initial position or the reference differs";
    return d;
  }
  if (line_max <= tolerance && line_max <= kExplainedRms * r.displacement_max_error) {
    d.defect = Defect::drift;
    d.value = rate;
    d.evidence = "x - x_exact grows at " + signed_g(rate) + " per unit time (" +
                 signed_g(rate * s.total()) + " over the record), a straight line within " +
                 g(line_max) + ": a small velocity bias, integrated";
    return d;
  }
  return std::nullopt;
}

}  // namespace

Diagnosis diagnose(const ComparisonReport& r, const TimeHistory& history,
                   const ExactMotion& exact) {
  Diagnosis d;
  if (r.verdict == Verdict::pass) {
    d.evidence = "every check passed and the samples resolve the exact motion";
    return d;
  }
  if (r.verdict == Verdict::inconclusive) {
    d.defect = Defect::unresolved;
    d.evidence = "every check passed, but " + std::to_string(r.unresolved_phases) +
                 " exact phase(s) and " + std::to_string(r.unresolved_events) +
                 " event(s) fall between samples (" + r.resolution_advice() + ")";
    return d;
  }
  const Samples samples(r, history, exact);
  const Residual before = samples.residual([&](std::size_t i) { return exact.states[i].v; });
  if (before.rms > 0 && std::isfinite(before.rms)) {
    if (auto found = time_shift(r, samples, before)) return *found;
    if (auto found = scale(r, samples, before)) return *found;
    if (auto found = velocity_bias(r, samples, before)) return *found;
  }
  if (auto found = phase_anomalies(r, samples)) return *found;
  if (auto found = displacement_line(r, history, samples)) return *found;
  d.defect = Defect::unclassified;
  const auto failed =
      std::find_if(r.checks.begin(), r.checks.end(), [](const Check& c) { return !c.passed; });
  d.evidence = "no single class explains the differences; the first failed check is " +
               std::string(failed->name()) + " (" + failed->message + ")";
  return d;
}

}  // namespace frictionref::comparison
