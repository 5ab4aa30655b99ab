// Replaying the seed's steady motion (docs/theory.md 3.9, 3.10).
//
// The family reports every stop, reversal and breakaway here, and the event
// loop asks at each breakaway and reversal whether to replay from it:
// - with dead bands (steady_cycle.hpp), at a breakaway, when the cycle just
//   finished (from the breakaway before) has the phases of the 50-digit
//   cycle, every phase of that cycle is far longer than the time resolution
//   at t_end, and enough whole cycles remain;
// - sliding continuously (converging_cycle.hpp), at a reversal within
//   2^-44 rad of the fixed point of the reversal map, when enough whole
//   periods remain.
// The replay then hands the loop every following phase to the horizon, the
// last one included (its state at t_end from the 50-digit law).
#pragma once

#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "engine/event_loop.hpp"
#include "engine/scalar_traits.hpp"
#include "frictionref/model.hpp"
#include "laws/harmonic_coulomb/converging_cycle.hpp"
#include "laws/harmonic_coulomb/force_crossings.hpp"
#include "laws/harmonic_coulomb/steady_cycle.hpp"

namespace frictionref::detail {

template <class Real>
class CycleReplay {
 public:
  using Work = work_t<Real>;

  CycleReplay() = default;
  // alpha as the engine keeps it (its breakaway times are alpha + k pi).
  CycleReplay(const BasicModel<Real>& model, const Real& t_end, bool crosses, const Work& alpha,
              const Work& tau_end)
      : model_(&model), crosses_(crosses), alpha_(alpha), t_end_(t_end), tau_end_(tau_end) {}

  // A slip of this kind stopped at tau with x, then `next_direction` (0: a
  // stick); `clean`: no touch and no merged stick on the way (either makes
  // the cycle fragile to rounding).
  void observe_stop(PhaseKind kind, const Work& tau, const Work& x, bool clean,
                    int next_direction) {
    at_reversal_ = clean && next_direction != 0 &&
                   next_direction != (kind == PhaseKind::slip_forward ? 1 : -1);
    if (at_reversal_) {
      reversal_tau_ = tau;
      reversal_x_ = x;
      reversal_direction_ = next_direction;
    }
    if (!watching() || !open_) return;
    clean_ = clean_ && clean;
    append(kind, tau, x);
  }

  // A stick at x ended in a breakaway at tau in `direction`: closes the cycle
  // since the breakaway before and opens the next one.
  void observe_breakaway(const Work& tau, const Work& x, int direction) {
    at_reversal_ = false;
    if (!watching()) return;
    if (open_) append(PhaseKind::stick, tau, x);
    closed_ = open_ && clean_ && count_[current_] <= kMaxPhases;
    closed_start_tau_ = start_tau_;
    closed_start_x_ = start_x_;
    closed_direction_ = direction_;
    current_ ^= 1;
    count_[current_] = 0;
    open_ = true;
    clean_ = true;
    start_tau_ = tau;
    start_x_ = x;
    direction_ = direction;
  }

  // At the breakaway or reversal just observed: true to replay from it.
  bool start(std::uint64_t min_cycles) {
    if (at_reversal_) return start_sliding(min_cycles);
    if constexpr (!std::is_same_v<Real, double>) {
      (void)min_cycles;
      return false;  // no wider type to compute the cycle in
    } else {
      if (min_cycles == 0 || disabled_ || !closed_ || !crosses_) return false;
      using std::fabs;
      const Work pi = boost::math::constants::pi<Work>();
      const Work turns = (start_tau_ - closed_start_tau_) / pi;
      const std::int64_t j = std::llround(turns);
      if (j < 1 || fabs(turns - Work(j)) > Work(1e-3)) return false;
      const Work whole = (tau_end_ - start_tau_) / (Work(j) * pi);
      if (!(whole >= Work(min_cycles))) return false;
      if (!cycle_) {
        cycle_ = SteadyCycle::compute(*model_);
        if (!cycle_) return disable();
      }
      if (cycle_->half_turns() != j || !matches()) return disable();
      // Every phase stays far above the time resolution to the horizon.
      if (!(cycle_->shortest() > HighPrecision(64 * ScalarTraits<Real>::time_resolution(tau_end_))))
        return disable();
      // The replay counts its cycles from the start of the one just closed
      // (its cycle 0, already emitted): the exact continuation from the x
      // there, not from the x here, which carries that cycle's rounding.
      n0_ = std::llround((closed_start_tau_ - alpha_) / pi);
      if ((n0_ % 2 == 0) != (closed_direction_ > 0)) return disable();
      x0_ = closed_start_x_;
      cycle_index_ = 1;
      phase_index_ = 0;
      replayed_ = true;
      return true;
    }
  }

