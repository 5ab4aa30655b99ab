// Compares the event times of the engine with the 50-digit reference
// (reference_solver.hpp) and measures the error in ulps of t
// (docs/accuracy.md has the definitions, the grid and the results).
//
// Events are the phase boundaries strictly inside (t0, t_end):
//   stop       a slip ends with v = 0 (followed by a stick or a reversal);
//              classified by the reference acceleration a just before it:
//              regular if |a| >= 1e-3 B/m, near-grazing below;
//   breakaway  a stick ends (closed-form time).
// Limits: 4 ulps for regular stops and breakaways; for near-grazing stops
// the conditioning bound below (grazing_bound) on top of 4 ulps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "reference_solver.hpp"

namespace frictionref::accuracy {

namespace ref = frictionref_reference;
using ref::Real;

// The acceptance limits of the issue.
inline constexpr double kUlpLimit = 4;             // |error| <= 4 ulps of t
inline constexpr double kGrazingAcceleration = 1e-3;  // |a| < 1e-3 B/m: near-grazing
// The near-grazing bound (derivation in docs/accuracy.md). For a stop at
// tau_s = w t_s ending a slip that began at tau_a with speed v_a, in velocity
// units (b = B/(m w), r = R/(m w)), A = |d(s v)/d tau| and q = |d^2(s v)/d tau^2|
// at tau_s, A_a = |d(s v)/d tau| at tau_a:
//   S = |v_a| + b (|cos tau_a| + |cos tau_s|) + r |tau_s - tau_a| + A |tau_s| + A_a |tau_a|
//   E = kEvalError eps_ld S + A_a Delta_a   (Delta_a: the bound of the start)
//   u = 2 q E / A^2
//   lambda < 1, u < 1:  Delta = g(u) E / A,  g(u) = 2 (1 - sqrt(1 - u)) / u in [1, 2]
//   lambda >= 1:        Delta = kMonotoneConditioning E / A  (cubic inflection)
//   u >= 1 (unresolvable: the dip of v may vanish in the noise):
//                       Delta = kDipWidth sqrt(E / q)
// and the allowed error is 4 ulps + Delta / (w ulp(t_s)).
inline constexpr double kEvalError = 4;
inline constexpr double kMonotoneConditioning = 4;
inline constexpr double kDipWidth = 4;

ref::Input to_reference_input(const Model& model);
std::string describe(const Model& model);

// Spacing of doubles at |t|: 2^(e - 53) for 2^(e-1) <= |t| < 2^e (the ulp of
// the double nearest t; the smallest subnormal spacing at 0).
Real ulp_of(const Real& t);

enum class EventKind { stop, breakaway };
const char* to_string(EventKind kind);

struct Event {
  std::size_t index = 0;  // boundary number (0: end of the first phase)
  EventKind kind = EventKind::stop;
  PhaseKind before = PhaseKind::stick, after = PhaseKind::stick;
  double t_engine = 0;
  Real t_reference = 0;
  double error_ulps = 0;  // (t_engine - t_reference) / ulp(t_reference)
  // Stops: reference acceleration just before the stop, in units of B/m
  // (0 for breakaways and when B = 0).
  double accel = 0;
  bool near_grazing = false;  // a stop with |accel| < kGrazingAcceleration
  // Stops: the allowed error in ulps from the conditioning bound (4 + the
  // propagated long double error / |A|), computed for every stop; only
  // applied to near-grazing ones. Breakaways: 4.
  double bound_ulps = kUlpLimit;
  // Near-grazing stops: false when the long double noise could make the
  // velocity's dip vanish (2 |v''| E >= A^2): the stop itself is then not
  // resolvable at the engine's precision.
  bool resolvable = true;
};

struct CaseResult {
  std::string name;
  double t_end = 0;
  std::vector<Event> events;
  bool sequence_matches = true;
  std::string mismatch;  // the first difference of the phase-kind sequences, in words
  std::size_t engine_phases = 0, reference_phases = 0;
  std::size_t normalized_reference = 0;  // reference phases merged/dropped as sub-resolution
  std::size_t normalized_engine = 0;
  std::size_t unresolvable_dips = 0;  // reference stops not resolvable in long double
  std::uint64_t reference_evaluations = 0;
  double engine_seconds = 0, reference_seconds = 0;
};

// Runs both and compares. The reference phases are first brought to the
// engine's output resolution (phase.hpp; the engine decides what happens at
// rest within 8 ulps of a force crossing by the crossing): phases shorter than
// 16 double ulps of max(1, |w t|) in w t, and phases empty in double, are
// dropped, and phases of one kind that become adjacent are merged; the same is applied to the
// engine's phases, so a boundary case is treated alike on both sides. Before
// that, on both sides, phases lying entirely inside the window of a stop that
// is unresolvable in long double (kDipWidth sqrt(E / |v''|) around it) are
// dropped: there the engine may legitimately see a touch instead of a stop
// and a short excursion, or the reverse.
CaseResult compare(const Model& model, double t_end, const ref::Options& options = {});
CaseResult compare(const Model& model, double t_end, const Solution& engine,
                   const ref::Result& reference);

// Max and RMS of |error| in ulps, with the worst case, in the manner of
// Boost.Math's handle_test_result.
class Stats {
 public:
  void add(const CaseResult& result, bool (*select)(const Event&));
  std::size_t count() const { return count_; }
  double max_ulps() const { return max_; }
  double rms_ulps() const;
  double max_bound_ratio() const { return max_ratio_; }  // max |error| / bound_ulps
  std::string report(const std::string& title) const;

 private:
  std::size_t count_ = 0;
  std::size_t above_half_ = 0;  // not correctly rounded
  double max_ = 0, sum_squares_ = 0, max_ratio_ = 0;
  std::string worst_, worst_ratio_;
};

bool regular_stop(const Event& e);
bool near_grazing_stop(const Event& e);
bool breakaway(const Event& e);
bool any_event(const Event& e);

// One line per event: index, kind, engine t, reference t, error, accel, bound.
std::string event_line(const Event& e);

}  // namespace frictionref::accuracy
