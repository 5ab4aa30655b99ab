// The seed's family of phase laws: m x'' = B sin(w t) - R sign(v), static =
// sliding friction (BasicModel::is_harmonic_coulomb()), docs/theory.md 2-4.
//
// A slip ends at the first zero of v after its start; v is monotone between
// the closed-form critical times where B sin(w t) = +-R (force_crossings.hpp),
// so each such piece holds at most one zero and a sign test at its end
// brackets it exactly. The zero is found inside that bracket by Halley steps
// from a prediction (stop_predictions.hpp; one evaluation per stop in a steady
// state), else by the scalar type's bracketing solver (scalar_traits.hpp).
// Breakaway times are closed form. No time stepping and no
// tolerance-dependent event detection (docs/theory.md 3.4, 3.5).
#pragma once

#include <cassert>
#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>

#include "engine/engine_core.hpp"
#include "engine/event_loop.hpp"
#include "engine/motion_range.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/harmonic_coulomb/cycle_replay.hpp"
#include "laws/harmonic_coulomb/force_crossings.hpp"
#include "laws/harmonic_coulomb/phase_law.hpp"
#include "laws/harmonic_coulomb/stop_predictions.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Real>
class HarmonicCoulombFamily {
 public:
  using Work = work_t<Real>;
  using Traits = ScalarTraits<Real>;
  using Law = PhaseLaw<Work>;
  using Point = typename Law::Point;

  HarmonicCoulombFamily(const BasicModel<Real>& model, const Real& t_end, const Work& tau0,
                        const Work& tau_end, BasicSummary<Real>& summary);

  int direction_at_rest(const Work& tau, const Work& x);
  Breakaway<Work> stick_end(const Work& tau, const Work& x);
  SlipEnd<Work> slip_end(const PhaseStart<Work>& start);
  // The steady motion's replay (event_loop.hpp, cycle_replay.hpp); it sees
  // every stop, reversal and breakaway.
  CycleReplay<Real>& cycle_replay() { return replay_; }
  const CycleReplay<Real>& cycle_replay() const { return replay_; }

 private:
  // At v = 0 at forcing phase tau (sin tau given): returns the slip direction
  // (+1/-1) if the force beats friction (or a breakaway is within the time
  // resolution), 0 to stick.
  int direction_at_rest(const Work& tau, const Work& sin_tau, bool& merged) const;
  // Earliest stop of the slip in (tau_a, tau_end_]; false if none. On a stop,
  // `end` is the point there and `direction` what follows it.
  bool find_slip_end(const Law& law, const PhaseStart<Work>& start, Point& end, int& direction);
  // s v at a critical time (sin, cos there in closed form), trusted only when
  // clear of zero by its rounding bound; otherwise the full evaluation.
  Work speed_at_critical(const Law& law, const PhaseStart<Work>& start, const Work& tau,
                         bool minimum);
  // The root of s v on [lo, hi] (s v(lo) > 0 >= s v(hi), s v decreasing):
  // predicted Halley steps when a prediction applies, else the bracketing
  // solver.
  void slip_root(const Law& law, const PhaseStart<Work>& start, Work lo, Work hi, Point& root);
  // Halley's method from `guess`, kept inside [lo, hi]; false if it does not
  // settle within a few steps (the caller then takes the bracketing solver).
  bool halley_root(const Law& law, const Work& guess, Work lo, Work hi, Point& root);
  void remember_stop(const Law& law, const PhaseStart<Work>& start, const Work& phase,
                     const Point& root);
  // sin, cos of the start of the slip at tau: carried from the event that
  // started it where that is exact enough, else computed.
  const SinCos<Work>& start_trig(const Work& tau);

