// Event times of the exact engine on the GENERAL model (static friction,
// spring, damper, force offset, several harmonics) against the independent
// 50-digit Taylor-series reference (general_reference_solver.hpp), in ulps of
// t (docs/accuracy.md, "The general model").
//
// Acceptance (the issue): every well-conditioned event within 4 ulps of t;
// near-grazing events within 4 ulps plus the conditioning bound below; the
// phase-kind sequences agree once both are brought to the engine's output
// resolution. Nothing expected here is computed by the engine.
//
// Events are the phase boundaries strictly inside (t0, t_end):
//   stop       a slip reaches v = 0 (then a stick, or a reversal). Well
//              conditioned if the reference |dv/dt| just before it is at least
//              1e-3 Fs / m, Fs = |F0| + B + sum |B_i| + Rs + k max|x| (the
//              forces whose rounding the engine's v carries);
//   breakaway  a stick ends (|N| reaches Rs). Well conditioned if
//              |dN/dt| = |F'(t)| >= 1e-3 (B w + sum |B_i| w_i), its largest value.
// Events below those thresholds are near-grazing; an event whose bound carries
// more than 1 ulp from near-grazing events before it (a late breakaway shifts
// the slip after it) is "after a near-grazing one". Both are held to the bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "general_reference_solver.hpp"

