// Checking another code's time history against the exact solution: the
// velocity error, the stick intervals (dead bands) it shows, the regime, and
// the displacement; each judged against a tolerance, with a PASS, FAIL or
// INCONCLUSIVE verdict and a diagnosis of the likeliest defect
// (docs/cross-checking.md).
//
// Principle: every feature of the candidate is compared with the same feature
// extracted the same way from the exact solution at the candidate's own times
// (one pass of the engine). So a stick that starts or ends between two
// samples, or a breakaway whose velocity creeps up through the threshold,
// biases both alike. What no sample can see is judged from the engine's own
// phases: PASS needs the samples to resolve every exact phase and event. The
// creep check and the diagnosis read those phases too.
//
// Scales (motion_scales.hpp): velocities are judged relative to B/(m w),
// displacements relative to B/(m w^2) and times relative to the forcing
// period 2 pi / w, so the default tolerances mean the same for every
// consistent set of units. Under a ground-motion record the same roles are
// played by its peak ground velocity PGV, PGV^2/PGA and T* = 2 pi PGV/PGA
// (the three coincide for a harmonic ground acceleration); in the comments
// below, read B/(m w) as "the velocity scale", and so on.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frictionref/classification.hpp"
#include "frictionref/model.hpp"
#include "frictionref/motion_scales.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/time_history.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

struct CompareOptions {
  // Stick detection: the candidate is "at rest" while |v| < stick_threshold *
  // B/(m w), and a rest counts as a stick if it lasts at least
  // min_stick_duration periods. Also the creep limit inside exact sticks.
  double stick_threshold = 1e-3;     // [B/(m w)]; finite, > 0
  double min_stick_duration = 0.01;  // [periods 2 pi / w]; finite, >= 0

  double velocity_max_tolerance = 0.02;  // max |v - v_exact| [B/(m w)]; finite, >= 0
  double velocity_rms_tolerance = 0.01;  // time-weighted RMS of v - v_exact [B/(m w)]; finite, >= 0
  double stop_time_tolerance = 0.01;     // |start/end error| of each matched stick, and the margin
                                         // at both ends of an exact stick for the creep check
                                         // [periods]; finite, >= 0
  std::uint64_t max_missed_stops = 0;    // exact sticks the candidate may lack
  std::uint64_t max_extra_stops = 0;     // candidate sticks the exact solution may lack
  double displacement_max_tolerance = 0.02;  // max |x - x_exact| [B/(m w^2)], only when the
                                             // history has x; finite, >= 0
  double regime_window = 2;  // the regime shown is read from the last this many periods
                             // (or the whole record if shorter) [periods]; finite, > 0

  // Throws InvalidInput naming the first field that breaks its rule.
  void validate() const;
};

// The checks, in report order.
enum class CheckKind {
  velocity_max,      // max |v - v_exact| <= velocity_max_tolerance
  velocity_rms,      // RMS(v - v_exact) <= velocity_rms_tolerance
  displacement_max,  // max |x - x_exact| <= displacement_max_tolerance (only with x)
  stop_times,        // every matched stick starts and ends within stop_time_tolerance
  missed_stops,      // exact sticks without a candidate stick <= max_missed_stops
  extra_stops,       // candidate sticks without an exact stick <= max_extra_stops
  creep,             // inside every exact stick (less the margins) |v| < stick threshold
  regime,            // the regime the candidate shows = the one the exact solution shows
};

enum class Verdict {
  pass,          // every check passed, and the samples resolve the exact motion
  fail,          // at least one check failed
  inconclusive,  // every check passed, but the samples cannot see part of the exact
                 // motion (ComparisonReport::unresolved): a defect there would pass too
};

// The most likely class of defect behind a verdict, named first in every
// report (docs/cross-checking.md, "The diagnosis").
enum class Defect {
  none,              // PASS: nothing to name
  unresolved,        // INCONCLUSIVE: the samples do not see part of the exact motion
  time_shift,        // the candidate is the exact motion late (or early) by a constant time
  scale,             // v = s v_exact with s != 1 (units, amplitude, mass)
  chattering,        // v flips sign, sample after sample, inside the exact sticks
  creep,             // v small but not zero inside the exact sticks (regularised friction)
  missed_breakaway,  // at rest where the exact mass breaks away and slides
  missed_stop,       // sliding on where the exact mass stops and sticks
  drift,             // a displacement error growing with time (a velocity bias)
  offset,            // a constant displacement error (x0, or another reference)
  unclassified,      // FAIL, and no single class above explains it
};