  BasicSummary<Real>* summary_;
  Work tau_end_;
  Work b_, r_;            // b = B/(m w), r = R/(m w)
  Work omega_;
  bool crosses_ = false;  // lambda < 1: the force crosses +-R and breakaways exist
  Work alpha_ = 0;        // asin(lambda) when crosses_
  Work cos_alpha_ = 0;    // cos alpha = sqrt(1 - lambda^2): cos of the critical times, +-
                          // (sin there is +-lambda; speed_at_critical)
  // |F| > R only on windows pi - 2 alpha wide; beyond |w t| = this the window
  // is under 4 time resolutions and no slip it starts is representable.
  Work resolvable_phase_ = 0;
  // sin, cos of trig_tau_. Slip starts whose sin, cos came from the previous
  // slip by the sum formulas (cheap, but rounding accumulates) are
  // recomputed fresh every 64.
  Work trig_tau_ = 0;
  SinCos<Work> trig_{0, 1};
  int carried_starts_ = 0;
  StopPredictions<Work> predictions_;
  CycleReplay<Real> replay_;
};

template <class Real>
HarmonicCoulombFamily<Real>::HarmonicCoulombFamily(const BasicModel<Real>& model,
                                                   const Real& t_end, const Work& tau0,
                                                   const Work& tau_end,
                                                   BasicSummary<Real>& summary)
    : summary_(&summary), tau_end_(tau_end) {
  omega_ = Work(model.omega);
  b_ = Work(model.amplitude) / (Work(model.mass) * omega_);
  r_ = Work(model.friction) / (Work(model.mass) * omega_);
  const ForceCrossings<Work> crossings(b_, r_);
  crosses_ = crossings.crosses();
  alpha_ = crossings.alpha();
  replay_ = CycleReplay<Real>(model, t_end, crosses_, alpha_, tau_end);
  if (crosses_) {
    // time_resolution = 8 eps |tau|: the window pi - 2 alpha is 4 of them at
    // |tau| = window / (32 eps). Only for lambda within ~1e-14 of 1.
    const Work window = boost::math::constants::pi<Work>() - 2 * alpha_;
    resolvable_phase_ = window / (32 * Work(std::numeric_limits<Real>::epsilon()));
    using std::sqrt;
    const Work lambda = r_ / b_;
    cos_alpha_ = sqrt((1 - lambda) * (1 + lambda));
  }
  // The motion must stay within the range of Real: closed-form bounds on
  // |a|, |v| (|v0| + 2 b + r |w (t_end - t0)|) and |x| (|x0| + that |v|
  // times the horizon).
  using std::fabs;
  MotionBounds<Work> bounds;
  bounds.acceleration = omega_ * (b_ + r_);
  bounds.speed = fabs(Work(model.v0)) + 2 * b_ + r_ * fabs(tau_end - tau0);
  bounds.travel = fabs(Work(model.x0)) + bounds.speed * fabs(Work(t_end) - Work(model.t0));
  check_motion_bounds(model, t_end, bounds, b_, "B/(m w)");
  check_motion_scales<Real, Work>(model);
  trig_tau_ = tau0;
  trig_ = sin_cos(tau0);
}

template <class Real>
const SinCos<typename HarmonicCoulombFamily<Real>::Work>&
HarmonicCoulombFamily<Real>::start_trig(const Work& tau) {
  if (tau != trig_tau_) {
    trig_tau_ = tau;
    trig_ = sin_cos(tau);
    carried_starts_ = 0;
  }
  return trig_;
}

template <class Real>
int HarmonicCoulombFamily<Real>::direction_at_rest(const Work& tau, const Work& x) {
  (void)x;  // no spring: the force does not depend on the position
  bool merged = false;
  const int direction = direction_at_rest(tau, start_trig(tau).sin, merged);
  summary_->merged_sticks += merged;
  return direction;
}

