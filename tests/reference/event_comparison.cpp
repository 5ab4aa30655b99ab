// Event-time comparison of the engine against the 50-digit reference.
#include "event_comparison.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace frictionref::accuracy {

namespace {

using boost::multiprecision::abs;
using boost::multiprecision::cos;

constexpr double kEpsDouble = std::numeric_limits<double>::epsilon();
// The engine's work type for double (closed_form.hpp: long double). Taken
// from the platform so the bound follows the type actually used.
const double kEpsWork = static_cast<double>(std::numeric_limits<long double>::epsilon());

int kind_code(PhaseKind kind) { return static_cast<int>(kind); }
int kind_code(ref::Kind kind) {
  switch (kind) {
    case ref::Kind::stick: return kind_code(PhaseKind::stick);
    case ref::Kind::slip_forward: return kind_code(PhaseKind::slip_forward);
    case ref::Kind::slip_backward: return kind_code(PhaseKind::slip_backward);
  }
  return -1;
}
const char* kind_name(int code) {
  return code == 0 ? "stick" : code == 1 ? "slip+" : code == 2 ? "slip-" : "?";
}

// A phase after normalization: the span of raw phases [first, last].
struct NPhase {
  int kind = 0;
  Real t_begin = 0, t_end = 0;
  std::size_t first = 0, last = 0;
};

struct Raw {
  int kind;
  Real t_begin, t_end;
  std::size_t first, last;  // the raw reference phases it spans
};

// Drops sub-resolution phases (shorter than 16 double ulps of max(1, |w t|)
// in w t, or empty once rounded to double), then merges neighbours of one
// kind. Returns how many raw phases disappeared as separate phases.
std::vector<NPhase> normalize(const std::vector<Raw>& raw, const Real& omega,
                              std::size_t& removed) {
  std::vector<NPhase> out;
  for (std::size_t j = 0; j < raw.size(); ++j) {
    const Raw& p = raw[j];
    const bool last = j + 1 == raw.size();
    const Real tau_end = omega * p.t_end;
    const Real scale = std::max(Real(1), Real(abs(tau_end)));
    const bool too_short = omega * (p.t_end - p.t_begin) < 16 * kEpsDouble * scale;
    const bool empty = static_cast<double>(p.t_begin) == static_cast<double>(p.t_end);
    if ((too_short || empty) && !(last && out.empty())) {
      ++removed;
      if (last && !out.empty()) out.back().t_end = p.t_end;  // runs to the horizon
      continue;
    }
    if (!out.empty() && out.back().kind == p.kind) {
      ++removed;
      out.back().t_end = p.t_end;
      out.back().last = p.last;
      continue;
    }
    NPhase n;
    n.kind = p.kind;
    n.t_begin = p.t_begin;
    n.t_end = p.t_end;
    n.first = p.first;
    n.last = p.last;
    out.push_back(n);
  }
  return out;
}

// A window of user time around a reference stop that long double cannot
// resolve (the dip of s v below zero is within the evaluation noise): inside
// it the engine may show the excursion (stop, stick or reverse slip, the slip
// again), a touch without one, or a slightly different stop.
struct Dip {
  Real t_from, t_to;
};

// Drops every phase that lies entirely inside a dip window (never the last
// one), on both sides alike; normalize() then merges the neighbours. Returns
// the number of phases dropped.
std::size_t drop_inside_dips(std::vector<Raw>& raw, const std::vector<Dip>& dips) {
  if (dips.empty()) return 0;
  std::vector<Raw> out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    bool inside = false;
    for (const Dip& d : dips)
      if (d.t_from <= raw[i].t_begin && raw[i].t_end <= d.t_to) inside = true;
    if (!inside || i + 1 == raw.size()) out.push_back(raw[i]);
  }
  const std::size_t dropped = raw.size() - out.size();
  raw.swap(out);
  return dropped;
}

// Per raw reference phase: the conditioning bound on the engine's error of
// its end time, in w t, and whether the end is resolvable (see header).
struct RawBound {
  Real delta = 0;  // in tau
  bool resolvable = true;
};

