// libFuzzer target: model parameters + the exact engine.
//
// The input is decoded into the seven Model fields, the horizon t_end and
// optionally SolveOptions::max_phases. Every field is either the raw bit
// pattern of a double (so NaN, +-inf, subnormals, -0 and huge values all
// occur) or a short decimal m * 10^e (so realistic models such as lambda = 0.7
// are easy to reach). The contract under test:
//
//   ExactEngine(model, t_end, options) either throws frictionref::InvalidInput,
//   or it streams phases whose invariants hold (below), within at most
//   kPhasesPerPeriod * (periods + 1) phases, and ends with reached_end (or
//   phase_limit when max_phases was given). numerical_failure, any other
//   exception, a sanitizer report or a hang is a finding.
//
// Invariants checked (docs/theory.md sections 2-4, phase.hpp):
//   - every value of every phase is finite; t_begin < t_end;
//   - the first phase starts at (t0, x0, v0), the last ends at t_end exactly
//     when the run reached the end;
//   - consecutive phases share their boundary (t, x, v), v = 0 there, and two
//     adjacent phases are never of the same kind;
//     (except where the engine skipped phases shorter than one ulp of t,
//     docs/theory.md 4.8, counted from the summary: there x may jump by what
//     the mass covers in that time, see check_boundary);
//   - a stick has v = 0 and constant x, and |B sin(w t)| <= R inside it;
//   - a slip of sign s has s v >= 0 inside it (dense evaluation), ends with
//     v = 0 by its own closed form when it stops, and its first phase matches
//     the sign of v0 (or of the force when v0 = 0 and |F(t0)| is clearly > R);
//   - a breakaway (stick -> slip s) happens where B sin(w t) = s R;
//   - the summary agrees with the stream (phase counts, final state).
// Tolerances are relative and generous (tens of ulps of the scales involved):
// the target looks for wrong signs, gaps and runaway phase counts, not for the
// last ulp (the unit tests and docs/accuracy.md do that).
//
// Work per input is bounded: inputs whose horizon exceeds kMaxPeriods forcing
// periods are skipped after validation. Open findings can be tolerated with
// FRICTIONREF_FUZZ_ALLOW (see allowed() below).
//
// Input layout (missing bytes read as 0):
//   byte 0      encoding of fields 0..7: bit i set = raw 8-byte double,
//               clear = 4-byte decimal m * 10^e (int24 m, int8 byte % 11 = e in -10..10)
//   byte 1      flags: bit 0 friction field is lambda (R = lambda B);
//               bits 1-2 t_end field: 0 absolute t_end, 1 span (t_end = t0 + span),
//               2-3 forcing periods (t_end = t0 + n 2 pi / w);
//               bit 3 v0 is in units of B / (m w); bit 4 max_phases follows (uint16);
//               bit 7 replay the seed's steady motion from the first cycle
//               or reversal that allows it on (SolveOptions::
//               replay_min_cycles = 1, docs/theory.md 3.9, 3.10)
//   fields      mass, amplitude, omega, friction|lambda, x0, v0, t0, t_end|span|periods
//   [2 bytes]   max_phases (little endian), if flag bit 4
//   the general model, if flag bit 5 (docs/theory.md 7):
//   byte        encoding of the general fields (bit i: field i raw, else decimal)
//   fields      static (Rs = R + |field|, or the raw value itself when raw), stiffness,
//               damping, force_offset
//   byte        number of extra harmonics, % 4; then per harmonic B, W, PHI (encoding
//               bits 4, 5, 6 of the general byte, shared by all harmonics)
//   a ground record, if flag bit 6 (docs/theory.md 9):
//   byte        number of samples, 2 + byte % 31
//   byte        encoding: bit 0 times raw, bit 1 accelerations raw; bit 2 one-way
//   fields      t_0, a_0, then per further sample dt_i (t_i = t_{i-1} + dt_i), a_i
//
// The general model (anything but the seed's) is checked against its own rules:
// N(t) = F(t) - k x; a stick keeps |N| <= Rs, a breakaway has |N| = Rs in the
// slip's direction, a stop into a stick has |N| <= Rs, a reversal has N
// beyond Rs against the old direction; a slip keeps the sign of v. Its
// tolerances are relative to the a priori bounds of the motion (1e-9 of them):
// the target looks for wrong decisions, not for the last ulp. With a record,
// N includes -m a_g(t) (right-continuous: at a sample time the segment to its
// right), and a breakaway at a sample time may find |N| beyond Rs (a_g jumps
// at the record's first and last sample).
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "frictionref/frictionref.hpp"
#include "fuzz_check.hpp"

