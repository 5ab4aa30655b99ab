// The event loop of the exact engine (docs/theory.md 3 and 7): one state
// machine for every model. It alternates stick and slip phases, asks the
// model's family of phase laws where each one ends, and emits the phases in
// the output type. It knows nothing of the forcing or the structure; the
// family does, behind this interface (a compile-time concept):
//
//   Family(const BasicModel<Real>& model, const Real& t_end, const Work& tau0,
//          const Work& tau_end, BasicSummary<Real>& summary)
//       validates the range of the motion (throws InvalidInput) and keeps
//       `summary` to count its work (sign tests, root calls, touches, ...).
//   int direction_at_rest(const Work& tau, const Work& x)
//       at v = 0: +1 / -1 if the mass slides that way at once, 0 if it sticks.
//   Breakaway<Work> stick_end(const Work& tau, const Work& x)
//       the first breakaway after tau of a stick at x, before tau_end.
//   SlipEnd<Work> slip_end(const PhaseStart<Work>& start)
//       the first stop of the slip (v = 0) before tau_end, or the state at
//       tau_end; throws RootFailure if a root solver failed.
//
// A family may also replay its steady motion (the seed's, with dead bands or
// sliding continuously: laws/harmonic_coulomb/cycle_replay.hpp), through
//   CycleReplay& cycle_replay()
//       with start(min_cycles) at each breakaway and reversal (true: replay
//       from here), then next(ReplayedPhase&) for every phase to the horizon.
//
// Time is the forcing phase tau = w t (w = model.omega) in the work type;
// phases are emitted in user time.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "engine/engine_core.hpp"
#include "engine/scalar_traits.hpp"
#include "numeric/first_zero.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"

namespace frictionref::detail {

template <class Work>
struct PhaseStart {
  Work tau;  // forcing phase w t
  Work x;
  Work v;    // 0 after a stop or breakaway; v0 at the start
  int sign;  // slip direction, +1 or -1
};

template <class Work>
struct Breakaway {
  bool found = false;  // false: the stick lasts to tau_end
  Work tau = 0;
  int direction = 0;
};

template <class Work>
struct SlipEnd {
  bool stops = false;  // v reached 0 before tau_end
  Work tau = 0;        // the stop, or tau_end
  Work x = 0;
  Work v = 0;                // 0 at a stop
  Work acceleration = 0;     // left limit at tau
  int next_direction = 0;    // after a stop: +1 / -1 slides on at once, 0 sticks
};

// A phase of a replayed cycle, rounded to Real: it starts at rest where the
// phase before ended, and ends at a stop or breakaway (v = 0) or at the
// horizon, which ends the run.
template <class Real>
struct ReplayedPhase {
  PhaseKind kind = PhaseKind::stick;
  Real t_end = 0, x_end = 0, v_end = 0;
  Real acceleration = 0;  // left limit at the end
  // What ends it (counted in the summary), or the horizon.
  bool stop = false, reversal = false, breakaway = false, at_horizon = false;
  int rounded_in_50_digits = 0;  // of t_end and x_end (the rest in double-double)
};

template <class Family, class = void>
struct replays_cycles : std::false_type {};
template <class Family>
struct replays_cycles<Family, std::void_t<decltype(std::declval<Family&>().cycle_replay())>>
    : std::true_type {};

template <class Real, class Family>
class EventLoop final : public EngineCore<Real> {
 public:
  using Work = work_t<Real>;
  using Traits = ScalarTraits<Real>;

  EventLoop(const BasicModel<Real>& model, const Real& t_end, const SolveOptions& options);

  bool next(BasicPhase<Real>& phase) override;
  const BasicSummary<Real>& summary() const override { return summary_; }
  const BasicModel<Real>& model() const override { return model_; }
  const Real& t_end() const override { return t_end_; }
  // The family's own state (for tests: a replay's base).
  const Family& family() const { return family_; }

 private:
  enum class Mode { stick, slip };

  // Ends the run with Termination::numerical_failure; returns false.
  bool fail(RootStatus status, const char* what);
  // Fills `phase` unless it is shorter than the resolution of Real.
  bool emit(BasicPhase<Real>& phase, PhaseKind kind, const Work& tau_end, const Work& x_end,
            const Work& v_end, const Work& acceleration, bool at_horizon);
  // Emits a phase of a replayed cycle.
  void emit_replayed(BasicPhase<Real>& phase, const ReplayedPhase<Real>& replayed);
  // Counts an emitted phase in the summary and moves the current time to its end.
  void account(const BasicPhase<Real>& phase, const Real& acceleration);
  static const BasicModel<Real>& validated(const BasicModel<Real>& model);
  static Work validated_tau(const BasicModel<Real>& model, const Real& t_end);