std::vector<RawBound> conditioning(const ref::Result& r) {
  using boost::multiprecision::sqrt;
  const ref::RealInput& in = r.model;
  const Real w = in.omega;
  const Real b = in.amplitude / (in.mass * w);
  const Real rr = in.friction / (in.mass * w);
  const bool monotone = !(in.amplitude > in.friction);
  const Real eps(kEpsWork);
  std::vector<RawBound> out(r.phases.size());
  Real delta_start = eps * abs(w * in.t0);  // w t0 rounded to long double
  for (std::size_t j = 0; j < r.phases.size(); ++j) {
    const ref::Phase& p = r.phases[j];
    if (p.kind == ref::Kind::stick) {
      // A closed-form breakaway alpha + 2 pi k: a few roundings of |tau|.
      out[j].delta = 4 * eps * std::max(Real(1), Real(abs(p.tau_end)));
      delta_start = out[j].delta;
      continue;
    }
    const Real& a = p.tau_begin;
    const Real& ts = p.tau_end;
    const Real slope = abs(p.accel_end) / w;         // |d(s v)/d tau| at the end
    const Real slope_start = abs(p.accel_begin) / w;  // at the start
    const Real curvature = b * abs(cos(ts));         // |d^2(s v)/d tau^2| at the end
    const Real S = abs(p.v_begin) + b * (abs(cos(a)) + abs(cos(ts))) + rr * abs(ts - a) +
                   slope * abs(ts) + slope_start * abs(a);
    const Real E = Real(kEvalError) * eps * S + slope_start * delta_start;
    const Real u = 2 * curvature * E / (slope * slope);  // (inf when slope = 0)
    out[j].resolvable = monotone || u < 1;
    if (!out[j].resolvable) {
      out[j].delta = Real(kDipWidth) * sqrt(E / curvature);
    } else if (monotone) {
      out[j].delta = Real(kMonotoneConditioning) * E / slope;
    } else {
      // Quadratic model: the root of f + e, |e| <= E, moves by at most
      // (|A| / q)(1 - sqrt(1 - u)) = g(u) E / |A|, g(u) = 2 (1 - sqrt(1 - u)) / u.
      const Real g = u > Real("1e-30") ? 2 * (1 - sqrt(1 - u)) / u : Real(1);
      out[j].delta = g * E / slope;
    }
    delta_start = out[j].delta;
  }
  return out;
}

std::string window(const std::vector<NPhase>& list, std::size_t at) {
  std::ostringstream text;
  const std::size_t from = at >= 2 ? at - 2 : 0;
  for (std::size_t i = from; i < list.size() && i < at + 3; ++i)
    text << "  [" << i << "] " << kind_name(list[i].kind) << " " << list[i].t_begin.str(20)
         << " .. " << list[i].t_end.str(20) << "\n";
  return text.str();
}

std::string format_double(double v, int digits = 17) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace

ref::Input to_reference_input(const Model& model) {
  ref::Input in;
  in.mass = model.mass;
  in.amplitude = model.amplitude;
  in.omega = model.omega;
  in.friction = model.friction;
  in.x0 = model.x0;
  in.v0 = model.v0;
  in.t0 = model.t0;
  return in;
}

std::string describe(const Model& model) { return to_reference_input(model).describe(); }

Real ulp_of(const Real& t) {
  const double d = std::fabs(static_cast<double>(t));
  if (d == 0 || !std::isfinite(d)) return Real(std::numeric_limits<double>::denorm_min());
  int e = 0;
  std::frexp(d, &e);  // d = f 2^e, 0.5 <= f < 1
  return Real(std::max(std::ldexp(1.0, e - 53), std::numeric_limits<double>::denorm_min()));
}

const char* to_string(EventKind kind) { return kind == EventKind::stop ? "stop" : "breakaway"; }

CaseResult compare(const Model& model, double t_end, const ref::Options& options) {
  const auto start = std::chrono::steady_clock::now();
  const Solution engine = solve(model, t_end);
  const auto middle = std::chrono::steady_clock::now();
  const ref::Result reference = ref::solve(to_reference_input(model), t_end, options);
  const auto end = std::chrono::steady_clock::now();
  CaseResult result = compare(model, t_end, engine, reference);
  result.engine_seconds = std::chrono::duration<double>(middle - start).count();
  result.reference_seconds = std::chrono::duration<double>(end - middle).count();
  return result;
}