template <class Real>
int HarmonicCoulombFamily<Real>::direction_at_rest(const Work& tau, const Work& sin_tau,
                                                   bool& merged) const {
  merged = false;
  // Within the time resolution of a force crossing, the sign of b sin(tau) - r
  // is rounding noise: decide from the closed-form crossing times instead.
  // At a breakaway the stick would have zero length (a start exactly at a
  // breakaway time, a grazing stop): the slip starts now. Where the force
  // re-enters the band the mass stays.
  using std::fabs;
  // Where the force window is below the time resolution, no slip from rest is
  // representable: the mass stays (docs/theory.md 4.11).
  if (crosses_ && fabs(tau) >= resolvable_phase_) return 0;
  const Work force = b_ * sin_tau;  // velocity units, like r_
  if (crosses_) {
    // sin is 1-Lipschitz: within `tolerance` of a crossing, b sin tau lies
    // within b tolerance of +-r. Farther (with room for the rounding of
    // sin tau), no crossing is near and the sign test below decides.
    const Work tolerance = Traits::time_resolution(tau);
    if (fabs(fabs(force) - r_) <= b_ * (2 * tolerance + Work(1e-15))) {
      const int near = ForceCrossings<Work>(crosses_, alpha_).crossing_near(tau, tolerance);
      if (near != 2) {
        merged = near != 0;
        return near;
      }
    }
  }
  if (force > r_) return 1;
  if (force < -r_) return -1;
  return 0;
}

template <class Real>
Breakaway<typename HarmonicCoulombFamily<Real>::Work> HarmonicCoulombFamily<Real>::stick_end(
    const Work& tau, const Work& x) {
  Breakaway<Work> result;
  if (!crosses_) return result;  // lambda >= 1 or B = 0: nothing breaks away
  // The first breakaway whose force window is resolvable (|w t| below
  // resolvable_phase_; only matters for lambda within ~1e-14 of 1).
  const Work from = tau > -resolvable_phase_ ? tau : -resolvable_phase_;
  result.tau = ForceCrossings<Work>(crosses_, alpha_).next_breakaway(from, result.direction);
  result.found = result.tau < tau_end_ && result.tau < resolvable_phase_;
  if (result.found) {
    // sin, cos of the breakaway time as stored (rounded), not of the exact
    // one: the slip then starts from rest at the stored time with its true
    // force, an error of second order only (the slope of v is zero at a
    // breakaway).
    trig_tau_ = result.tau;
    trig_ = sin_cos(result.tau);
    carried_starts_ = 0;
    replay_.observe_breakaway(result.tau, x, result.direction);
  }
  return result;
}

template <class Real>
SlipEnd<typename HarmonicCoulombFamily<Real>::Work> HarmonicCoulombFamily<Real>::slip_end(
    const PhaseStart<Work>& start) {
  const PhaseKind kind = start.sign > 0 ? PhaseKind::slip_forward : PhaseKind::slip_backward;
  const Law law(omega_, b_, r_, kind, start.tau, start.x, start.v, start_trig(start.tau));
  Point end;
  int next = 0;
  SlipEnd<Work> result;
  const std::uint64_t fragile = summary_->touches + summary_->merged_sticks;
  result.stops = find_slip_end(law, start, end, next);
  if (!result.stops) end = law.point(tau_end_);
  result.tau = end.tau;
  result.x = law.position(end);
  result.v = result.stops ? Work(0) : Work(law.sign()) * end.speed;
  result.acceleration = law.acceleration_at(end.at);
  result.next_direction = next;
  if (result.stops)
    replay_.observe_stop(kind, result.tau, result.x,
                         summary_->touches + summary_->merged_sticks == fragile, next);
  if (result.stops && next != 0) {
    // The next slip starts here: carry sin, cos of the stop, recomputed
    // fresh now and then so rounding cannot build up.
    if (++carried_starts_ < 64) {
      trig_tau_ = end.tau;
      trig_ = end.at;
    } else {
      trig_tau_ = end.tau;
      trig_ = sin_cos(end.tau);
      carried_starts_ = 0;
    }
  }
  return result;
}

template <class Real>
void HarmonicCoulombFamily<Real>::remember_stop(const Law& law, const PhaseStart<Work>& start,
                                                const Work& phase, const Point& root) {
  // Only slips from rest: their stop depends on the start time alone.
  if (start.v != 0 || !(root.slope < 0)) return;
  const int s = law.sign();
  // F(a, tau) = s b (cos a - cos tau) - r (tau - a) = 0 at the stop:
  // d tau / d a = (s b sin a - r) / (s b sin tau - r).
  const Work dtau_da = (Work(s) * b_ * law.sin_begin() - r_) / root.slope;
  predictions_.remember(phase, root.h, dtau_da);
}