  // Whether a replay started, and from where (for tests); every replayed
  // value is the correctly rounded one of the exact motion from there.
  // With dead bands its cycle 0 (observed, not replayed) starts at the
  // breakaway alpha + base_turns() pi with x = base_x(), v = 0; sliding
  // continuously (sliding()) the replay starts at the reversal at forcing
  // phase base_tau() with x = base_x(), v = 0.
  bool replayed() const { return replayed_; }
  bool sliding() const { return sliding_; }
  std::int64_t base_turns() const { return n0_; }
  const Work& base_x() const { return x0_; }
  const Work& base_tau() const { return base_tau_; }
  std::size_t cycle_length() const { return cycle_ ? cycle_->size() : 0; }

  // The next replayed phase, up to the one at the horizon (at_horizon), the
  // last one.
  void next(ReplayedPhase<Real>& out) {
    if constexpr (std::is_same_v<Real, double>) {
      if (sliding_) return next_sliding(out);
      if (phase_index_ == 0) shift_ = cycle_->shift(n0_, x0_, cycle_index_);
      const SteadyCycle::Phase& phase = cycle_->phase(phase_index_);
      const SteadyCycle::End end = cycle_->end(shift_, phase_index_);
      out.kind = end.kind;
      if (!(end.t < t_end_)) {
        // The horizon falls in this phase (or its end rounds to it).
        const SteadyCycle::Horizon at = cycle_->horizon(shift_, phase_index_, t_end_);
        return at_horizon(out, at.x, at.v, at.acceleration);
      }
      ended(out, end.t, end.x, end.acceleration, end.rounded_in_50_digits);
      out.stop = phase.stop;
      out.reversal = phase.reversal;
      out.breakaway = phase.breakaway;
      if (++phase_index_ == cycle_->size()) {
        phase_index_ = 0;
        ++cycle_index_;
      }
    } else {
      (void)out;
    }
  }

 private:
  static constexpr std::size_t kMaxPhases = 32;
  struct Seen {
    PhaseKind kind;
    Work tau, x;
  };

  void append(PhaseKind kind, const Work& tau, const Work& x) {
    std::size_t& count = count_[current_];
    if (count < kMaxPhases) seen_[current_][count] = {kind, tau, x};
    ++count;
  }

  // At a reversal: replay the continuous sliding from here if it is near
  // enough its fixed point (a cheap test in the work type first).
  bool start_sliding(std::uint64_t min_cycles) {
    if constexpr (!std::is_same_v<Real, double>) {
      (void)min_cycles;
      return false;
    } else {
      if (min_cycles == 0 || sliding_disabled_) return false;
      using std::fabs;
      const Work pi = boost::math::constants::pi<Work>();
      if (!(fabs(tau_end_ - reversal_tau_) >= 2 * pi * Work(min_cycles))) return disable_sliding();
      if (!fixed_known_) {
        const Work omega = Work(model_->omega);
        fixed_phase_ = ConvergingCycle::fixed_phase(
            Work(model_->amplitude) / (Work(model_->mass) * omega),
            Work(model_->friction) / (Work(model_->mass) * omega));
        fixed_known_ = true;
        if (!model_->is_harmonic_coulomb() || std::isnan(fixed_phase_)) return disable_sliding();
      }
      const Work turns = std::nearbyint((reversal_tau_ - fixed_phase_) / pi);
      const Work deviation = reversal_tau_ - turns * pi - fixed_phase_;
      if (!(fabs(deviation) <= Work(2 * ConvergingCycle::kMaxDeviation))) return false;
      // Every phase (about half a period) stays far above the time
      // resolution to the horizon.
      if (!(1 > 64 * ScalarTraits<Real>::time_resolution(tau_end_))) return disable_sliding();
      if (!converging_) {
        converging_ = ConvergingCycle::compute(*model_);
        if (!converging_) return disable_sliding();
      }
      if (!converging_->start(reversal_tau_, reversal_x_, reversal_direction_)) return false;
      base_tau_ = reversal_tau_;
      x0_ = reversal_x_;
      replayed_ = sliding_ = true;
      return true;
    }
  }

  bool disable_sliding() {
    sliding_disabled_ = true;
    return false;
  }