CaseResult compare(const Model& model, double t_end, const Solution& engine,
                   const ref::Result& reference) {
  CaseResult result;
  result.name = describe(model) + " t_end=" + format_double(t_end);
  result.t_end = t_end;
  result.engine_phases = engine.phases.size();
  result.reference_phases = reference.phases.size();
  result.reference_evaluations = reference.velocity_evaluations;

  std::vector<Raw> raw_engine, raw_reference;
  for (std::size_t j = 0; j < engine.phases.size(); ++j) {
    const Phase& p = engine.phases[j];
    raw_engine.push_back({kind_code(p.kind), Real(p.t_begin), Real(p.t_end), j, j});
  }
  for (std::size_t j = 0; j < reference.phases.size(); ++j) {
    const ref::Phase& p = reference.phases[j];
    raw_reference.push_back({kind_code(p.kind), p.t_begin, p.t_end, j, j});
  }
  const Real omega(model.omega);
  const std::vector<RawBound> bounds = conditioning(reference);
  std::vector<Dip> dips;
  for (std::size_t j = 0; j + 1 < reference.phases.size(); ++j)
    if (!bounds[j].resolvable) {
      const ref::Phase& p = reference.phases[j];
      const Real half = bounds[j].delta / omega;
      dips.push_back({p.t_end - half, p.t_end + half});
    }
  result.unresolvable_dips = dips.size();
  result.normalized_reference = drop_inside_dips(raw_reference, dips);
  result.normalized_engine = drop_inside_dips(raw_engine, dips);
  const std::vector<NPhase> e = normalize(raw_engine, omega, result.normalized_engine);
  const std::vector<NPhase> r = normalize(raw_reference, omega, result.normalized_reference);

  const std::size_t n = std::min(e.size(), r.size());
  std::size_t first_difference = n;
  for (std::size_t i = 0; i < n; ++i)
    if (e[i].kind != r[i].kind) {
      first_difference = i;
      break;
    }
  if (engine.summary.termination != Termination::reached_end || engine.phases.empty() ||
      engine.phases.back().t_end != t_end) {
    result.sequence_matches = false;
    result.mismatch = "the engine did not reach t_end: termination " +
                      std::string(to_string(engine.summary.termination)) + " (" +
                      engine.summary.message + ")\n";
  }
  if (first_difference < n || e.size() != r.size()) {
    result.sequence_matches = false;
    std::ostringstream text;
    text << "phase sequences differ at normalized phase " << first_difference << " (engine "
         << e.size() << " phases, reference " << r.size() << ")\n engine:\n"
         << window(e, first_difference) << " reference:\n"
         << window(r, first_difference);
    result.mismatch += text.str();
  }

  // Events: the boundaries between phases i and i + 1 where both sides agree
  // on both kinds (i + 1 < first_difference); never the horizon.
  for (std::size_t i = 0; i + 1 < first_difference; ++i) {
    Event ev;
    ev.index = i;
    ev.before = static_cast<PhaseKind>(r[i].kind);
    ev.after = static_cast<PhaseKind>(r[i + 1].kind);
    ev.kind = r[i].kind == kind_code(PhaseKind::stick) ? EventKind::breakaway : EventKind::stop;
    ev.t_engine = static_cast<double>(e[i].t_end);
    ev.t_reference = r[i].t_end;
    const Real ulp = ulp_of(ev.t_reference);
    ev.error_ulps = static_cast<double>((Real(ev.t_engine) - ev.t_reference) / ulp);
    const ref::Phase& seg = reference.phases[r[i].last];
    const RawBound& bound = bounds[r[i].last];
    if (ev.kind == EventKind::stop) {
      if (model.amplitude > 0)
        ev.accel = static_cast<double>(seg.accel_end * Real(model.mass) / Real(model.amplitude));
      ev.near_grazing = model.amplitude > 0 && std::fabs(ev.accel) < kGrazingAcceleration;
      const Real allowed = Real(kUlpLimit) + bound.delta / (omega * ulp);
      ev.bound_ulps = static_cast<double>(allowed);
      ev.resolvable = bound.resolvable;
    }
    result.events.push_back(ev);
  }
  return result;
}

bool regular_stop(const Event& e) { return e.kind == EventKind::stop && !e.near_grazing; }
bool near_grazing_stop(const Event& e) { return e.kind == EventKind::stop && e.near_grazing; }
bool breakaway(const Event& e) { return e.kind == EventKind::breakaway; }
bool any_event(const Event&) { return true; }

void Stats::add(const CaseResult& result, bool (*select)(const Event&)) {
  for (const Event& e : result.events) {
    if (!select(e)) continue;
    ++count_;
    const double err = std::fabs(e.error_ulps);
    if (err > 0.5) ++above_half_;
    sum_squares_ += err * err;
    if (err > max_ || worst_.empty()) {
      max_ = std::max(max_, err);
      worst_ = result.name + "\n    " + event_line(e);
    }
    const double ratio = err / e.bound_ulps;
    if (ratio > max_ratio_ || worst_ratio_.empty()) {
      max_ratio_ = std::max(max_ratio_, ratio);
      worst_ratio_ = result.name + "\n    " + event_line(e);
    }
  }
}

double Stats::rms_ulps() const { return count_ ? std::sqrt(sum_squares_ / double(count_)) : 0; }

std::string Stats::report(const std::string& title) const {
  std::ostringstream text;
  text << title << ": " << count_ << " events, max |error| = " << format_double(max_, 4)
       << " ulps, RMS = " << format_double(rms_ulps(), 4) << " ulps, " << above_half_
       << " above 0.5 ulp (not correctly rounded)";
  if (count_) {
    text << "\n  worst: " << worst_;
    if (worst_ratio_ != worst_)
      text << "\n  largest error / bound = " << format_double(max_ratio_, 4) << ": "
           << worst_ratio_;
    else
      text << "\n  error / bound there = " << format_double(max_ratio_, 4);
  }
  return text.str();
}

std::string event_line(const Event& e) {
  std::ostringstream text;
  text << "event " << e.index << " (" << to_string(e.kind) << ", " << to_string(e.before)
       << " -> " << to_string(e.after) << "): engine t = " << format_double(e.t_engine)
       << ", reference t = " << e.t_reference.str(25)
       << ", error = " << format_double(e.error_ulps, 4) << " ulps";
  if (e.kind == EventKind::stop) {
    text << ", a = " << format_double(e.accel, 4) << " B/m, bound = "
         << format_double(e.bound_ulps, 4) << " ulps";
    if (!e.resolvable) text << " (unresolvable in long double)";
  }
  return text.str();
}

}  // namespace frictionref::accuracy