namespace {

namespace gref = frictionref_general_reference;
using boost::multiprecision::abs;
using boost::multiprecision::sqrt;
using frictionref::Model;
using frictionref::PhaseKind;
using gref::Real;

constexpr double kUlpLimit = 4;        // well-conditioned events: |error| <= 4 ulps of t
constexpr double kConditioned = 1e-3;  // the well-conditioned threshold (header comment)
// The near-grazing bound (docs/accuracy.md): the engine evaluates v (and N) in
// long double with a certified rounding bound e0 of 64 ulps of the sum of the
// magnitudes it adds (slip_law.hpp, net_force.hpp), and counts a value within
// 2 e0 of zero as zero (a touch, or a dip's minimum, is then the event). So
// its event is a root of f + e with |e| <= 3 e0: kEvalError = 3 x 64 ulps.
// Plus the error of the start carried by the slope there, and the curvature's
// worst case.
constexpr double kEvalError = 192;
constexpr double kDipWidth = 4;
const double kEpsWork = static_cast<double>(std::numeric_limits<long double>::epsilon());
constexpr double kEpsDouble = std::numeric_limits<double>::epsilon();

gref::Input to_reference_input(const Model& m) {
  gref::Input in;
  in.mass = m.mass;
  in.amplitude = m.amplitude;
  in.omega = m.omega;
  in.friction = m.friction;
  in.static_friction = m.static_friction;
  in.stiffness = m.stiffness;
  in.damping = m.damping;
  in.force_offset = m.force_offset;
  for (const auto& h : m.harmonics) in.harmonics.push_back({h.amplitude, h.omega, h.phase});
  if (m.ground_motion) {
    in.record_t = m.ground_motion->t;
    in.record_a = m.ground_motion->a;
  }
  in.x0 = m.x0;
  in.v0 = m.v0;
  in.t0 = m.t0;
  return in;
}

std::string describe(const Model& m) { return to_reference_input(m).describe(); }

std::string format(double v, int digits = 17) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// Spacing of doubles at |t| (the smallest subnormal at 0).
Real ulp_of(const Real& t) {
  const double d = std::fabs(static_cast<double>(t));
  if (d == 0) return Real(std::numeric_limits<double>::denorm_min());
  int e = 0;
  std::frexp(d, &e);
  return Real(std::max(std::ldexp(1.0, e - 53), std::numeric_limits<double>::denorm_min()));
}

int kind_code(PhaseKind k) { return static_cast<int>(k); }
int kind_code(gref::Kind k) {
  return k == gref::Kind::stick ? 0 : k == gref::Kind::slip_forward ? 1 : 2;
}
const char* kind_name(int code) {
  return code == 0 ? "stick" : code == 1 ? "slip+" : code == 2 ? "slip-" : "?";
}

// A phase before normalization; after it, the span of raw phases it covers.
struct Span {
  int kind = 0;
  Real t_begin = 0, t_end = 0;
  std::size_t last = 0;  // the raw phase whose end is this span's end
};

// Per raw reference phase: how well its end time is conditioned.
struct Conditioning {
  Real delta = 0;                // bound of the engine's error in t from rounding (user time)
  bool well_conditioned = true;  // own slope above the threshold, nothing inherited
  bool near_grazing = false;     // own slope below the threshold
  bool resolvable = true;        // false: the noise can make the event vanish (a window)
  double ratio = 0;              // |slope| / its scale (the conditioning, for reports)
  double inherited_ulps = 0;     // the part of delta carried from earlier events, in ulps
};

// The quadratic-model bound: a root of f with slope A and curvature q moved
// by |e| <= E lies within g(u) E / A, g(u) = 2 (1 - sqrt(1 - u)) / u, u = 2 q E / A^2,
// if u < 1; else the dip may vanish and the roots lie within 4 sqrt(E / q).
Real root_bound(const Real& E, const Real& A, const Real& q, bool& resolvable) {
  const Real u = A > 0 ? Real(2 * q * E / (A * A)) : Real(2);
  resolvable = u < 1;
  if (!resolvable) return Real(kDipWidth) * sqrt(E / (q > 0 ? q : Real(1e-300)));
  const Real g = u > Real("1e-30") ? Real(2 * (1 - sqrt(1 - u)) / u) : Real(1);
  return g * E / A;
}

// The bound is carried along the run (docs/accuracy.md). The error of a
// slip's start time shifts the trajectory: its velocity by the slope there
// times that error. The error of the position is another perturbation of the
// start. Both evolve by the homogeneous equation m d'' + c d' + k d = 0, whose
// energy m d'^2 / 2 + k d^2 / 2 never grows: a velocity error P = A_a Delta_a
// + wn delta_x (wn^2 = k/m) bounds |d'| and P / wn bounds |d| over the slip. The
// position error then moves N = F - k x by k times it in the stick that
// follows. A stop's own time error does not move the position (v = 0 there).
// What an event hands on: the error bound of its time and of the position.
struct Carried {
  Real start = 0, x = 0;
};

std::vector<Conditioning> conditioning(const gref::Result& r) {
  const gref::RealInput& in = r.model;
  const Real eps(kEpsWork);
  Real x_max = abs(in.x0), record_peak = 0;
  for (const gref::Phase& p : r.phases) x_max = std::max(x_max, Real(abs(p.x_end)));
  Real amplitudes = 0, rate_max = 0;
  for (const gref::RealTerm& term : in.terms) {
    amplitudes += abs(term.amplitude);
    rate_max += abs(term.amplitude) * term.omega;
  }
  // A record: its force m max|a_g| counts as an amplitude, m max|a_g'| as a
  // rate (its rounding in the engine: the value on a segment at the rounded
  // time, m |a_g'| eps |t|, like a harmonic's argument).
  Real record_slope = 0;
  for (std::size_t i = 0; i < in.record_a.size(); ++i) {
    const Real a = in.mass * abs(in.record_a[i]);
    if (a > record_peak) record_peak = a;
    if (i + 1 < in.record_a.size()) {
      const Real slope = in.mass * abs(in.record_a[i + 1] - in.record_a[i]) /
                         (in.record_t[i + 1] - in.record_t[i]);
      if (slope > record_slope) record_slope = slope;
    }
  }
  amplitudes += record_peak;
  rate_max += record_slope;
  const Real force_scale =
      abs(in.force_offset) + amplitudes + in.static_friction + in.stiffness * x_max;
  const Real wn = sqrt(in.stiffness / in.mass);
  std::vector<Conditioning> out(r.phases.size());
  // The whole bound, and the part of it that comes from near-grazing events
  // (what makes a later event "after a near-grazing one"); both propagate
  // linearly by the same rules.
  Carried all{eps * abs(in.t0), eps * abs(in.x0)}, from_grazing;
  for (std::size_t j = 0; j < r.phases.size(); ++j) {
    const gref::Phase& p = r.phases[j];
    Conditioning& c = out[j];
    // The rounding of each harmonic's argument w_j t moves F by |B_j| eps |w_j t|.
    Real phase_rounding = 0;
    for (const gref::RealTerm& term : in.terms)
      phase_rounding += abs(term.amplitude) * eps * term.omega * abs(p.t_end);
    phase_rounding += record_slope * eps * abs(p.t_end);
    Real own = 0, A = 0, q = 0, span = 0, A_a = 0;
    if (p.kind == gref::Kind::stick) {
      // N = F(t) - k x_r reaches +-Rs with slope F'(t).
      A = abs(p.net_force_rate_end);
      q = abs(p.net_force_curvature_end);
      own = Real(kEvalError) * eps *
                (abs(in.force_offset) + amplitudes + in.stiffness * abs(p.x_begin) +
                 in.static_friction) +
            phase_rounding + A * eps * abs(p.t_end);
      c.ratio = rate_max > 0 ? static_cast<double>(A / rate_max) : 1.0;
      c.near_grazing = A < Real(kConditioned) * rate_max;
    } else {
      // s v from the slip's start: the magnitudes it sums (velocities, and
      // the forces integrated over the slip) and the argument roundings.
      A = abs(p.slope_end);
      q = abs(p.curvature_end);
      A_a = abs(p.slope_begin);
      span = p.t_end - p.t_begin;
      const Real forces = abs(in.force_offset) + in.friction + amplitudes + in.stiffness * x_max +
                          in.damping * p.speed_max;
      const Real S = abs(p.v_begin) + p.speed_max + forces * span / in.mass + A * abs(p.t_end) +
                     A_a * abs(p.t_begin);
      own = Real(kEvalError) * eps * S + phase_rounding * span / in.mass;
      c.ratio = static_cast<double>(A * in.mass / force_scale);
      c.near_grazing = A * in.mass < Real(kConditioned) * force_scale;
    }
    // The error carried into this event's function (N for a stick, s v for a
    // slip, then P the perturbation's velocity bound), and the position's
    // error handed on.
    auto inherited = [&](Carried& carried) {
      if (p.kind == gref::Kind::stick) return Real(in.stiffness * carried.x);
      const Real P = A_a * carried.start + wn * carried.x;
      if (in.stiffness > 0) carried.x = std::min(Real(P / wn), Real(carried.x + P * span));
      return P;
    };
    const Real inherited_all = inherited(all);
    const Real inherited_grazing = inherited(from_grazing);
    if (p.kind != gref::Kind::stick) all.x += Real(kEvalError) * eps * x_max;
    const Real E = own + inherited_all;
    c.delta = root_bound(E, A, q, c.resolvable);
    all.start = c.delta;
    from_grazing.start = c.near_grazing ? c.delta : Real(c.delta * inherited_grazing / E);
    if (c.near_grazing && p.kind != gref::Kind::stick) from_grazing.x = all.x;
    c.inherited_ulps = static_cast<double>(from_grazing.start / ulp_of(p.t_end));
    c.well_conditioned = !c.near_grazing && c.inherited_ulps <= 1;
  }
  return out;
}

// Drops sub-resolution phases (shorter than 16 double ulps of max(1, |w t|) in
// w t, or empty in double: the engine merges them, phase.hpp) and phases lying
// inside the window of an unresolvable event, then merges neighbours of one kind.
std::vector<Span> normalize(const std::vector<Span>& raw, double omega,
                            const std::vector<std::pair<Real, Real>>& windows,
                            std::size_t& removed) {
  std::vector<Span> out;
  for (std::size_t j = 0; j < raw.size(); ++j) {
    const Span& p = raw[j];
    const bool last = j + 1 == raw.size();
    const Real scale = std::max(Real(1), Real(abs(Real(omega) * p.t_end)));
    const bool too_short = Real(omega) * (p.t_end - p.t_begin) < 16 * kEpsDouble * scale;
    const bool empty = static_cast<double>(p.t_begin) == static_cast<double>(p.t_end);
    bool inside = false;
    for (const auto& w : windows)
      if (w.first <= p.t_begin && p.t_end <= w.second) inside = true;
    if ((too_short || empty || inside) && !(last && out.empty())) {
      ++removed;
      if (last && !out.empty()) out.back().t_end = p.t_end;
      continue;
    }
    if (!out.empty() && out.back().kind == p.kind) {
      ++removed;
      out.back().t_end = p.t_end;
      out.back().last = p.last;
      continue;
    }
    out.push_back(p);
  }
  return out;
}

enum class EventKind { stop_to_stick, reversal, breakaway };
const char* to_string(EventKind k) {
  return k == EventKind::stop_to_stick ? "stop"
         : k == EventKind::reversal    ? "reversal"
                                       : "breakaway";
}

struct Event {
  std::size_t index = 0;
  EventKind kind = EventKind::breakaway;
  double t_engine = 0;
  Real t_reference = 0;
  double error_ulps = 0;
  double bound_ulps = kUlpLimit;  // near-grazing: 4 + the conditioning bound
  double ratio = 0;               // slope / its scale
  bool well_conditioned = true;
  bool near_grazing = false;  // else, if not well conditioned: inherits an earlier event's error
  bool resolvable = true;
};

struct CaseResult {
  std::string name;
  std::vector<Event> events;
  bool sequence_matches = true;
  std::string mismatch;
  std::size_t removed = 0, windows = 0;
  double engine_seconds = 0, reference_seconds = 0;
};

std::string window_text(const std::vector<Span>& list, std::size_t at) {
  std::ostringstream text;
  for (std::size_t i = at >= 2 ? at - 2 : 0; i < list.size() && i < at + 3; ++i)
    text << "  [" << i << "] " << kind_name(list[i].kind) << " " << list[i].t_begin.str(20)
         << " .. " << list[i].t_end.str(20) << "\n";
  return text.str();
}

CaseResult compare(const Model& model, double t_end, const gref::Options& options = {}) {
  CaseResult result;
  result.name = describe(model) + " t_end=" + format(t_end);
  const auto start = std::chrono::steady_clock::now();
  const frictionref::Solution engine = frictionref::solve(model, t_end);
  const auto middle = std::chrono::steady_clock::now();
  const gref::Result reference = gref::solve(to_reference_input(model), t_end, options);
  const auto end = std::chrono::steady_clock::now();
  result.engine_seconds = std::chrono::duration<double>(middle - start).count();
  result.reference_seconds = std::chrono::duration<double>(end - middle).count();

  const std::vector<Conditioning> cond = conditioning(reference);
  std::vector<std::pair<Real, Real>> windows;
  for (std::size_t j = 0; j + 1 < reference.phases.size(); ++j)
    if (!cond[j].resolvable)
      windows.push_back(
          {reference.phases[j].t_end - cond[j].delta, reference.phases[j].t_end + cond[j].delta});
  result.windows = windows.size();

  std::vector<Span> raw_engine, raw_reference;
  for (std::size_t j = 0; j < engine.phases.size(); ++j)
    raw_engine.push_back({kind_code(engine.phases[j].kind), Real(engine.phases[j].t_begin),
                          Real(engine.phases[j].t_end), j});
  for (std::size_t j = 0; j < reference.phases.size(); ++j)
    raw_reference.push_back({kind_code(reference.phases[j].kind), reference.phases[j].t_begin,
                             reference.phases[j].t_end, j});
  const std::vector<Span> e = normalize(raw_engine, model.omega, windows, result.removed);
  const std::vector<Span> r = normalize(raw_reference, model.omega, windows, result.removed);

  if (engine.summary.termination != frictionref::Termination::reached_end ||
      engine.phases.empty() || engine.phases.back().t_end != t_end) {
    result.sequence_matches = false;
    result.mismatch = "the engine did not reach t_end: " + engine.summary.message + "\n";
  }
  if (reference.phase_limit) {
    result.sequence_matches = false;
    result.mismatch += "the reference hit its phase limit\n";
  }
  const std::size_t n = std::min(e.size(), r.size());
  std::size_t first_difference = n;
  for (std::size_t i = 0; i < n; ++i)
    if (e[i].kind != r[i].kind) {
      first_difference = i;
      break;
    }
  if (first_difference < n || e.size() != r.size()) {
    result.sequence_matches = false;
    std::ostringstream text;
    text << "phase sequences differ at normalized phase " << first_difference << " (engine "
         << e.size() << " phases, reference " << r.size() << ")\n engine:\n"
         << window_text(e, first_difference) << " reference:\n"
         << window_text(r, first_difference);
    result.mismatch += text.str();
  }
  for (std::size_t i = 0; i + 1 < first_difference; ++i) {
    Event ev;
    ev.index = i;
    ev.kind = r[i].kind == 0       ? EventKind::breakaway
              : r[i + 1].kind == 0 ? EventKind::stop_to_stick
                                   : EventKind::reversal;
    ev.t_engine = static_cast<double>(e[i].t_end);
    ev.t_reference = r[i].t_end;
    const Real ulp = ulp_of(ev.t_reference);
    ev.error_ulps = static_cast<double>((Real(ev.t_engine) - ev.t_reference) / ulp);
    const Conditioning& c = cond[r[i].last];
    ev.well_conditioned = c.well_conditioned;
    ev.near_grazing = c.near_grazing;
    ev.resolvable = c.resolvable;
    ev.ratio = c.ratio;
    ev.bound_ulps = static_cast<double>(Real(kUlpLimit) + c.delta / ulp);
    result.events.push_back(ev);
  }
  return result;
}

std::string event_line(const Event& e) {
  std::ostringstream text;
  text << "event " << e.index << " (" << to_string(e.kind)
       << (e.near_grazing       ? ", near-grazing"
           : e.well_conditioned ? ""
                                : ", after a near-grazing one")
       << "): engine t = " << format(e.t_engine) << ", reference t = " << e.t_reference.str(25)
       << ", error = " << format(e.error_ulps, 4) << " ulps, slope/scale = " << format(e.ratio, 3)
       << ", bound = " << format(e.bound_ulps, 4) << " ulps"
       << (e.resolvable ? "" : " (unresolvable in long double)");
  return text.str();
}

// Max and RMS of |error| with the worst case.
class Stats {
 public:
  void add(const std::string& name, const Event& e) {
    const double err = std::fabs(e.error_ulps);
    ++count_;
    sum_squares_ += err * err;
    if (err > 0.5) ++above_half_;
    if (err > max_ || worst_.empty()) {
      max_ = std::max(max_, err);
      worst_ = name + "\n    " + event_line(e);
    }
    max_ratio_ = std::max(max_ratio_, err / e.bound_ulps);
  }
  std::size_t count() const { return count_; }
  double max() const { return max_; }
  double rms() const { return count_ ? std::sqrt(sum_squares_ / double(count_)) : 0; }
  std::string report(const std::string& title) const {
    std::ostringstream text;
    text << "  " << title << ": " << count_ << " events, max |error| = " << format(max_, 4)
         << " ulps, RMS = " << format(rms(), 4) << ", " << above_half_
         << " above 0.5 ulp, max error/bound = " << format(max_ratio_, 3);
    if (count_) text << "\n    worst: " << worst_;
    return text.str();
  }