struct Diagnosis {
  Defect defect = Defect::none;
  // time_shift: the shift [time] (> 0: the candidate is late, v(t) = v_exact(t - shift));
  // scale: the factor s; drift: the velocity bias [length/time]; offset: [length];
  // chattering, creep, missed_breakaway, missed_stop: how many exact phases show it;
  // none, unresolved, unclassified: 0.
  double value = 0;
  std::string evidence;  // the measurements that point at it, in words

  // "time shift: ..." (the class in words, then the evidence).
  std::string text() const;
};

// "none", "unresolved", "time_shift", "scale", "chattering", "creep",
// "missed_breakaway", "missed_stop", "drift", "offset", "unclassified"
std::string_view to_string(Defect defect);
std::optional<Defect> defect_from_string(std::string_view text);

// "velocity_max", "velocity_rms", "displacement_max", "stop_times",
// "missed_stops", "extra_stops", "creep", "regime"
std::string_view to_string(CheckKind kind);
// "PASS", "FAIL", "INCONCLUSIVE"
std::string_view to_string(Verdict verdict);
std::optional<CheckKind> check_kind_from_string(std::string_view text);
std::optional<Verdict> verdict_from_string(std::string_view text);

// A time interval where |v| stayed under the stick threshold, from samples.
struct StickInterval {
  double start = 0;  // where the motion stopped: v extrapolated linearly to zero from the
                     // last two moving samples, kept between the last moving and the first
                     // resting sample (else where |v| crossed the threshold, interpolated);
                     // or the first time of the record [time]
  double end = 0;    // where |v| rose above the threshold again (linear interpolation
                     // between the two samples around it), or the last time of the record [time]
  std::size_t first_row = 0;  // first sample under the threshold (0-based row)
  std::size_t last_row = 0;   // last sample under the threshold

  double duration() const { return end - start; }
};

// A stick the exact solution and the candidate both show.
struct MatchedStick {
  std::size_t number = 0;   // 1-based position among the exact sticks (report order)
  StickInterval exact;      // detected in the exact velocity at the candidate's times
  StickInterval candidate;  // detected in the candidate's velocity
  double start_error = 0;   // candidate.start - exact.start [time]
  double end_error = 0;     // candidate.end - exact.end [time]
  double phase_start = 0;   // the exact stick phase (engine) inside it: its start [time];
                            // NaN if there is none (|v| small without stopping)
  double phase_end = 0;     // ... its end [time]; NaN if none
};

// A part of the exact motion that the candidate's samples do not resolve
// (docs/cross-checking.md, "What compare can and cannot see").
struct UnresolvedPart {
  enum class Kind {
    phase,  // an exact phase longer than the stop-time tolerance holds no sample
    event,  // the samples around an exact event are further apart than that tolerance
  };
  Kind kind = Kind::phase;
  PhaseKind phase = PhaseKind::stick;  // the phase, or (event) the phase that begins there
  double start = 0;                    // the phase's start, or the event's time [time]
  double end = 0;                      // the phase's end, or the event's time [time]
  double spacing = 0;                  // the distance between the samples around it [time]
};

// One verdict on one property.
struct Check {
  CheckKind kind = CheckKind::velocity_max;
  bool passed = true;
  double value = 0;      // what was measured, in the unit of the tolerance
  double tolerance = 0;  // the limit it was held to
  std::string message;   // what was measured and where (time, interval), in words

  std::string_view name() const { return to_string(kind); }
};

struct ComparisonReport {
  Model model;             // the exact problem
  CompareOptions options;  // as used
  std::string source;      // TimeHistory::source
  std::size_t rows = 0;    // candidate samples
  double t_first = 0;      // first and last candidate time [time]
  double t_last = 0;
  double max_spacing = 0;  // largest gap between consecutive candidate times [time]

  // Scales and the options in absolute units.
  MotionScales scales;  // B/(m w), B/(m w^2), 2 pi / w; or a record's PGV, PGV^2/PGA, T*
  double stick_velocity = 0;      // stick_threshold * velocity_scale [length/time]
  double min_stick_time = 0;      // min_stick_duration * period [time]
  double stop_time_margin = 0;    // stop_time_tolerance * period [time]