namespace {

using frictionref::ExactEngine;
using frictionref::InvalidInput;
using frictionref::Model;
using frictionref::Phase;
using frictionref::PhaseKind;
using frictionref::SolveOptions;
using frictionref::Termination;

// Bounds: inputs longer than this many forcing periods are skipped, and a run
// may emit at most kPhasesPerPeriod * (periods + 1) phases. In steady state
// there are at most 4 phases per period (dead bands: slip+, stick, slip-,
// stick), and a transient adds at most a few; 8 leaves a factor of two.
constexpr long double kMaxPeriods = 200;
constexpr std::uint64_t kPhasesPerPeriod = 8;
// Dense samples inside each phase (at k / (kSamples + 1) of its length).
constexpr int kSamples = 3;

// Known findings can be tolerated while they are open, so a long run goes on
// looking for new ones: the environment variable FRICTIONREF_FUZZ_ALLOW is a
// comma-separated list of
//   overflow           a valid model whose solution leaves the range of double
//                      (|v|, |x| or |a| may exceed kRangeLimit, e.g. B/(m w) =
//                      1e600) may report inf: such models get the time and
//                      count checks only (finding F1 in docs/reliability.md);
//   numerical_failure  Termination::numerical_failure is accepted (findings F2, F3);
//   root_polish        a slip whose velocity has the wrong sign inside it, that
//                      stops where its velocity is not 0, or that is followed by a
//                      slip of the same kind, is accepted
//                      (finding F4: the long double polish of a stop time can
//                      stall and return the far end of the bracket).
// Unset (the default, and CI): everything is a finding.
constexpr long double kRangeLimit = 1e300L;

struct Allowed {
  bool overflow = false;
  bool numerical_failure = false;
  bool root_polish = false;
};

const Allowed& allowed() {
  static const Allowed value = [] {
    Allowed a;
    const char* list = std::getenv("FRICTIONREF_FUZZ_ALLOW");
    const std::string text = list ? list : "";
    std::size_t begin = 0;
    while (begin <= text.size()) {
      std::size_t end = text.find(',', begin);
      if (end == std::string::npos) end = text.size();
      const std::string item = text.substr(begin, end - begin);
      if (item == "overflow") {
        a.overflow = true;
      } else if (item == "numerical_failure") {
        a.numerical_failure = true;
      } else if (item == "root_polish") {
        a.root_polish = true;
      } else if (!item.empty()) {
        std::fprintf(stderr, "fuzz_engine: unknown FRICTIONREF_FUZZ_ALLOW item '%s'\n",
                     item.c_str());
        std::exit(2);
      }
      begin = end + 1;
    }
    if (a.overflow || a.numerical_failure || a.root_polish)
      std::fprintf(stderr, "fuzz_engine: tolerating%s%s%s (FRICTIONREF_FUZZ_ALLOW)\n",
                   a.overflow ? " overflow" : "", a.numerical_failure ? " numerical_failure" : "",
                   a.root_polish ? " root_polish" : "");
    return a;
  }();
  return value;
}

constexpr long double kTwoPi = 6.283185307179586476925286766559L;
constexpr long double kEps = std::numeric_limits<double>::epsilon();

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  std::uint64_t little_endian(int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value |= std::uint64_t{byte()} << (8 * i);
    return value;
  }