 private:
  std::size_t count_ = 0, above_half_ = 0;
  double max_ = 0, sum_squares_ = 0, max_ratio_ = 0;
  std::string worst_;
};

// Checks cases against the limits, prints the first failures in full, and
// a summary per event kind.
class Checker {
 public:
  void run(const Model& model, double t_end) {
    try {
      check(compare(model, t_end));
    } catch (const std::exception& e) {
      ++cases_;
      ++failures_;
      if (printed_++ < 20)
        ADD_FAILURE() << "exception: " << e.what() << "\n  " << describe(model)
                      << " t_end=" << t_end;
    }
  }

  void check(const CaseResult& r) {
    ++cases_;
    if (!r.sequence_matches) {
      ++failures_;
      if (printed_++ < 20) ADD_FAILURE() << r.name << "\n" << r.mismatch;
    }
    for (const Event& e : r.events) {
      const double limit = e.well_conditioned ? kUlpLimit : e.bound_ulps;
      if (!(std::fabs(e.error_ulps) <= limit)) {
        ++failures_;
        if (printed_++ < 20)
          ADD_FAILURE() << (e.well_conditioned ? "well-conditioned event above 4 ulps"
                                               : "ill-conditioned event above its bound")
                        << "\n  " << r.name << "\n  " << event_line(e);
      }
      if (e.near_grazing)
        grazing_.add(r.name, e);
      else if (!e.well_conditioned)
        inherited_.add(r.name, e);
      else if (e.kind == EventKind::breakaway)
        breakaways_.add(r.name, e);
      else if (e.kind == EventKind::reversal)
        reversals_.add(r.name, e);
      else
        stops_.add(r.name, e);
    }
    removed_ += r.removed;
    windows_ += r.windows;
    engine_seconds_ += r.engine_seconds;
    reference_seconds_ += r.reference_seconds;
  }

