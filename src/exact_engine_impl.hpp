// Definitions of the exact engine templates; instantiated for double in
// exact_engine.cpp and for HighPrecision in exact_engine_multiprecision.cpp.
#pragma once

#include <algorithm>
#include <charconv>
#include <type_traits>
#include <cassert>
#include <cmath>
#include <limits>
#include <sstream>

#include <boost/math/constants/constants.hpp>

#include "bracketed_root.hpp"
#include "force_crossings.hpp"
#include "number_text.hpp"
#include "frictionref/closed_form.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"

namespace frictionref {
namespace detail {

template <class T>
std::string to_text(const T& value) {
  if constexpr (std::is_same_v<T, double>) return shortest_text(value);  // round-trip form
  std::ostringstream text;
  text.precision(std::numeric_limits<T>::max_digits10);
  text << value;
  return text.str();
}

// Phases shorter than this (8 ulps of the output type at the time scale
// max(1, |tau|)) cannot be told apart from zero length in the output: a stick
// that short is merged into the slip around it, as at a grazing stop.
template <class Real, class Work>
Work time_resolution(const Work& tau) {
  using std::fabs;
  const Work scale = fabs(tau) > Work(1) ? Work(fabs(tau)) : Work(1);
  return Work(8) * Work(std::numeric_limits<Real>::epsilon()) * scale;
}

// A root bracket lost to rounding: an internal invariant broken, reported as
// Termination::numerical_failure by next().
struct LostBracket {};

template <class Root>
const Root& checked(const Root& root) {
  if (!root.ok) throw LostBracket{};
  return root;
}

// Beyond this forcing phase a double cannot resolve w t well enough for the
// event logic (its ulp there is 2e-6 rad); about 1.6e9 forcing periods.
constexpr double kMaxForcingPhase = 1e10;

}  // namespace detail

template <class Real>
std::string BasicSummary<Real>::brief_report() const {
  std::ostringstream text;
  text.precision(std::numeric_limits<Real>::max_digits10);
  text << "termination=" << to_string(termination) << " phases=" << phases
       << " stick=" << count(PhaseKind::stick) << " slip+=" << count(PhaseKind::slip_forward)
       << " slip-=" << count(PhaseKind::slip_backward) << " stops=" << stops
       << " reversals=" << reversals << " breakaways=" << breakaways
       << " merged_sticks=" << merged_sticks << " touches=" << touches << " sign_tests=" << sign_tests
       << " root_function_calls=" << root_function_calls << " predicted_stops=" << predicted_stops << " t=" << final_state.t
       << " x=" << final_state.x << " v=" << final_state.v;
  return text.str();
}

template <class Real>
BasicExactEngine<Real>::BasicExactEngine(const BasicModel<Real>& model, const Real& t_end,
                                         const SolveOptions& options)
    : model_(model), t_end_(t_end), options_(options) {
  using std::isfinite;
  model.validate();
  options.validate();
  if (!model.is_harmonic_coulomb())  // temporary, until the general phase laws land
    throw InvalidInput("model", "general", "only the seed's model is supported so far");
  if (!isfinite(t_end)) throw InvalidInput("t_end", detail::to_text(t_end), "must be a finite number");
  if (!(t_end > model.t0))
    throw InvalidInput("t_end", detail::to_text(t_end),
                       "must be > t0 = " + detail::to_text(model.t0));

  omega_ = Work(model.omega);
  b_ = Work(model.amplitude) / (Work(model.mass) * omega_);
  r_ = Work(model.friction) / (Work(model.mass) * omega_);
  const detail::ForceCrossings<Work> crossings(b_, r_);
  crosses_ = crossings.crosses();
  alpha_ = crossings.alpha();
  if (crosses_) {
    // time_resolution = 8 eps |tau|: the window pi - 2 alpha is 4 of them at
    // |tau| = window / (32 eps). Only for lambda within ~1e-14 of 1.
    const Work window = boost::math::constants::pi<Work>() - 2 * alpha_;
    resolvable_phase_ = window / (32 * Work(std::numeric_limits<Real>::epsilon()));
  }

  tau_ = omega_ * Work(model.t0);
  tau_end_ = omega_ * Work(t_end);
  {
    // The motion must stay within the range of Real: closed-form bounds on
    // |a|, |v| (|v0| + 2 b + r |w (t_end - t0)|) and |x| (|x0| + that |v|
    // times the horizon).
    using std::fabs;
    const Work limit(1e300);
    const Work acceleration = omega_ * (b_ + r_);
    const Work speed = fabs(Work(model.v0)) + 2 * b_ + r_ * fabs(tau_end_ - tau_);
    const Work travel = fabs(Work(model.x0)) + speed * fabs(Work(t_end) - Work(model.t0));
    using std::isfinite;
    if (!(isfinite(acceleration) && acceleration < limit && isfinite(speed) && speed < limit))
      throw InvalidInput("amplitude", detail::to_text(model.amplitude),
                         "with this mass, omega and friction the velocity or acceleration "
                         "(B/(m w) = " + detail::to_text(Real(b_)) +
                             ") would leave the range of double");
    if (!(isfinite(travel) && travel < limit))
      throw InvalidInput("t_end", detail::to_text(t_end),
                         "the position could leave the range of double before t_end (|x| up "
                         "to " + detail::to_text(Real(travel)) + ")");
  }
  using std::fabs;
  const Work max_phase(detail::kMaxForcingPhase);
  // (A literal, not a std::string: engines are built by the million in sweeps.)
  constexpr const char* phase_rule = "must satisfy |w t| <= 1e10 rad (a double cannot resolve "
                                     "the forcing phase beyond that)";
  if (fabs(tau_) > max_phase) throw InvalidInput("t0", detail::to_text(model.t0), phase_rule);
  if (fabs(tau_end_) > max_phase) throw InvalidInput("t_end", detail::to_text(t_end), phase_rule);
  // Nothing shorter than the time resolution is resolved (phases that short
  // are merged), so a shorter horizon has no answer the engine can give.
  if (!(tau_end_ - tau_ > detail::time_resolution<Real>(tau_)))
    throw InvalidInput(
        "t_end", detail::to_text(t_end),
        "must exceed t0 by more than the engine's time resolution 8 eps max(1, |w t0|) / w = " +
            detail::to_text(Real(detail::time_resolution<Real>(tau_) / omega_)));
  t_current_ = model.t0;
  x_ = Work(model.x0);
  v_ = Work(model.v0);
  start_trig_ = sin_cos(tau_);
  if (crosses_) {
    using std::sqrt;
    const Work lambda = r_ / b_;
    cos_alpha_ = sqrt((1 - lambda) * (1 + lambda));
  }
  bool merged = false;
  sign_ = model.v0 > 0   ? 1
          : model.v0 < 0 ? -1
                         : direction_at_rest(tau_, start_trig_.sin, merged);
  summary_.merged_sticks += merged;
  mode_ = sign_ != 0 ? Mode::slip : Mode::stick;
  summary_.final_state = {model.t0, model.x0, model.v0, 0, PhaseKind::stick};
}

template <class Real>
int BasicExactEngine<Real>::direction_at_rest(const Work& tau, const Work& sin_tau,
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
    const Work tolerance = detail::time_resolution<Real>(tau);
    if (fabs(fabs(force) - r_) <= b_ * (2 * tolerance + Work(1e-15))) {
      const int near = detail::ForceCrossings<Work>(crosses_, alpha_).crossing_near(tau, tolerance);
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
auto BasicExactEngine<Real>::normalised_phase(const Work& tau, int s) const -> Work {
  // In [-pi, pi] give or take rounding: only compared with other such phases
  // within kPredictionWindow, so the period count need not be exact.
  const Work shifted = s > 0 ? tau : tau - boost::math::constants::pi<Work>();
  return shifted -
         boost::math::constants::two_pi<Work>() * detail::ForceCrossings<Work>::periods_in(shifted);
}

namespace detail {
// A prediction is used for starts within this many radians of its own (its
// first-order guess is then off by ~1e-3 at worst, which Halley's method
// removes in two steps).
constexpr double kPredictionWindow = 0.05;
}  // namespace detail

template <class Real>
int BasicExactEngine<Real>::prediction_for(const Work& phase) const {
  using std::fabs;
  for (std::size_t i = 0; i < predictions_.size(); ++i)
    if (predictions_[i].valid && fabs(phase - predictions_[i].phase) < Work(detail::kPredictionWindow))
      return static_cast<int>(i);
  return -1;
}

template <class Real>
void BasicExactEngine<Real>::remember_stop(const Law& law, const Work& phase, const Point& root) {
  // Only slips from rest: their stop depends on the start time alone.
  if (v_ != 0 || !(root.slope < 0)) return;
  const int s = law.sign();
  // F(a, tau) = s b (cos a - cos tau) - r (tau - a) = 0 at the stop:
  // d tau / d a = (s b sin a - r) / (s b sin tau - r).
  const Work dtau_da = (Work(s) * b_ * law.sin_begin() - r_) / root.slope;
  // The slot of this start phase, else the oldest one.
  int slot = prediction_for(phase);
  if (slot < 0) {
    slot = next_prediction_slot_;
    next_prediction_slot_ = (next_prediction_slot_ + 1) % static_cast<int>(predictions_.size());
  }
  predictions_[slot] = {true, phase, root.h, dtau_da - 1};
}

template <class Real>
bool BasicExactEngine<Real>::halley_root(const Law& law, const Work& guess, Work lo, Work hi,
                                         Point& root) {
  using std::fabs;
  const Work eps = std::numeric_limits<Work>::epsilon();
  Work x = guess;
  for (int iteration = 0; iteration < 6; ++iteration) {
    ++summary_.root_function_calls;
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
void BasicExactEngine<Real>::slip_root(const Law& law, Work lo, Work hi, Point& root) {
  const Work phase = v_ == 0 ? normalised_phase(tau_, law.sign()) : Work(0);
  if (v_ == 0) {
    if (const int slot = prediction_for(phase); slot >= 0) {
      const StopPrediction* p = &predictions_[slot];
      const Work guess = tau_ + p->length + p->dlength_dstart * (phase - p->phase);
      if (guess > lo && guess < hi && halley_root(law, guess, lo, hi, root)) {
        ++summary_.predicted_stops;
        remember_stop(law, phase, root);
        return;
      }
    }
  }
  // No prediction (a first stop, a transient) or it did not settle: the
  // bracketing solver, which cannot fail on [lo, hi].
  const auto speed = [&law](const Work& tau) { return law.speed_along_slip(tau); };
  const auto slope = [&law](const Work& tau) { return law.speed_slope(tau); };
  const Work tau_root = detail::checked(detail::decreasing_root<Work>(
                                            speed, slope, lo, hi, summary_.root_function_calls))
                            .root;
  root = law.point(tau_root);
  remember_stop(law, phase, root);
}

template <class Real>
auto BasicExactEngine<Real>::speed_at_critical(const Law& law, const Work& tau, bool minimum)
    -> Work {
  using std::fabs;
  ++summary_.sign_tests;
  const int s = law.sign();
  // At a minimum of s v, cos tau = s cos alpha; at a maximum, -s cos alpha.
  const Work cos_tau = Work(minimum ? s : -s) * cos_alpha_;
  const Work h = tau - tau_;
  const Work value = Work(s) * (v_ + b_ * (law.cos_begin() - cos_tau)) - r_ * h;
  // Rounding of the terms (the carried sin, cos of the start included): the
  // sign is certain beyond this; within it, the cancellation-free form.
  const Work eps = std::numeric_limits<Work>::epsilon();
  const Work bound = 512 * eps * (fabs(v_) + 2 * b_ + r_ * (fabs(h) + fabs(tau)));
  if (fabs(value) > bound) return value;
  return law.point(tau).speed;
}

template <class Real>
bool BasicExactEngine<Real>::find_slip_end(const Law& law, Point& end, int& direction) {
  using std::fabs;
  const int s = sign_;
  const Work resolution = detail::time_resolution<Real>(tau_);

  // s v(tau) >= s v_a + s b cos a - b - r (tau - a): no stop before `lower`
  // (and none ever when r = 0 and the bound is positive).
  const Work reach_lower = Work(s) * (v_ + b_ * law.cos_begin()) - b_;
  const Work reach_upper = Work(s) * (v_ + b_ * law.cos_begin()) + b_;
  if (r_ == 0 && reach_lower > 0) return false;

  Work piece_begin = tau_;
  if (!crosses_) {
    // lambda >= 1 or B = 0: s v is monotone (non-increasing); the stop lies
    // before tau_a + reach_upper / r, where the upper envelope reaches zero.
    if (r_ == 0) return false;  // B = R = 0: constant velocity
    Work bound = tau_ + reach_upper / r_;
    bound += resolution + fabs(bound) * Work(std::numeric_limits<Work>::epsilon()) * 4;
    const bool horizon = bound >= tau_end_;
    const Work piece_end = horizon ? tau_end_ : bound;
    ++summary_.sign_tests;
    const Point end_point = law.point(piece_end);
    if (end_point.speed > 0) {
      assert(horizon && "the closed-form upper bound of a monotone slip must bracket its stop");
      return false;
    }
    if (end_point.speed == 0) {
      end = end_point;
    } else {
      slip_root(law, piece_begin, piece_end, end);
    }
    direction = 0;  // nothing breaks away when lambda >= 1
    return true;
  }

  // lambda < 1: split at the critical times; s v is monotone on each piece.
  // A slip that starts at rest starts where the force has just beaten
  // friction, so s v rises first: skip a critical time within the resolution.
  Work search_from = tau_ + resolution;
  if (r_ > 0 && reach_lower > 0) {
    piece_begin = tau_ + reach_lower / r_ * (1 - 64 * std::numeric_limits<Real>::epsilon());
    search_from = piece_begin;
  }
  const detail::ForceCrossings<Work> crossings(crosses_, alpha_);
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
      ++summary_.sign_tests;
      end_point = law.point(piece_end);
      end_speed = end_point.speed;
    } else {
      end_speed = speed_at_critical(law, critical.tau, critical.minimum);
    }
    if (end_speed <= 0) {
      if (end_speed < 0) {
        slip_root(law, piece_begin, piece_end, end);
      } else {
        end = horizon ? end_point : law.point(piece_end);
      }
      // v = 0 where the slip goes on in the same direction: a touch at a
      // minimum of s v (a breakaway time in direction s). Not a stop.
      bool merged = false;
      const int next = direction_at_rest(end.tau, end.at.sin, merged);
      if (next == s) {
        ++summary_.touches;
        if (horizon) return false;  // the slip goes on to the horizon
        piece_begin = critical.tau;
        search_from = critical.tau + resolution;
        continue;
      }
      summary_.merged_sticks += merged;
      direction = next;
      return true;
    }
    if (horizon) return false;
    piece_begin = piece_end;
    search_from = piece_end;
  }
}

template <class Real>
bool BasicExactEngine<Real>::emit(BasicPhase<Real>& phase, PhaseKind kind, const Work& tau_end,
                                  const Work& x_end, const Work& v_end, const Work& acceleration,
                                  bool at_horizon) {
  const Real t_end = at_horizon ? t_end_ : Real(tau_end / omega_);
  if (!(t_end > t_current_)) return false;  // shorter than the output resolution
  phase.kind = kind;
  phase.t_begin = t_current_;
  phase.t_end = t_end;
  phase.x_begin = Real(x_);
  phase.x_end = Real(x_end);
  phase.v_begin = Real(v_);
  phase.v_end = Real(v_end);
  t_current_ = t_end;
  ++summary_.phases;
  ++summary_.phases_by_kind[static_cast<int>(kind)];
  summary_.final_state = {phase.t_end, phase.x_end, phase.v_end, Real(acceleration), kind};
  return true;
}

template <class Real>
bool BasicExactEngine<Real>::next(BasicPhase<Real>& phase) {
  // Phases too short to show in Real are skipped; a run of them means the
  // engine is not advancing, which must end in a status, never a hang.
  for (int skipped = 0; !done_; ++skipped) {
    if (skipped > 16) {
      done_ = true;
      summary_.termination = Termination::numerical_failure;
      summary_.message = "no progress at t = " + detail::to_text(Real(tau_ / omega_)) +
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
    if (mode_ == Mode::stick) {
      int direction = 0;
      Work breakaway = tau_end_;
      bool breaks = false;
      if (crosses_) {
        // The first breakaway whose force window is resolvable (|w t| below
        // resolvable_phase_; only matters for lambda within ~1e-14 of 1).
        const Work from = tau_ > -resolvable_phase_ ? tau_ : -resolvable_phase_;
        breakaway = detail::ForceCrossings<Work>(crosses_, alpha_).next_breakaway(from, direction);
        // A breakaway that rounds to t_end in Real is at the horizon.
        breaks = breakaway < tau_end_ && breakaway < resolvable_phase_ &&
                 Real(breakaway / omega_) < t_end_;
        if (!breaks) breakaway = tau_end_;
      }
      const Work end = breaks ? breakaway : tau_end_;
      const bool emitted = emit(phase, PhaseKind::stick, end, x_, Work(0), Work(0), !breaks);
      if (breaks) {
        ++summary_.breakaways;
        mode_ = Mode::slip;
        sign_ = direction;
        tau_ = breakaway;
        v_ = 0;
        // sin, cos of the breakaway time as stored (rounded), not of the
        // exact one: the slip then starts from rest at the stored time with
        // its true force, an error of second order only (the slope of v is
        // zero at a breakaway).
        start_trig_ = sin_cos(tau_);
        carried_starts_ = 0;
      } else {
        done_ = true;
      }
      if (emitted) return true;
      continue;
    }

    const PhaseKind kind = sign_ > 0 ? PhaseKind::slip_forward : PhaseKind::slip_backward;
    const Law law(omega_, b_, r_, kind, tau_, x_, v_, start_trig_);
    Point end;
    int next = 0;
    bool stops = false;
    try {
      stops = find_slip_end(law, end, next);
    } catch (const detail::LostBracket&) {
      done_ = true;
      summary_.termination = Termination::numerical_failure;
      summary_.message = "lost the root bracket of a slip end after t = " +
                         detail::to_text(Real(tau_ / omega_)) + " (please report this model)";
      return false;
    }
    if (!stops) end = law.point(tau_end_);
    const Work x_end = law.position(end);
    const Work v_end = stops ? Work(0) : Work(law.sign()) * end.speed;
    // A stop that rounds to t_end in Real ends the run there (found by
    // fuzzing: with max_phases it was reported as a phase limit).
    const bool at_horizon = !stops || end.tau >= tau_end_ || !(Real(end.tau / omega_) < t_end_);
    const bool emitted =
        emit(phase, kind, end.tau, x_end, v_end, law.acceleration_at(end.at), at_horizon);
    if (at_horizon) {
      done_ = true;
    } else {
      ++summary_.stops;
      if (next == -sign_) ++summary_.reversals;
      mode_ = next != 0 ? Mode::slip : Mode::stick;
      sign_ = next;
      tau_ = end.tau;
      x_ = x_end;
      v_ = 0;
      if (next != 0) {
        // The next slip starts here: carry sin, cos of the stop, recomputed
        // fresh now and then so rounding cannot build up.
        if (++carried_starts_ < 64) {
          start_trig_ = end.at;
        } else {
          start_trig_ = sin_cos(tau_);
          carried_starts_ = 0;
        }
      }
    }
    if (emitted) return true;
  }
  if (summary_.termination == Termination::reached_end && summary_.message.empty())
    summary_.message = "reached t_end";
  return false;
}

template <class Real>
const BasicPhase<Real>& BasicSolution<Real>::phase_at(const Real& t) const {
  if (phases.empty() || !(t >= phases.front().t_begin) || !(t <= phases.back().t_end))
    throw InvalidInput("t", detail::to_text(t), "must lie within [t0, t_end] of the solution");
  // First phase whose t_end > t; the last phase also owns its t_end.
  auto it = std::upper_bound(phases.begin(), phases.end(), t,
                             [](const Real& value, const BasicPhase<Real>& p) {
                               return value < p.t_end;
                             });
  if (it == phases.end()) --it;
  return *it;
}

template <class Real>
BasicState<Real> BasicSolution<Real>::state_at(const Real& t) const {
  return evaluate(model, phase_at(t), t);
}

template <class Real>
BasicSolution<Real> solve(const BasicModel<Real>& model, const Real& t_end,
                          const SolveOptions& options) {
  BasicExactEngine<Real> engine(model, t_end, options);
  BasicSolution<Real> solution;
  solution.model = model;
  BasicPhase<Real> phase;
  while (engine.next(phase)) solution.phases.push_back(phase);
  solution.summary = engine.summary();
  return solution;
}

}  // namespace frictionref