  // Velocity error v - v_exact at the candidate's times.
  double velocity_max_error = 0;       // max |v - v_exact| [length/time]
  double velocity_max_error_time = 0;  // where (first of equal maxima) [time]
  double velocity_rms_error = 0;       // sqrt(integral of (v - v_exact)^2 dt / (t_last - t_first))
                                       // by the trapezoidal rule [length/time]
  bool has_displacement = false;       // the history has x
  double displacement_max_error = 0;   // max |x - x_exact| [length]; 0 without x
  double displacement_max_error_time = 0;  // where [time]
  double displacement_rms_error = 0;       // as velocity_rms_error [length]

  // Sticks.
  std::vector<StickInterval> exact_phases;      // the engine's stick phases over the record
                                                // (start = phase t_begin, end = t_end; rows unused)
  std::vector<StickInterval> exact_sticks;      // detected in the exact velocity
  std::vector<StickInterval> candidate_sticks;  // detected in the candidate's velocity
  std::vector<MatchedStick> matched;
  std::vector<StickInterval> missed;  // exact sticks without a candidate stick
  std::vector<StickInterval> extra;   // candidate sticks without an exact stick
  double creep_max_velocity = 0;      // max |v| inside the exact sticks less the margins
                                      // [length/time]; 0 if no sample falls there
  double creep_time = 0;              // where [time]
  std::size_t creep_samples = 0;      // candidate samples inside those intervals

  // Regime over [regime_window_start, t_last].
  double regime_window_start = 0;       // [time]
  Regime exact_regime = Regime::stops;  // classify(model).regime: the steady state
  ClassificationMethod exact_regime_method = ClassificationMethod::closed_form;  // how it was found
  Regime exact_shown_regime = Regime::stops;  // what the exact motion shows in the window
  Regime candidate_regime = Regime::stops;    // what the candidate shows in the window:
                                              // stops if at rest throughout, dead-bands if
                                              // any stick in it, continuous otherwise
  double exact_stops_per_period = 0;          // sticks in the window / window length in periods
  double candidate_stops_per_period = 0;

  std::vector<Check> checks;  // in CheckKind order; displacement_max only with x

  // Resolution: whether the samples can see every exact phase and event. The
  // first 100 unresolved parts in time order, and how many there are of each.
  std::vector<UnresolvedPart> unresolved;
  std::size_t unresolved_phases = 0;
  std::size_t unresolved_events = 0;
  double resolving_step = 0;  // an archive step that resolves them all [time]; 0 if none needed

  Diagnosis diagnosis;  // the most likely defect behind the verdict

  Verdict verdict = Verdict::pass;  // fail if a check failed; else inconclusive if anything
                                    // is unresolved; else pass
  std::vector<std::string> notes;   // remarks that are not checks (sampling, short record)

  // What is unresolved, for people: counts and the first few parts, e.g.
  // "2 exact phases hold no sample: slip+ [12.1, 12.4] (samples 5 apart), ...".
  std::string resolution_text() const;
  // "archive at most every 0.0314 (half the shortest ...)" or why no step can.
  std::string resolution_advice() const;

  // Names of the failed checks, in order.
  std::vector<std::string> failed_checks() const;
  // "diagnosis: <class>: <evidence>", then one line per check,
  // "<name>: PASS <message>" or "<name>: FAIL <message>", then (when something
  // is unresolved) "resolution: ...", then "verdict: PASS", "verdict: FAIL
  // (checks a, b)" or "verdict: INCONCLUSIVE (...)".
  std::string brief_report() const;
  // Everything for people: the diagnosis line, candidate, model, scales,
  // tolerances, errors, the stick table (up to 50 rows), the regime, notes,
  // then the checks and the verdict as in brief_report().
  std::string full_report() const;
};

// Compares `history` with the exact solution of `model`. Throws InvalidInput
// for an invalid model, options or history, an amplitude B = 0 (the scales
// are relative to B), or a history that starts before model.t0.
ComparisonReport compare(const Model& model, const TimeHistory& history,
                         const CompareOptions& options = {});

// The stick detector used on both sides: maximal runs of samples with
// |v| < threshold lasting at least min_duration (interpolated ends).
std::vector<StickInterval> detect_sticks(const std::vector<double>& t, const std::vector<double>& v,
                                         double threshold, double min_duration);

}  // namespace frictionref