  std::size_t events() const {
    return stops_.count() + reversals_.count() + breakaways_.count() + grazing_.count() +
           inherited_.count();
  }
  std::size_t grazing() const { return grazing_.count(); }

  void finish(const std::string& title) {
    std::cout << "==== " << title << ": " << cases_ << " models, " << events() << " events\n"
              << stops_.report("stops (then stuck), well conditioned") << "\n"
              << reversals_.report("reversals, well conditioned") << "\n"
              << breakaways_.report("breakaways, well conditioned") << "\n"
              << grazing_.report("near-grazing events (bound)") << "\n"
              << inherited_.report("events after a near-grazing one (bound)") << "\n"
              << "  phases dropped or merged as sub-resolution: " << removed_
              << "; unresolvable windows: " << windows_ << "; time: reference "
              << format(reference_seconds_, 3) << " s, engine " << format(engine_seconds_, 3)
              << " s\n"
              << std::flush;
    ::testing::Test::RecordProperty("events", std::to_string(events()));
    EXPECT_EQ(failures_, 0u) << "failed checks (models, sequences or events)";
  }

 private:
  std::size_t cases_ = 0, failures_ = 0, printed_ = 0, removed_ = 0, windows_ = 0;
  double engine_seconds_ = 0, reference_seconds_ = 0;
  Stats stops_, reversals_, breakaways_, grazing_, inherited_;
};

// m = B = w = 1 unless set.
Model base(double R, double Rs) {
  Model m;
  m.friction = R;
  m.static_friction = Rs;
  return m;
}

}  // namespace