  BasicModel<Real> model_;
  Real t_end_;
  SolveOptions options_;
  BasicSummary<Real> summary_;
  Work omega_;
  Work tau_end_;
  Family family_;
  Real t_current_;    // user time of tau_ as emitted (t0 exactly at the start)
  Work tau_, x_, v_;  // current phase start
  Mode mode_ = Mode::stick;
  int sign_ = 0;  // slip direction when mode_ == slip
  bool done_ = false;
  bool replaying_ = false;  // the family's cycle replay emits the phases
  Real replayed_x_ = 0;     // x at the end of the last replayed phase
};

// Checks in the order the messages have always come (docs/reliability.md):
// the model, the options, t_end, then the family's range, then the phases.
template <class Real, class Family>
const BasicModel<Real>& EventLoop<Real, Family>::validated(const BasicModel<Real>& model) {
  model.validate();
  return model;
}

template <class Real, class Family>
auto EventLoop<Real, Family>::validated_tau(const BasicModel<Real>& model, const Real& t_end)
    -> Work {
  using std::isfinite;
  if (!isfinite(t_end)) throw InvalidInput("t_end", to_text(t_end), "must be a finite number");
  if (!(t_end > model.t0))
    throw InvalidInput("t_end", to_text(t_end), "must be > t0 = " + to_text(model.t0));
  return Work(model.omega) * Work(t_end);
}

template <class Real, class Family>
EventLoop<Real, Family>::EventLoop(const BasicModel<Real>& model, const Real& t_end,
                                   const SolveOptions& options)
    : model_(validated(model)),
      t_end_(t_end),
      options_((options.validate(), options)),
      omega_(Work(model.omega)),
      tau_end_(validated_tau(model, t_end)),
      family_(model_, t_end_, omega_ * Work(model.t0), tau_end_, summary_) {
  using std::fabs;
  tau_ = omega_ * Work(model.t0);
  const Work max_phase(Traits::max_forcing_phase);
  // (A literal, not a std::string: engines are built by the million in sweeps.)
  constexpr const char* phase_rule = "must satisfy |w t| <= 1e10 rad (a double cannot resolve "
                                     "the forcing phase beyond that)";
  if (fabs(tau_) > max_phase) throw InvalidInput("t0", to_text(model.t0), phase_rule);
  if (fabs(tau_end_) > max_phase) throw InvalidInput("t_end", to_text(t_end), phase_rule);
  // Nothing shorter than the time resolution is resolved (phases that short
  // are merged), so a shorter horizon has no answer the engine can give.
  if (!(tau_end_ - tau_ > Traits::time_resolution(tau_)))
    throw InvalidInput(
        "t_end", to_text(t_end),
        "must exceed t0 by more than the engine's time resolution 8 eps max(1, |w t0|) / w = " +
            to_text(Real(Traits::time_resolution(tau_) / omega_)));
  t_current_ = model.t0;
  x_ = Work(model.x0);
  v_ = Work(model.v0);
  sign_ = model.v0 > 0 ? 1 : model.v0 < 0 ? -1 : family_.direction_at_rest(tau_, x_);
  mode_ = sign_ != 0 ? Mode::slip : Mode::stick;
  summary_.final_state = {model.t0, model.x0, model.v0, 0, PhaseKind::stick};
}

template <class Real, class Family>
bool EventLoop<Real, Family>::emit(BasicPhase<Real>& phase, PhaseKind kind, const Work& tau_end,
                                   const Work& x_end, const Work& v_end,
                                   const Work& acceleration, bool at_horizon) {
  const Real t_end = at_horizon ? t_end_ : Real(tau_end / omega_);
  if (!(t_end > t_current_)) return false;  // shorter than the output resolution
  phase.kind = kind;
  phase.t_begin = t_current_;
  phase.t_end = t_end;
  phase.x_begin = Real(x_);
  phase.x_end = Real(x_end);
  phase.v_begin = Real(v_);
  phase.v_end = Real(v_end);
  account(phase, Real(acceleration));
  return true;
}

template <class Real, class Family>
void EventLoop<Real, Family>::account(const BasicPhase<Real>& phase, const Real& acceleration) {
  t_current_ = phase.t_end;
  ++summary_.phases;
  ++summary_.phases_by_kind[static_cast<int>(phase.kind)];
  summary_.final_state = {phase.t_end, phase.x_end, phase.v_end, acceleration, phase.kind};
}

template <class Real, class Family>
void EventLoop<Real, Family>::emit_replayed(BasicPhase<Real>& phase,
                                            const ReplayedPhase<Real>& replayed) {
  phase.kind = replayed.kind;
  phase.t_begin = t_current_;
  phase.t_end = replayed.t_end;
  phase.x_begin = replayed_x_;
  phase.x_end = replayed.x_end;
  phase.v_begin = 0;
  phase.v_end = replayed.v_end;
  account(phase, replayed.acceleration);
  replayed_x_ = replayed.x_end;
  summary_.stops += replayed.stop;
  summary_.reversals += replayed.reversal;
  summary_.breakaways += replayed.breakaway;
  ++summary_.replayed_phases;
  summary_.replay_values_in_50_digits += static_cast<std::uint64_t>(replayed.rounded_in_50_digits);
  if (replayed.at_horizon) done_ = true;
}

template <class Real, class Family>
bool EventLoop<Real, Family>::fail(RootStatus status, const char* what) {
  done_ = true;
  summary_.termination = Termination::numerical_failure;
  summary_.message = (status == RootStatus::lost_bracket ? "lost the root bracket of "
                                                         : "the event search or root solver hit "
                                                           "its iteration cap for ") +
                     std::string(what) + " after t = " + to_text(Real(tau_ / omega_)) +
                     " (please report this model)";
  return false;
}

template <class Real, class Family>
bool EventLoop<Real, Family>::next(BasicPhase<Real>& phase) {
  // Phases too short to show in Real are skipped; a run of them means the
  // engine is not advancing, which must end in a status, never a hang.
  for (int skipped = 0; !done_; ++skipped) {
    if (skipped > 16) {
      done_ = true;
      summary_.termination = Termination::numerical_failure;
      summary_.message = "no progress at t = " + to_text(Real(tau_ / omega_)) +
                         ": phases shorter than the time resolution repeat";
      return false;
    }
    if (summary_.phases >= options_.max_phases) {
      done_ = true;
      summary_.termination = Termination::phase_limit;
      summary_.message = "stopped after max_phases = " + std::to_string(options_.max_phases) +
                         " phases, before t_end";
      return false;
    }
    if constexpr (replays_cycles<Family>::value) {
      if (replaying_) {  // to the horizon
        ReplayedPhase<Real> replayed;
        family_.cycle_replay().next(replayed);
        emit_replayed(phase, replayed);
        return true;
      }
    }
    if (mode_ == Mode::stick) {
      Breakaway<Work> breakaway;
      try {
        breakaway = family_.stick_end(tau_, x_);
      } catch (const RootFailure& failure) {
        return fail(failure.status, "a stick end");
      } catch (const SearchStalled&) {
        return fail(RootStatus::iteration_cap, "a stick end");
      }
      // A breakaway that rounds to t_end in Real is at the horizon.
      const bool breaks = breakaway.found && breakaway.tau < tau_end_ &&
                          Real(breakaway.tau / omega_) < t_end_;
      const Work end = breaks ? breakaway.tau : tau_end_;
      const bool emitted = emit(phase, PhaseKind::stick, end, x_, Work(0), Work(0), !breaks);
      if (breaks) {
        ++summary_.breakaways;
        mode_ = Mode::slip;
        sign_ = breakaway.direction;
        tau_ = breakaway.tau;
        v_ = 0;
        if constexpr (replays_cycles<Family>::value) {
          replaying_ = family_.cycle_replay().start(options_.replay_min_cycles);
          replayed_x_ = Real(x_);
        }
      } else {
        done_ = true;
      }
      if (emitted) return true;
      continue;
    }

    const PhaseKind kind = sign_ > 0 ? PhaseKind::slip_forward : PhaseKind::slip_backward;
    SlipEnd<Work> end;
    try {
      end = family_.slip_end(PhaseStart<Work>{tau_, x_, v_, sign_});
    } catch (const RootFailure& failure) {
      return fail(failure.status, "a slip end");
    } catch (const SearchStalled&) {
      return fail(RootStatus::iteration_cap, "a slip end");
    }
    // A stop that rounds to t_end in Real ends the run there (found by
    // fuzzing: with max_phases it was reported as a phase limit).
    const bool at_horizon =
        !end.stops || end.tau >= tau_end_ || !(Real(end.tau / omega_) < t_end_);
    const bool emitted = emit(phase, kind, end.tau, end.x, end.v, end.acceleration, at_horizon);
    if (at_horizon) {
      done_ = true;
    } else {
      ++summary_.stops;
      const bool reverses = end.next_direction == -sign_;
      if (reverses) ++summary_.reversals;
      mode_ = end.next_direction != 0 ? Mode::slip : Mode::stick;
      sign_ = end.next_direction;
      tau_ = end.tau;
      x_ = end.x;
      v_ = 0;
      if constexpr (replays_cycles<Family>::value) {
        if (reverses) {
          replaying_ = family_.cycle_replay().start(options_.replay_min_cycles);
          replayed_x_ = Real(x_);
        }
      }
    }
    if (emitted) return true;
  }
  if (summary_.termination == Termination::reached_end && summary_.message.empty())
    summary_.message = "reached t_end";
  return false;
}

}  // namespace frictionref::detail