template <class Real>
bool HarmonicCoulombFamily<Real>::halley_root(const Law& law, const Work& guess, Work lo, Work hi,
                                              Point& root) {
  using std::fabs;
  const Work eps = std::numeric_limits<Work>::epsilon();
  Work x = guess;
  for (int iteration = 0; iteration < 6; ++iteration) {
    ++summary_->root_function_calls;
    const Point p = law.point(x);
    if (p.speed == 0) {
      root = p;
      return true;
    }
    (p.speed > 0 ? lo : hi) = x;
    const Work f = p.speed;
    const Work d1 = p.slope;
    const Work d2 = p.curvature;
    if (!(d1 < 0)) return false;  // not on the falling flank the bracket promises
    const Work denominator = 2 * d1 * d1 - f * d2;
    if (!(denominator > 0)) return false;
    const Work step = -2 * f * d1 / denominator;
    const Work next = x + step;
    if (!(next >= lo && next <= hi)) return false;
    // Converged: the second and third derivatives of s v are at most b in
    // size, so with K = b / |slope| the error left after this step is below
    // (K/6 + K^2/4) |e|^3, where the error e of x is within 1% of the step
    // while K |step| is small. Accept once that is an eighth of an ulp of the
    // work type; the state at the root then follows from this point by a
    // rotation (no further sin_cos).
    // (Written times slope^2, without divisions.)
    const Work size = fabs(step);
    const Work slope = -d1;
    if (size <= Work(1e-3) && b_ * size <= Work(1e-3) * slope) {
      const Work e = size * Work(1.01);
      const Work bound = (b_ * slope / 6 + b_ * b_ / 4) * e * e * e;
      const Work scale = fabs(next) > 1 ? Work(fabs(next)) : Work(1);
      if (bound <= eps * scale * slope * slope / 8) {
        // Shift by the step as rounded into `next` (exact: next and x are
        // close), so sin, cos belong to the stored root time itself.
        root = law.shifted(p, next - x);
        return true;
      }
    }
    x = next;
  }
  return false;
}

template <class Real>
void HarmonicCoulombFamily<Real>::slip_root(const Law& law, const PhaseStart<Work>& start,
                                            Work lo, Work hi, Point& root) {
  const Work phase =
      start.v == 0 ? StopPredictions<Work>::normalised_phase(start.tau, law.sign()) : Work(0);
  if (start.v == 0) {
    if (const auto* p = predictions_.find(phase)) {
      const Work guess = StopPredictions<Work>::guess(*p, start.tau, phase);
      if (guess > lo && guess < hi && halley_root(law, guess, lo, hi, root)) {
        ++summary_->predicted_stops;
        remember_stop(law, start, phase, root);
        return;
      }
    }
  }
  // No prediction (a first stop, a transient) or it did not settle: the
  // bracketing solver, which cannot fail on [lo, hi].
  const auto speed = [&law](const Work& tau) { return law.speed_along_slip(tau); };
  const auto slope = [&law](const Work& tau) { return law.speed_slope(tau); };
  const Work tau_root =
      checked(Traits::decreasing_root(speed, slope, lo, hi, summary_->root_function_calls)).root;
  root = law.point(tau_root);
  remember_stop(law, start, phase, root);
}

template <class Real>
auto HarmonicCoulombFamily<Real>::speed_at_critical(const Law& law, const PhaseStart<Work>& start,
                                                    const Work& tau, bool minimum) -> Work {
  using std::fabs;
  ++summary_->sign_tests;
  const int s = law.sign();
  // At a minimum of s v, cos tau = s cos alpha; at a maximum, -s cos alpha.
  const Work cos_tau = Work(minimum ? s : -s) * cos_alpha_;
  const Work h = tau - start.tau;
  const Work value = Work(s) * (start.v + b_ * (law.cos_begin() - cos_tau)) - r_ * h;
  // Rounding of the terms (the carried sin, cos of the start included): the
  // sign is certain beyond this; within it, the cancellation-free form.
  const Work eps = std::numeric_limits<Work>::epsilon();
  const Work bound = 512 * eps * (fabs(start.v) + 2 * b_ + r_ * (fabs(h) + fabs(tau)));
  if (fabs(value) > bound) return value;
  return law.point(tau).speed;
}