  double raw_double() {
    const std::uint64_t bits = little_endian(8);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  // m * 10^e with m a signed 24-bit integer and e in [-10, 10], correctly
  // rounded (strtod), so 7e-1 is the double nearest 0.7.
  double decimal() {
    std::int32_t mantissa = static_cast<std::int32_t>(little_endian(3));
    if (mantissa & 0x800000) mantissa -= 0x1000000;
    const int exponent = static_cast<std::int8_t>(byte()) % 11;  // -10 .. 10
    char text[32];
    std::snprintf(text, sizeof text, "%de%d", static_cast<int>(mantissa), exponent);
    return std::strtod(text, nullptr);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// What is being checked, printed before aborting on a violation.
struct Context {
  Model model;
  double t_end = 0;
  std::optional<std::uint64_t> max_phases;
  std::uint64_t phase_number = 0;
};
const Context* g_context = nullptr;

void print_phase(const char* name, const Phase& p) {
  std::fprintf(stderr, "  %s: %s t=[%.17g, %.17g] x=[%.17g, %.17g] v=[%.17g, %.17g]\n", name,
               std::string(frictionref::to_string(p.kind)).c_str(), p.t_begin, p.t_end, p.x_begin,
               p.x_end, p.v_begin, p.v_end);
}

[[noreturn]] void fail(const char* what, int line, const Phase* phase = nullptr,
                       const Phase* previous = nullptr) {
  std::fprintf(stderr, "\nfuzz_engine: invariant violated (fuzz_engine.cpp:%d): %s\n", line, what);
  if (g_context) {
    const Model& m = g_context->model;
    std::fprintf(stderr,
                 "  model: mass=%.17g amplitude=%.17g omega=%.17g friction=%.17g x0=%.17g "
                 "v0=%.17g t0=%.17g\n  t_end=%.17g max_phases=%s phase #%" PRIu64 "\n",
                 m.mass, m.amplitude, m.omega, m.friction, m.x0, m.v0, m.t0, g_context->t_end,
                 g_context->max_phases ? std::to_string(*g_context->max_phases).c_str() : "(none)",
                 g_context->phase_number);
    if (!m.is_harmonic_coulomb()) {
      std::fprintf(stderr,
                   "  static_friction=%.17g stiffness=%.17g damping=%.17g force_offset=%.17g\n",
                   m.static_limit(), m.stiffness, m.damping, m.force_offset);
      for (const auto& h : m.harmonics)
        std::fprintf(stderr, "  harmonic=%.17g,%.17g,%.17g\n", h.amplitude, h.omega, h.phase);
      if (m.ground_motion)
        for (std::size_t i = 0; i < m.ground_motion->t.size(); ++i)
          std::fprintf(stderr, "  record t=%.17g a=%.17g\n", m.ground_motion->t[i],
                       m.ground_motion->a[i]);
    }
  }
  if (previous) print_phase("previous", *previous);
  if (phase) print_phase("phase", *phase);
  std::fflush(stderr);
  std::abort();
}

long double force(const Model& m, double t) {
  return static_cast<long double>(m.amplitude) *
         std::sin(static_cast<long double>(m.omega) * static_cast<long double>(t));
}

// Scale of the forcing phase at t, for tolerances: max(1, |w t|).
long double tau_scale(const Model& m, double t) {
  return std::fmax(1.0L, std::fabs(static_cast<long double>(m.omega) * t));
}

// |B sin(w t)| <= R up to the rounding of w t (stored event times are rounded
// to double, so a sample may lie a few ulps of t outside the true stick).
bool inside_friction_band(const Model& m, double t) {
  const long double tolerance = 1e-12L * m.friction + 64 * kEps * tau_scale(m, t) * m.amplitude;
  return std::fabs(force(m, t)) <= static_cast<long double>(m.friction) + tolerance;
}

// Tolerance for a velocity inside a slip that started at (t_begin, v_begin):
// the closed form's terms |v_a|, b, r |tau - a| at the rounding of tau.
long double velocity_tolerance(const Model& m, const Phase& p, double t) {
  const long double w = m.omega;
  const long double b = static_cast<long double>(m.amplitude) / (m.mass * w);
  const long double r = static_cast<long double>(m.friction) / (m.mass * w);
  const long double h = std::fabs(w * (static_cast<long double>(t) - p.t_begin));
  const long double scale = std::fmax(tau_scale(m, t), tau_scale(m, p.t_begin));
  return 64 * kEps * scale * (std::fabs(static_cast<long double>(p.v_begin)) + b + r * (1 + h));
}

// Bounds on |v|, |x| and |a| over the horizon, all within kRangeLimit.
bool solution_in_double_range(const Model& m, double t_end) {
  const long double w = m.omega;
  const long double b = static_cast<long double>(m.amplitude) / (m.mass * w);
  const long double r = static_cast<long double>(m.friction) / (m.mass * w);
  const long double h = w * (static_cast<long double>(t_end) - m.t0);  // horizon [rad]
  const long double v = std::fabs(static_cast<long double>(m.v0)) + 2 * b + r * h;
  const long double x = std::fabs(static_cast<long double>(m.x0)) + v * h / w;
  const long double a = w * (b + r);
  return v <= kRangeLimit && x <= kRangeLimit && a <= kRangeLimit;
}

bool finite(const Phase& p) {
  return std::isfinite(p.t_begin) && std::isfinite(p.t_end) && std::isfinite(p.x_begin) &&
         std::isfinite(p.x_end) && std::isfinite(p.v_begin) && std::isfinite(p.v_end);
}

// ---- the general model --------------------------------------------------

// A priori bounds of the general motion over [t0, t_end] (the energy grows at
// most at rate |v| (F_max + R)), its fastest rate, and the scale tolerances are
// taken relative to.
struct GeneralScales {
  long double force = 0;         // |F0| + B + sum |B_i| + m max |a_g|
  long double record_rate = 0;   // m max |a_g'|
  long double forcing_rate = 0;  // B w + sum |B_i| w_i >= |F'|
  long double speed = 0;         // >= |v|
  long double travel = 0;        // >= |x|
  long double fast = 0;          // max(w, w_i, sqrt(k/m), c/m) [1/time]
};

GeneralScales general_scales(const Model& m, double t_end) {
  GeneralScales g;
  g.force = std::fabs(static_cast<long double>(m.force_offset)) + m.amplitude;
  g.forcing_rate = static_cast<long double>(m.amplitude) * m.omega;
  for (const auto& h : m.harmonics) {
    g.force += std::fabs(static_cast<long double>(h.amplitude));
    g.forcing_rate += std::fabs(static_cast<long double>(h.amplitude)) * h.omega;
  }
  if (m.ground_motion) {
    const auto& r = *m.ground_motion;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      if (i + 1 < r.a.size())
        g.record_rate = std::max<long double>(
            g.record_rate, m.mass * std::fabs(static_cast<long double>(r.a[i + 1]) - r.a[i]) /
                               (static_cast<long double>(r.t[i + 1]) - r.t[i]));
    }
    g.force += static_cast<long double>(m.mass) * r.pga();
  }
  const long double v0 = m.v0, x0 = m.x0, k = m.stiffness, mass = m.mass;
  const long double span = static_cast<long double>(t_end) - m.t0;
  g.speed = std::sqrt(v0 * v0 + k * x0 * x0 / mass) + (g.force + m.friction) * span / mass;
  g.travel = std::fabs(x0) + g.speed * span;
  g.fast = std::max<long double>(m.omega, std::sqrt(k / mass));
  g.fast = std::max<long double>(g.fast, m.damping / mass);
  for (const auto& h : m.harmonics) g.fast = std::max<long double>(g.fast, h.omega);
  return g;
}

// a_g(t) as the engine takes it: linear between samples, 0 before the first
// and from the last on (right-continuous at every sample).
long double ground_accel(const Model& m, double t) {
  if (!m.ground_motion) return 0;
  const auto& ts = m.ground_motion->t;
  const auto& as = m.ground_motion->a;
  if (t < ts.front() || t >= ts.back()) return 0;
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin()) - 1;
  const long double h = static_cast<long double>(ts[i + 1]) - ts[i];
  return as[i] + (static_cast<long double>(as[i + 1]) - as[i]) * ((t - ts[i]) / h);
}

// True if t is one of the record's sample times.
bool at_sample(const Model& m, double t) {
  if (!m.ground_motion) return false;
  const auto& ts = m.ground_motion->t;
  return std::binary_search(ts.begin(), ts.end(), t);
}

// F(t) - m a_g(t) - k x, in long double.
long double net_force(const Model& m, double t, double x) {
  long double f = m.force_offset + static_cast<long double>(m.amplitude) *
                                       std::sin(static_cast<long double>(m.omega) * t);
  for (const auto& h : m.harmonics)
    f += static_cast<long double>(h.amplitude) *
         std::sin(static_cast<long double>(h.omega) * t + h.phase);
  f -= static_cast<long double>(m.mass) * ground_accel(m, t);
  return f - static_cast<long double>(m.stiffness) * x;
}

// Tolerance of N at t: 1e-9 of the forces involved, plus the rounding of the
// forcing phases at |t| (a stored time is rounded to double), plus this
// oracle's own rounding of w_i t + phi_i in long double (the engine reduces
// phi_i mod 2 pi exactly; net_force above does not).
long double force_tolerance(const Model& m, const GeneralScales& g, double t, double x) {
  // (In long double throughout: |B_i| 4 in double overflowed for |B_i| = 1.2e308
  // and made the tolerance inf * 0 = NaN; found by fuzzing.)
  const long double spring = std::fabs(static_cast<long double>(m.stiffness) * x);
  const long double scale = g.force + m.static_limit() + spring;
  const long double phase = 64 * kEps * std::fmax(1.0L, g.fast * std::fabs(t));
  long double oracle = 0;
  for (const auto& h : m.harmonics)
    oracle += std::fabs(static_cast<long double>(h.amplitude)) * 4 * kEps * std::fabs(h.phase);
  // The record's value at a time rounded to double (and to tau = w t), and
  // the forcing's and the record's change within the engine's time
  // resolution 8 eps max(1, |w t|) / w, inside which an event is placed (at a
  // sample, a breakaway the record's next interval brings within the
  // resolution is placed at the sample; a stick starts where N, moving
  // inwards, re-enters the band within it). The resolution is the main
  // forcing's: a harmonic up to 1e10 times faster (docs/theory.md 4.12)
  // moves N by |B_i| w_i times it, more than the band itself can be (found
  // by fuzzing: corpus general-finding-fast-harmonic-within-resolution).
  const long double resolution = 16 * std::numeric_limits<double>::epsilon() *
                                 std::fmax(1.0L, static_cast<long double>(m.omega) * std::fabs(t)) /
                                 m.omega;
  const long double record =
      g.record_rate * (64 * kEps * std::fmax(1.0L, std::fabs(t)) + resolution);
  const long double forcing = g.forcing_rate * resolution;
  return 1e-9L * scale + phase * (g.force + spring) + oracle + record + forcing;
}

long double speed_tolerance(const GeneralScales& g) { return 1e-9L * g.speed; }

// The phase's rows in one batch, as states and as columns, equal its single evaluations bit for
// bit: a batch's whole groups of eight take the dense fast path's eight lanes where the CPU has
// AVX-512F, a single row its four lanes (or either falls back to long double: the same rule both
// ways). 17 times: its ends and 15 between, two groups of eight and one row.
void check_batch(const Model& m, const Phase& p) {
  constexpr int kBatch = 17;
  double times[kBatch];
  for (int k = 0; k < kBatch; ++k)
    times[k] = k == kBatch - 1 ? p.t_end : p.t_begin + (p.t_end - p.t_begin) * k / (kBatch - 1);
  const frictionref::PhaseEvaluator law(m, p);
  frictionref::State rows[kBatch];
  law(times, kBatch, rows);
  double x[kBatch], v[kBatch], a[kBatch];  // the same as columns
  law(times, kBatch, x, v, a);
  for (int k = 0; k < kBatch; ++k) {
    const frictionref::State single = law(times[k]);
    FUZZ_CHECK_AT(std::memcmp(&rows[k].x, &single.x, sizeof(double)) == 0 &&
                      std::memcmp(&rows[k].v, &single.v, sizeof(double)) == 0 &&
                      std::memcmp(&rows[k].a, &single.a, sizeof(double)) == 0 &&
                      rows[k].t == single.t && rows[k].phase == single.phase,
                  &p);
    FUZZ_CHECK_AT(std::memcmp(&x[k], &single.x, sizeof(double)) == 0 &&
                      std::memcmp(&v[k], &single.v, sizeof(double)) == 0 &&
                      std::memcmp(&a[k], &single.a, sizeof(double)) == 0,
                  &p);
  }
}

void check_phase_general(const Model& m, const GeneralScales& g, const Phase& p) {
  FUZZ_CHECK_AT(std::isfinite(p.t_begin) && std::isfinite(p.t_end), &p);
  FUZZ_CHECK_AT(p.t_begin < p.t_end, &p);
  FUZZ_CHECK_AT(finite(p), &p);
  const int s = frictionref::slip_sign(p.kind);
  if (m.one_way) FUZZ_CHECK_AT(s >= 0, &p);  // never towards negative x
  if (s == 0) {
    FUZZ_CHECK_AT(p.v_begin == 0 && p.v_end == 0, &p);
    FUZZ_CHECK_AT(p.x_begin == p.x_end, &p);
  } else {
    FUZZ_CHECK_AT(s * p.v_begin >= 0, &p);
    FUZZ_CHECK_AT(s * p.v_end >= -speed_tolerance(g), &p);
  }
  for (int k = 1; k <= kSamples; ++k) {
    const double t = p.t_begin + (p.t_end - p.t_begin) * k / (kSamples + 1);
    if (!(t > p.t_begin && t < p.t_end)) continue;
    const frictionref::State state = frictionref::evaluate(m, p, t);
    FUZZ_CHECK_AT(std::isfinite(state.x) && std::isfinite(state.v) && std::isfinite(state.a), &p);
    if (s == 0) {
      FUZZ_CHECK_AT(state.v == 0 && state.x == p.x_begin, &p);
      // One-way only the upper edge holds: N may be below -Rs.
      const long double n = net_force(m, t, p.x_begin);
      FUZZ_CHECK_AT(
          (m.one_way ? n : std::fabs(n)) <= m.static_limit() + force_tolerance(m, g, t, p.x_begin),
          &p);
    } else {
      FUZZ_CHECK_AT(s * state.v >= -speed_tolerance(g), &p);
      FUZZ_CHECK_AT(std::fabs(state.v) <= g.speed * (1 + 1e-9L) + speed_tolerance(g), &p);
    }
  }
}

void check_boundary_general(const Model& m, const GeneralScales& g, const Phase& p, const Phase& q,
                            std::uint64_t skipped) {
  FUZZ_CHECK_AT(q.t_begin == p.t_end, &q, &p);
  FUZZ_CHECK_AT(p.v_end == 0, &q, &p);
  FUZZ_CHECK_AT(q.v_begin == 0, &q, &p);
  if (skipped > 0) return;  // sub-resolution phases in between: no decision to check
  FUZZ_CHECK_AT(p.kind != q.kind, &q, &p);
  FUZZ_CHECK_AT(q.x_begin == p.x_end, &q, &p);
  const long double n = net_force(m, q.t_begin, q.x_begin);
  const long double tolerance = force_tolerance(m, g, q.t_begin, q.x_begin);
  const long double rs = m.static_limit();
  const int s = frictionref::slip_sign(p.kind), next = frictionref::slip_sign(q.kind);
  if (s == 0) {                   // a breakaway: |N| reached Rs in the slip's direction
    if (at_sample(m, q.t_begin))  // or jumped past it (the record's ends)
      FUZZ_CHECK_AT(std::fabs(n) >= rs - tolerance, &q, &p);
    else
      FUZZ_CHECK_AT(std::fabs(std::fabs(n) - rs) <= tolerance, &q, &p);
    FUZZ_CHECK_AT(next * n >= -tolerance, &q, &p);
  } else if (next == 0) {  // a stop into a stick (one-way: N may be below -Rs)
    FUZZ_CHECK_AT((m.one_way ? n : std::fabs(n)) <= rs + tolerance, &q, &p);
  } else {  // a reversal: N beats Rs against the old direction
    FUZZ_CHECK_AT(next == -s, &q, &p);
    FUZZ_CHECK_AT(next * n >= rs - tolerance, &q, &p);
  }
}

void check_first_general(const Model& m, const GeneralScales& g, const Phase& p,
                         std::uint64_t skipped) {
  FUZZ_CHECK_AT(p.t_begin == m.t0, &p);
  if (skipped > 0) return;  // an initial slip shorter than the resolution
  FUZZ_CHECK_AT(p.x_begin == m.x0, &p);
  FUZZ_CHECK_AT(p.v_begin == m.v0, &p);
  const int s = frictionref::slip_sign(p.kind);
  if (m.v0 > 0) FUZZ_CHECK_AT(s == 1, &p);
  if (m.v0 < 0) FUZZ_CHECK_AT(s == -1, &p);
  if (m.v0 == 0) {
    const long double n = net_force(m, m.t0, m.x0);
    const long double margin = 1e3L * force_tolerance(m, g, m.t0, m.x0);
    const long double rs = m.static_limit();
    if (n > rs + margin) FUZZ_CHECK_AT(s == 1, &p);
    if (n < -(rs + margin)) FUZZ_CHECK_AT(s == (m.one_way ? 0 : -1), &p);
    if (std::fabs(n) < rs - margin) FUZZ_CHECK_AT(s == 0, &p);
  }
}

void check_phase(const Model& m, const Phase& p, bool values) {
  FUZZ_CHECK_AT(std::isfinite(p.t_begin) && std::isfinite(p.t_end), &p);
  FUZZ_CHECK_AT(p.t_begin < p.t_end, &p);
  if (!values) return;
  FUZZ_CHECK_AT(finite(p), &p);
  const int s = frictionref::slip_sign(p.kind);
  if (s == 0) {
    FUZZ_CHECK_AT(p.v_begin == 0 && p.v_end == 0, &p);
    FUZZ_CHECK_AT(p.x_begin == p.x_end, &p);
  } else {
    FUZZ_CHECK_AT(s * p.v_begin >= 0, &p);
    if (!allowed().root_polish)
      FUZZ_CHECK_AT(s * p.v_end >= -velocity_tolerance(m, p, p.t_end), &p);
  }
  for (int k = 1; k <= kSamples; ++k) {
    const double t = p.t_begin + (p.t_end - p.t_begin) * k / (kSamples + 1);
    if (!(t > p.t_begin && t < p.t_end)) continue;  // phase a few ulps long
    const frictionref::State state = frictionref::evaluate(m, p, t);
    FUZZ_CHECK_AT(std::isfinite(state.x) && std::isfinite(state.v) && std::isfinite(state.a), &p);
    if (s == 0) {
      FUZZ_CHECK_AT(state.v == 0 && state.x == p.x_begin, &p);
      FUZZ_CHECK_AT(inside_friction_band(m, t), &p);
    } else if (!allowed().root_polish) {
      FUZZ_CHECK_AT(s * state.v >= -velocity_tolerance(m, p, t), &p);
    }
  }
}

// Phases too short to show in double are skipped and the motion goes on from
// their end state (docs/theory.md section 4.8), so a boundary may hide `skipped`
// phases, each shorter than one ulp of t: there x may jump by what the mass
// covers in that time, two phases of the same kind may meet, and the first
// phase may start at rest after an initial slip that was too short to show.
// The caller counts them from the summary (below); without them the checks
// are exact.
long double skipped_tau(const Model& m, double t, std::uint64_t skipped) {
  const double at = std::fabs(t);
  const long double ulp = std::nextafter(at, HUGE_VAL) - at;
  return 2.0L * static_cast<long double>(skipped) * m.omega * ulp;
}

long double ulp_of(double a, double b) {
  const double at = std::fmax(std::fabs(a), std::fabs(b));
  return std::nextafter(at, HUGE_VAL) - at;
}

// How far the mass can move in `tau` radians starting at speed `speed`, plus
// the rounding of the closed-form position in the work type (long double),
// which does not shrink with the phase: x = x_a + [.. - b (sin tau - sin a) ..] / w.
long double reach(const Model& m, long double speed, long double tau, std::uint64_t skipped) {
  const long double w = m.omega;
  const long double b = static_cast<long double>(m.amplitude) / (m.mass * w);
  const long double r = static_cast<long double>(m.friction) / (m.mass * w);
  const long double rounding = 64 * std::numeric_limits<long double>::epsilon() *
                               static_cast<long double>(skipped) * (b + speed + r * tau) / w;
  return 2 * (speed + (b + r) * tau) * tau / w + rounding;
}

// The boundary between two consecutive phases p -> q.
void check_boundary(const Model& m, const Phase& p, const Phase& q, bool values,
                    std::uint64_t skipped) {
  FUZZ_CHECK_AT(q.t_begin == p.t_end, &q, &p);
  if (!values) return;
  if (skipped == 0 && !allowed().root_polish) FUZZ_CHECK_AT(p.kind != q.kind, &q, &p);
  FUZZ_CHECK_AT(p.v_end == 0, &q, &p);  // an interior boundary is always at rest
  FUZZ_CHECK_AT(q.v_begin == 0, &q, &p);
  if (skipped == 0) {
    FUZZ_CHECK_AT(q.x_begin == p.x_end, &q, &p);
  } else {
    const long double jump = std::fabs(static_cast<long double>(q.x_begin) - p.x_end);
    FUZZ_CHECK_AT(jump <= reach(m, 0, skipped_tau(m, p.t_end, skipped), skipped) +
                              4 * ulp_of(p.x_end, q.x_begin),
                  &q, &p);
  }
  const int s = frictionref::slip_sign(p.kind);
  if (s != 0) {
    // The slip stopped where its own closed form gives v = 0: evaluate one
    // ulp before the stored end (evaluate() returns the stored 0 at t_end).
    const double before = std::nextafter(p.t_end, p.t_begin);
    if (before > p.t_begin && !allowed().root_polish) {
      const double v = frictionref::evaluate(m, p, before).v;
      const long double a = std::fabs(static_cast<long double>(m.amplitude) + m.friction) / m.mass;
      FUZZ_CHECK_AT(std::fabs(static_cast<long double>(v)) <=
                        velocity_tolerance(m, p, p.t_end) + 4 * a * (p.t_end - before),
                    &q, &p);
    }
  }
  const int next = frictionref::slip_sign(q.kind);
  if (s == 0 && next != 0 && skipped == 0) {
    // A breakaway: the force has just reached next * R.
    const long double f = force(m, q.t_begin);
    const long double tolerance =
        1e-12L * m.friction + 64 * kEps * tau_scale(m, q.t_begin) * m.amplitude;
    FUZZ_CHECK_AT(std::fabs(f - static_cast<long double>(next) * m.friction) <= tolerance, &q, &p);
  }
}

void check_first(const Model& m, const Phase& p, bool values, std::uint64_t skipped) {
  FUZZ_CHECK_AT(p.t_begin == m.t0, &p);
  if (!values) return;
  if (skipped > 0 && !(p.x_begin == m.x0 && p.v_begin == m.v0)) {
    // An initial slip (or slips) shorter than one ulp of t0: the first phase
    // starts at rest, where that slip stopped. (`skipped` may also count the
    // stop that ends this phase when it rounds to t_end: then the start is exact.)
    FUZZ_CHECK_AT(p.v_begin == 0, &p);
    const long double tau = skipped_tau(m, m.t0, skipped);
    const long double w = m.omega;
    const long double b = static_cast<long double>(m.amplitude) / (m.mass * w);
    const long double r = static_cast<long double>(m.friction) / (m.mass * w);
    const long double speed = std::fabs(static_cast<long double>(m.v0));
    FUZZ_CHECK_AT(speed <= 2 * (b + r) * tau, &p);  // it could stop that soon
    const long double jump = std::fabs(static_cast<long double>(p.x_begin) - m.x0);
    FUZZ_CHECK_AT(jump <= reach(m, speed, tau, skipped) + 4 * ulp_of(m.x0, p.x_begin), &p);
    return;
  }
  FUZZ_CHECK_AT(p.x_begin == m.x0, &p);
  FUZZ_CHECK_AT(p.v_begin == m.v0, &p);
  if (skipped > 0) return;  // an exact start, yet something skipped: no direction checks
  const int s = frictionref::slip_sign(p.kind);
  if (m.v0 > 0) FUZZ_CHECK_AT(s == 1, &p);
  if (m.v0 < 0) FUZZ_CHECK_AT(s == -1, &p);
  if (m.v0 == 0) {
    // From rest: slip in the force's direction if it clearly beats friction,
    // stick if it is clearly inside the band (section 4.5); a start within
    // the time resolution of a crossing may go either way.
    const long double f = force(m, m.t0);
    const long double margin = 1e-9L * m.friction + 1e-9L * tau_scale(m, m.t0) * m.amplitude;
    if (f > m.friction + margin) FUZZ_CHECK_AT(s == 1, &p);
    if (f < -(m.friction + margin)) FUZZ_CHECK_AT(s == -1, &p);
    if (std::fabs(f) < m.friction - margin) FUZZ_CHECK_AT(s == 0, &p);
  }
}

void run(const Model& model, double t_end, const SolveOptions& options, bool limited) {
  std::optional<ExactEngine> engine;
  try {
    engine.emplace(model, t_end, options);
  } catch (const InvalidInput& error) {
    FUZZ_CHECK(error.what() != nullptr && *error.what() != '\0');
    FUZZ_CHECK(!error.parameter().empty() && !error.rule().empty());
    return;  // a clear validation error: fine
  }
  // Accepted: the inputs must be what the documentation promises.
  FUZZ_CHECK(std::isfinite(model.mass) && model.mass > 0);
  FUZZ_CHECK(std::isfinite(model.amplitude) && model.amplitude >= 0);
  FUZZ_CHECK(std::isfinite(model.omega) && model.omega > 0);
  FUZZ_CHECK(std::isfinite(model.friction) && model.friction >= 0);
  FUZZ_CHECK(std::isfinite(model.x0) && std::isfinite(model.v0) && std::isfinite(model.t0));
  FUZZ_CHECK(std::isfinite(t_end) && t_end > model.t0);
  FUZZ_CHECK(model.static_limit() >= model.friction);
  FUZZ_CHECK(std::isfinite(model.stiffness) && model.stiffness >= 0);
  FUZZ_CHECK(std::isfinite(model.damping) && model.damping >= 0);
  FUZZ_CHECK(std::isfinite(model.force_offset));
  for (const auto& h : model.harmonics)
    FUZZ_CHECK(std::isfinite(h.amplitude) && std::isfinite(h.phase) && h.omega > 0);

  const bool general = !model.is_harmonic_coulomb();
  const GeneralScales scales = general_scales(model, t_end);
  // Periods of the fastest rate of the model (the forcing's for the seed).
  const long double fastest = general ? scales.fast : static_cast<long double>(model.omega);
  const long double periods = (static_cast<long double>(t_end) - model.t0) * fastest / kTwoPi;
  if (!(periods <= kMaxPeriods)) return;  // bound the work per input
  // A record adds a few events per sample interval at most.
  const std::uint64_t max_count =
      kPhasesPerPeriod * (static_cast<std::uint64_t>(std::floor(periods)) + 1) +
      (model.ground_motion ? 8 * model.ground_motion->samples() : 0);
  const bool values = !allowed().overflow || solution_in_double_range(model, t_end);

  Context context{model, t_end, std::nullopt, 0};
  if (limited) context.max_phases = options.max_phases;
  g_context = &context;

  Phase phase, previous;
  std::uint64_t count = 0;
  std::uint64_t by_kind[3] = {0, 0, 0};
  // Phase boundaries the engine has passed: every emitted phase that does not
  // end at the horizon ends in one stop or breakaway, counted in the same
  // next() call. More than that means skipped phases (see check_boundary).
  const auto transitions = [&engine] {
    return engine->summary().stops + engine->summary().breakaways;
  };
  std::uint64_t transitions_before = 0;
  while (engine->next(phase)) {
    context.phase_number = ++count;
    FUZZ_CHECK_AT(count <= max_count, &phase);
    const std::uint64_t now = transitions();
    const std::uint64_t own_end = phase.t_end == t_end ? 0 : 1;
    FUZZ_CHECK_AT(now >= transitions_before + own_end, &phase);
    const std::uint64_t skipped = now - transitions_before - own_end;
    transitions_before = now;
    check_batch(model, phase);
    if (general) {
      check_phase_general(model, scales, phase);
      if (count == 1)
        check_first_general(model, scales, phase, skipped);
      else
        check_boundary_general(model, scales, previous, phase, skipped);
    } else {
      check_phase(model, phase, values);
      if (count == 1)
        check_first(model, phase, values, skipped);
      else
        check_boundary(model, previous, phase, values, skipped);
    }
    ++by_kind[static_cast<int>(phase.kind)];
    previous = phase;
  }

  const frictionref::Summary& summary = engine->summary();
  if (summary.termination == Termination::numerical_failure && allowed().numerical_failure) {
    g_context = nullptr;
    return;
  }
  if (summary.termination == Termination::numerical_failure) {
    std::fprintf(stderr, "engine message: %s\n", summary.message.c_str());
    fail("termination == numerical_failure", __LINE__, count ? &previous : nullptr);
  }
  FUZZ_CHECK(!summary.message.empty());
  FUZZ_CHECK(summary.phases == count);
  FUZZ_CHECK(summary.count(PhaseKind::stick) == by_kind[0]);
  FUZZ_CHECK(summary.count(PhaseKind::slip_forward) == by_kind[1]);
  FUZZ_CHECK(summary.count(PhaseKind::slip_backward) == by_kind[2]);
  // (Stops and breakaways may exceed the phase count: skipped phases have them too.)
  FUZZ_CHECK(summary.reversals <= summary.stops);
  if (summary.termination == Termination::reached_end) {
    FUZZ_CHECK(count >= 1);
    FUZZ_CHECK_AT(previous.t_end == t_end, &previous);
  } else {
    FUZZ_CHECK(summary.termination == Termination::phase_limit);
    FUZZ_CHECK(limited && count == options.max_phases);
    FUZZ_CHECK_AT(previous.t_end < t_end, &previous);
  }
  if (count >= 1) {
    FUZZ_CHECK_AT(summary.final_state.t == previous.t_end, &previous);
    FUZZ_CHECK_AT(summary.final_state.phase == previous.kind, &previous);
  }
  if (count >= 1 && values) {
    FUZZ_CHECK_AT(summary.final_state.x == previous.x_end, &previous);
    FUZZ_CHECK_AT(summary.final_state.v == previous.v_end, &previous);
    FUZZ_CHECK_AT(std::isfinite(summary.final_state.a), &previous);
  }
  FUZZ_CHECK(!summary.brief_report().empty());

  // The steady state of the seed's model (any B > 0): a regime consistent with lambda.
  if (!general && model.amplitude > 0) {
    const frictionref::SteadyState steady = frictionref::steady_state(model);
    FUZZ_CHECK(steady.regime == frictionref::regime_for(model.friction / model.amplitude));
    FUZZ_CHECK(steady.stuck_fraction >= 0 && steady.stuck_fraction <= 1);
    FUZZ_CHECK(!steady.report().empty());
  }
  g_context = nullptr;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  allowed();  // reads FRICTIONREF_FUZZ_ALLOW once, before the first input
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes bytes(data, size);
  const std::uint8_t encoding = bytes.byte();
  const std::uint8_t flags = bytes.byte();
  double field[8];
  for (int i = 0; i < 8; ++i) field[i] = (encoding >> i) & 1 ? bytes.raw_double() : bytes.decimal();

  Model model;
  model.mass = field[0];
  model.amplitude = field[1];
  model.omega = field[2];
  model.friction = flags & 1 ? field[3] * field[1] : field[3];
  model.x0 = field[4];
  model.v0 = flags & 8 ? field[5] * (field[1] / (field[0] * field[2])) : field[5];
  model.t0 = field[6];
  double t_end = field[7];
  switch ((flags >> 1) & 3) {
    case 0:
      break;
    case 1:
      t_end = model.t0 + field[7];
      break;
    default:
      t_end = model.t0 + field[7] * (6.283185307179586 / model.omega);
      break;
  }
  SolveOptions options;
  const bool limited = (flags & 16) != 0;
  if (limited) options.max_phases = bytes.little_endian(2);
  if (flags & 128) options.replay_min_cycles = 1;
  if (flags & 32) {
    const std::uint8_t general = bytes.byte();
    const auto next = [&](int bit) {
      return (general >> bit) & 1 ? bytes.raw_double() : bytes.decimal();
    };
    const double static_field = next(0);
    model.static_friction = (general & 1) ? static_field : model.friction + std::fabs(static_field);
    model.stiffness = next(1);
    model.damping = next(2);
    model.force_offset = next(3);
    const int harmonics = bytes.byte() % 4;
    for (int i = 0; i < harmonics; ++i) {
      frictionref::Harmonic h;
      h.amplitude = next(4);
      h.omega = next(5);
      h.phase = next(6);
      model.harmonics.push_back(h);
    }
  }
  if (flags & 64) {
    const std::size_t samples = 2 + bytes.byte() % 31;
    const std::uint8_t encoding_record = bytes.byte();
    const auto time = [&] { return encoding_record & 1 ? bytes.raw_double() : bytes.decimal(); };
    const auto accel = [&] { return encoding_record & 2 ? bytes.raw_double() : bytes.decimal(); };
    auto record = std::make_shared<frictionref::GroundMotion>();
    record->t.push_back(time());
    record->a.push_back(accel());
    for (std::size_t i = 1; i < samples; ++i) {
      record->t.push_back(record->t.back() + time());
      record->a.push_back(accel());
    }
    record->file = "fuzz";
    record->npts = samples;
    model.ground_motion = record;
    model.one_way = (encoding_record & 4) != 0;
  }

  run(model, t_end, options, limited);
  return 0;
}