  void next_sliding(ReplayedPhase<Real>& out) {
    const ConvergingCycle::End end = converging_->next_end();
    out.kind = end.kind;
    if (!(end.t < t_end_)) {
      const ConvergingCycle::Horizon at = converging_->horizon(t_end_);
      return at_horizon(out, at.x, at.v, at.acceleration);
    }
    ended(out, end.t, end.x, end.acceleration, end.rounded_in_50_digits);
    out.stop = out.reversal = true;
    out.breakaway = false;
    converging_->advance();
  }

  // The phase with the horizon: the event loop's rules there
  // (event_loop.hpp), nothing counted; its values come from 50 digits.
  void at_horizon(ReplayedPhase<Real>& out, double x, double v, double acceleration) const {
    out.t_end = t_end_;
    out.x_end = x;
    out.v_end = v;
    out.acceleration = acceleration;
    out.stop = out.reversal = out.breakaway = false;
    out.at_horizon = true;
    out.rounded_in_50_digits = 0;
  }

  // A phase that ends at rest before the horizon (what ends it: the caller).
  static void ended(ReplayedPhase<Real>& out, double t, double x, double acceleration,
                    int rounded_in_50_digits) {
    out.t_end = t;
    out.x_end = x;
    out.v_end = 0;
    out.acceleration = acceleration;
    out.at_horizon = false;
    out.rounded_in_50_digits = rounded_in_50_digits;
  }

  // Whether a replay may still start: not in the 50-digit engine itself,
  // nor once given up (then nothing is worth recording).
  bool watching() const { return std::is_same_v<Real, double> && !disabled_; }

  bool disable() {
    disabled_ = true;
    return false;
  }

  // The closed cycle against the 50-digit one, to well above rounding: the
  // same phases, kinds and (loosely) times and positions.
  bool matches() const {
    using std::fabs;
    const int closed = current_ ^ 1;
    const std::size_t count = count_[closed];
    if (count != cycle_->size()) return false;
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work time_slack = Work(1e-6) + 64 * eps * fabs(start_tau_);
    for (std::size_t i = 0; i < count; ++i) {
      const Seen& seen = seen_[closed][i];
      const SteadyCycle::Phase& phase = cycle_->phase(i);
      if (seen.kind != (closed_direction_ > 0 ? phase.kind : mirrored(phase.kind))) return false;
      const Work tau = static_cast<Work>(phase.tau_end);
      const Work x = Work(closed_direction_) * static_cast<Work>(phase.x_end);
      if (!(fabs(seen.tau - closed_start_tau_ - tau) <= time_slack)) return false;
      const Work x_slack = Work(1e-6) * (1 + fabs(x)) + 64 * eps * fabs(closed_start_x_);
      if (!(fabs(seen.x - closed_start_x_ - x) <= x_slack)) return false;
    }
    return true;
  }

  const BasicModel<Real>* model_ = nullptr;
  bool crosses_ = false;
  Work alpha_ = 0;
  Real t_end_ = 0;
  Work tau_end_ = 0;

  // The cycles seen: two buffers, the open one and the one just closed.
  std::array<std::array<Seen, kMaxPhases>, 2> seen_{};
  std::array<std::size_t, 2> count_{};
  int current_ = 0;
  bool open_ = false;  // a breakaway has been seen
  bool clean_ = true;
  Work start_tau_ = 0, start_x_ = 0;
  int direction_ = 0;
  bool closed_ = false;  // the cycle just closed may be the steady one
  Work closed_start_tau_ = 0, closed_start_x_ = 0;
  int closed_direction_ = 0;

  // The replay.
  bool disabled_ = false;  // no steady cycle, or it does not match: never again
  bool replayed_ = false;
  std::optional<SteadyCycle> cycle_;
  std::int64_t n0_ = 0;           // cycle 0 (the one observed) starts at alpha + n0 pi
  Work x0_ = 0;                   // with this x
  std::int64_t cycle_index_ = 0;  // replays cycles 1, 2, ... to the horizon
  std::size_t phase_index_ = 0;
  SteadyCycle::Shift shift_;  // of cycle_index_

  // Continuous sliding: the reversal just observed, and its replay.
  bool at_reversal_ = false;
  Work reversal_tau_ = 0, reversal_x_ = 0;
  int reversal_direction_ = 0;
  bool fixed_known_ = false;
  Work fixed_phase_ = 0;  // u*, NaN without continuous sliding
  bool sliding_disabled_ = false;
  bool sliding_ = false;
  Work base_tau_ = 0;
  std::optional<ConvergingCycle> converging_;
};

}  // namespace frictionref::detail