// Static friction above sliding friction, no spring: stick-slip with
// breakaways at |F| = Rs (transversal: Rs < B).
TEST(GeneralEventAccuracy, StaticAboveKinetic) {
  Checker checker;
  for (const auto& [R, Rs] : {std::pair{0.3, 0.5}, {0.3, 0.8}, {0.6, 0.95}, {0.1, 0.7}})
    for (const double v0 : {0.0, 0.5, -1.0})
      for (const double t0 : {0.0, 2.5}) {
        Model m = base(R, Rs);
        m.v0 = v0;
        m.t0 = t0;
        checker.run(m, t0 + 60);
      }
  checker.finish("static > kinetic friction, m = B = w = 1");
  EXPECT_GT(checker.events(), 300u);
}

// A spring, forced below and above its natural frequency (wn = sqrt(k/m) vs
// w = 1), without damping: sticks where the equilibrium band holds the mass,
// reversals elsewhere.
TEST(GeneralEventAccuracy, SpringForced) {
  Checker checker;
  for (const double k : {0.3, 2.5, 6.0})
    for (const auto& [R, Rs] : {std::pair{0.2, 0.2}, {0.2, 0.35}, {0.5, 0.7}})
      for (const double x0 : {0.0, 0.7}) {
        Model m = base(R, Rs);
        m.stiffness = k;
        m.x0 = x0;
        checker.run(m, 50);
      }
  checker.finish("spring k in {0.3, 2.5, 6}, forced at w = 1, no damping");
  EXPECT_GT(checker.events(), 400u);
}