template <class Real>
bool HarmonicCoulombFamily<Real>::find_slip_end(const Law& law, const PhaseStart<Work>& start,
                                                Point& end, int& direction) {
  using std::fabs;
  const int s = start.sign;
  const Work resolution = Traits::time_resolution(start.tau);

  // s v(tau) >= s v_a + s b cos a - b - r (tau - a): no stop before `lower`
  // (and none ever when r = 0 and the bound is positive).
  const Work reach_lower = Work(s) * (start.v + b_ * law.cos_begin()) - b_;
  const Work reach_upper = Work(s) * (start.v + b_ * law.cos_begin()) + b_;
  if (r_ == 0 && reach_lower > 0) return false;

  Work piece_begin = start.tau;
  if (!crosses_) {
    // lambda >= 1 or B = 0: s v is monotone (non-increasing); the stop lies
    // before tau_a + reach_upper / r, where the upper envelope reaches zero.
    if (r_ == 0) return false;  // B = R = 0: constant velocity
    Work bound = start.tau + reach_upper / r_;
    bound += resolution + fabs(bound) * Work(std::numeric_limits<Work>::epsilon()) * 4;
    const bool horizon = bound >= tau_end_;
    const Work piece_end = horizon ? tau_end_ : bound;
    ++summary_->sign_tests;
    const Point end_point = law.point(piece_end);
    if (end_point.speed > 0) {
      assert(horizon && "the closed-form upper bound of a monotone slip must bracket its stop");
      return false;
    }
    if (end_point.speed == 0) {
      end = end_point;
    } else {
      slip_root(law, start, piece_begin, piece_end, end);
    }
    direction = 0;  // nothing breaks away when lambda >= 1
    return true;
  }

  // lambda < 1: split at the critical times; s v is monotone on each piece.
  // A slip that starts at rest starts where the force has just beaten
  // friction, so s v rises first: skip a critical time within the resolution.
  Work search_from = start.tau + resolution;
  if (r_ > 0 && reach_lower > 0) {
    piece_begin = start.tau + reach_lower / r_ * (1 - 64 * std::numeric_limits<Real>::epsilon());
    search_from = piece_begin;
  }
  const ForceCrossings<Work> crossings(crosses_, alpha_);
  for (;;) {
    if (piece_begin >= tau_end_) return false;
    const auto critical = crossings.next_critical_point(s, search_from);
    const bool horizon = critical.tau >= tau_end_;
    const Work piece_end = horizon ? tau_end_ : critical.tau;
    // At a critical time s v follows from closed-form sin and cos; at the
    // horizon it takes a full evaluation.
    Point end_point;
    Work end_speed;
    if (horizon) {
      ++summary_->sign_tests;
      end_point = law.point(piece_end);
      end_speed = end_point.speed;
    } else {
      end_speed = speed_at_critical(law, start, critical.tau, critical.minimum);
    }
    if (end_speed <= 0) {
      if (end_speed < 0) {
        slip_root(law, start, piece_begin, piece_end, end);
      } else {
        end = horizon ? end_point : law.point(piece_end);
      }
      // v = 0 where the slip goes on in the same direction: a touch at a
      // minimum of s v (a breakaway time in direction s). Not a stop.
      bool merged = false;
      const int next = direction_at_rest(end.tau, end.at.sin, merged);
      if (next == s) {
        ++summary_->touches;
        if (horizon) return false;  // the slip goes on to the horizon
        piece_begin = critical.tau;
        search_from = critical.tau + resolution;
        continue;
      }
      summary_->merged_sticks += merged;
      direction = next;
      return true;
    }
    if (horizon) return false;
    piece_begin = piece_end;
    search_from = piece_end;
  }
}

}  // namespace frictionref::detail