// No forcing: the free Coulomb oscillator (half cycles of pi sqrt(m/k), 2R/k
// lost per half cycle, then stuck once |k x| <= Rs), and the same with a
// constant force (the band centred on F0/k).
TEST(GeneralEventAccuracy, SpringUnforced) {
  Checker checker;
  for (const double Rs : {0.05, 0.1})
    for (const double F0 : {0.0, 0.4}) {
      Model m = base(0.05, Rs);
      m.amplitude = 0;
      m.mass = 0.5;
      m.stiffness = 2;
      m.force_offset = F0;
      m.x0 = 3;
      checker.run(m, 120);
    }
  checker.finish("free Coulomb oscillator, m = 0.5, k = 2, R = 0.05, x0 = 3, F0 in {0, 0.4}");
  EXPECT_GT(checker.events(), 200u);
}

// A viscous damper under-, critically and overdamped (and a rounding either
// side of critical, c = 2 sqrt(k m) (1 +- 1e-6) and +-1 ulp), forced at two
// frequencies, with and without static friction.
TEST(GeneralEventAccuracy, Damping) {
  Checker checker;
  const double critical = 2.0;  // 2 sqrt(k m), k = m = 1
  for (const double c : {0.2, critical * (1 - 1e-6), std::nextafter(critical, 0.0), critical,
                         std::nextafter(critical, 4.0), critical * (1 + 1e-6), 3.0})
    for (const double w : {0.8, 1.7})
      for (const double Rs : {0.3, 0.45}) {
        Model m = base(0.3, Rs);
        m.stiffness = 1;
        m.damping = c;
        m.omega = w;
        m.amplitude = 1.5;
        checker.run(m, 60);
      }
  checker.finish("damping c/c_crit in {0.1, 1 -+ 1e-6, 1 -+ 1 ulp, 1, 1.5}, k = m = 1, B = 1.5");
  EXPECT_GT(checker.events(), 400u);
}

// k = 0 with a damper: the velocity relaxes within each slip.
TEST(GeneralEventAccuracy, DamperWithoutSpring) {
  Checker checker;
  for (const double c : {0.1, 1.0, 4.0})
    for (const auto& [R, Rs] : {std::pair{0.3, 0.5}, {0.2, 0.2}})
      for (const double v0 : {0.0, 2.0}) {
        Model m = base(R, Rs);
        m.damping = c;
        m.v0 = v0;
        checker.run(m, 60);
      }
  checker.finish("k = 0, c in {0.1, 1, 4}");
  EXPECT_GT(checker.events(), 300u);
}

// A constant force: drift one way (F0 above R breaks the symmetry), with and
// without a spring.
TEST(GeneralEventAccuracy, ForceOffset) {
  Checker checker;
  for (const double F0 : {0.2, -0.5, 0.9})
    for (const double k : {0.0, 1.5})
      for (const double Rs : {0.4, 0.6}) {
        Model m = base(0.4, Rs);
        m.force_offset = F0;
        m.stiffness = k;
        m.damping = k > 0 ? 0.1 : 0.0;
        checker.run(m, 60);
      }
  checker.finish("force offset F0 in {0.2, -0.5, 0.9}, k in {0, 1.5}");
  EXPECT_GT(checker.events(), 150u);
}

// Two or three harmonics with phases (commensurate and not), with and
// without spring and damper.
TEST(GeneralEventAccuracy, SeveralHarmonics) {
  Checker checker;
  const std::vector<std::vector<frictionref::Harmonic>> sets = {
      {{0.5, 2.0, 0.3}},
      {{0.3, 3.0, -1.0}, {0.2, 0.5, 2.0}},
      {{-0.6, 1.4142135623730951, 0.0}, {0.25, 4.5, 1.0}},
  };
  for (const auto& harmonics : sets)
    for (const double k : {0.0, 2.0})
      for (const auto& [R, Rs] : {std::pair{0.3, 0.3}, {0.3, 0.55}}) {
        Model m = base(R, Rs);
        m.harmonics = harmonics;
        m.stiffness = k;
        m.damping = k > 0 ? 0.2 : 0.0;
        checker.run(m, 50);
      }
  checker.finish("two and three harmonics with phases, k in {0, 2}");
  EXPECT_GT(checker.events(), 200u);
}

// Other units and starts: m = 2.5, B = 3, w = 0.7, non-zero v0, x0, t0,
// everything at once.
// A ground record (linear between samples, zero outside them: a jump at its
// first and last sample) with a spring, damper, static friction and a
// harmonic force: the engine walks the record's segments with the general
// laws (docs/theory.md 9.6); the reference's Taylor steps stop at every
// sample. Light and heavy damping, a damper without a spring, m != 1,
// starts at rest and sliding.
TEST(GeneralEventAccuracy, GroundRecordWithSpringDamperHarmonic) {
  // Three tones under a half-sine envelope, dt = 0.02 s from t = 0.5 s, at
  // two levels (mostly stick-slip, mostly sliding).
  const auto tones = [](double level) {
    auto record = std::make_shared<frictionref::GroundMotion>();
    for (int i = 0; i <= 500; ++i) {
      const double t = 0.5 + 0.02 * i;
      const double envelope = std::sin(M_PI * i / 500.0) + 0.2;
      record->t.push_back(t);
      record->a.push_back(
          level * envelope *
          (0.8 * std::sin(2.1 * t) + 0.5 * std::sin(5.3 * t + 1) + 0.3 * std::sin(11.0 * t)));
    }
    record->file = "three tones";
    record->npts = record->t.size();
    return std::shared_ptr<const frictionref::GroundMotion>(record);
  };
  struct Case {
    double R, Rs, k, c, B, mass;
  };
  Checker checker;
  for (const double level : {1.0, 2.5})
    for (const Case& cs : {Case{0.3, 0.3, 4, 0, 0, 1}, Case{0.2, 0.35, 4, 0.4, 0, 1},
                           Case{0.1, 0.25, 1, 6, 0, 1}, Case{0.25, 0.4, 0, 0.8, 0, 1},
                           Case{0.2, 0.3, 9, 0.3, 0.3, 1}, Case{0.6, 0.8, 8, 1, 0, 2}}) {
      Model m = base(cs.R, cs.Rs);
      m.stiffness = cs.k;
      m.damping = cs.c;
      m.amplitude = cs.B;
      m.omega = 1.7;
      m.mass = cs.mass;
      m.ground_motion = tones(level);
      checker.run(m, 14);
      m.x0 = 0.3;  // from off the spring's equilibrium, sliding
      m.v0 = -0.5;
      checker.run(m, 14);
    }
  checker.finish("ground record with spring, damper, harmonic");
  EXPECT_GT(checker.events(), 150u);
}

TEST(GeneralEventAccuracy, ScaledUnitsAndStarts) {
  Checker checker;
  for (const double v0 : {0.0, 1.5, -4.0})
    for (const double t0 : {0.0, -3.75, 101.3})
      for (const bool spring : {false, true}) {
        Model m;
        m.mass = 2.5;
        m.amplitude = 3;
        m.omega = 0.7;
        m.friction = 0.9;
        m.static_friction = 1.4;
        m.stiffness = spring ? 1.2 : 0.0;
        m.damping = spring ? 0.35 : 0.0;
        m.force_offset = 0.25;
        m.harmonics = {{0.8, 1.9, 0.4}};
        m.x0 = spring ? -0.6 : 2.0;
        m.v0 = v0;
        m.t0 = t0;
        checker.run(m, t0 + 90);
      }
  checker.finish("m = 2.5, B = 3, w = 0.7, R = 0.9, Rs = 1.4, F0 = 0.25, a harmonic; v0, t0, x0");
  EXPECT_GT(checker.events(), 300u);
}

// Near-grazing breakaways: Rs a little below the peak of |N| = |F|, so N
// reaches Rs almost tangentially (|dN/dt| ~ sqrt(2 eps) B w at F = B (1 - eps)).
TEST(GeneralEventAccuracyNearGrazing, BreakawayNearThePeakOfTheForce) {
  Checker checker;
  for (const double eps : {1e-3, 1e-6, 1e-9, 1e-12, 1e-14})
    for (const double k : {0.0, 0.5}) {
      Model m = base(0.5, 1 - eps);
      m.stiffness = k;
      m.damping = k > 0 ? 0.1 : 0.0;
      checker.run(m, 40);
    }
  checker.finish("Rs = B (1 - eps), eps from 1e-3 to 1e-14, R = 0.5, k in {0, 0.5}");
  EXPECT_GE(checker.grazing(), 5u);
}

// Near-grazing stops: from rest a time eta before N = F0 + B sin(w t) falls
// back to Rs = R (t_r = pi - asin((R - F0) / B)): a slip of length ~2 eta
// ending with |dv/dt| ~ eta B w / m.
TEST(GeneralEventAccuracyNearGrazing, ShortSlipBeforeTheForceFallsBack) {
  Checker checker;
  const double F0 = 0.2, R = 0.9;
  const double release = 3.14159265358979323846 - std::asin((R - F0) / 1.0);
  for (const double eta : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10})
    for (const double k : {0.0, 0.5}) {
      Model m = base(R, R);
      m.force_offset = F0;
      m.stiffness = k;
      m.t0 = release - eta;
      checker.run(m, m.t0 + 30);
    }
  checker.finish("from rest eta before the force falls back to Rs = R = 0.9, F0 = 0.2");
  EXPECT_GE(checker.grazing(), 5u);
}

// A cross-check of the reference, not of the double engine: the engine's own
// 50-digit instance (closed forms, TOMS 748; the same algorithm as the double
// engine, so not independent of it) and the Taylor-series reference are two
// different 50-digit methods. They agree on every event time to 1e-40
// relative (both phase lists normalized as above).
TEST(GeneralEventAccuracyHighPrecision, ReferenceAgreesWithTheFiftyDigitEngine) {
  using frictionref::HighPrecision;
  std::vector<Model> models;
  {
    Model m = base(0.3, 0.5);  // static > kinetic
    models.push_back(m);
    m = base(0.2, 0.35);  // spring, forced
    m.stiffness = 2.5;
    models.push_back(m);
    m.damping = 2 * std::sqrt(2.5);  // critically damped
    m.omega = 1.7;
    models.push_back(m);
    m = base(0.3, 0.55);  // harmonics, spring, damper, offset, v0, t0
    m.harmonics = {{0.3, 3.0, -1.0}, {0.2, 0.5, 2.0}};
    m.stiffness = 2;
    m.damping = 0.2;
    m.force_offset = 0.1;
    m.v0 = -0.7;
    m.t0 = 2.5;
    models.push_back(m);
  }
  std::size_t events = 0;
  Real worst = 0;
  for (const Model& model : models) {
    const double t_end = model.t0 + 30;
    const auto hp =
        frictionref::solve(frictionref::model_cast<HighPrecision>(model), HighPrecision(t_end));
    const gref::Result reference = gref::solve(to_reference_input(model), t_end);
    std::vector<Span> raw_hp, raw_reference;
    for (std::size_t j = 0; j < hp.phases.size(); ++j)
      raw_hp.push_back(
          {kind_code(hp.phases[j].kind), Real(hp.phases[j].t_begin), Real(hp.phases[j].t_end), j});
    for (std::size_t j = 0; j < reference.phases.size(); ++j)
      raw_reference.push_back({kind_code(reference.phases[j].kind), reference.phases[j].t_begin,
                               reference.phases[j].t_end, j});
    std::size_t removed = 0;
    const auto a = normalize(raw_hp, model.omega, {}, removed);
    const auto b = normalize(raw_reference, model.omega, {}, removed);
    ASSERT_EQ(a.size(), b.size()) << describe(model);
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
      ASSERT_EQ(a[i].kind, b[i].kind) << describe(model) << " phase " << i;
      const Real relative = abs(a[i].t_end - b[i].t_end) / abs(b[i].t_end);
      worst = std::max(worst, relative);
      EXPECT_LT(relative, Real("1e-40")) << describe(model) << " event " << i;
      ++events;
    }
  }
  std::cout << "50-digit engine vs reference: " << events << " events, max relative difference "
            << worst.str(3) << "\n";
  EXPECT_GT(events, 60u);
}

// Near-grazing stops at a dip: v0 set so that the first slip's speed dips to
// just below zero before the force turns it round (the stop then has slope
// ~ sqrt(2 |depth| |v''|)); below ~1e-16 the dip is not resolvable in long
// double and the window rule applies. v0* (the smallest double v0 whose slip
// does not stop before t0 + 1.5) is found by bisection on the reference: no
// literal value, no engine involved.
TEST(GeneralEventAccuracyNearGrazing, DipJustBelowZero) {
  Checker checker;
  for (const double t0 : {0.0, 50.25}) {
    Model m = base(0.5, 0.7);
    m.stiffness = 0.4;
    m.damping = 0.05;
    m.force_offset = 0.1;
    m.harmonics = {{0.2, 2.3, 0.5}};
    m.t0 = t0;
    auto stops_early = [&](double v0) {
      Model trial = m;
      trial.v0 = v0;
      const gref::Result r = gref::solve(to_reference_input(trial), t0 + 1.5);
      return !r.phases.front().at_horizon;
    };
    double low = 0, high = 1;  // stops early at low, not at high
    ASSERT_TRUE(stops_early(1e-9));
    ASSERT_FALSE(stops_early(high));
    while (std::nextafter(low, high) < high) {
      const double mid = low + (high - low) / 2;
      if (mid <= low || mid >= high) break;
      (stops_early(mid) ? low : high) = mid;
    }
    // depth 0: v0 = low, the last double that stops, a dip of ~1e-19, below
    // the engine's resolution (the window rule). Not compared: v0 = high, a
    // minimum of v within ~1e-17 above zero, which the engine may take as a
    // stop (within its rounding bound) and the reference, having no stop
    // there, has no event to compare it with.
    for (const double depth : {1e-3, 1e-6, 1e-9, 1e-12, 1e-14, 0.0}) {
      Model trial = m;
      trial.v0 = depth > 0 ? high - depth : low;
      checker.run(trial, t0 + 30);
    }
  }
  checker.finish("dips of v to -1e-3 ... -1e-14 and one ulp of v0 below zero, k = 0.4, c = 0.05");
  EXPECT_GE(checker.grazing(), 6u);
}
