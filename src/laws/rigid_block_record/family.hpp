// The family of phase laws of a rigid block under a recorded ground motion
// (docs/theory.md 9): m x'' = F0 - m a_g(t) - f, with a_g linear between the
// record's samples; Coulomb friction R, static Rs >= R; two-way, or one-way
// (Newmark's downslope block: no motion towards negative x). No spring,
// damper or harmonic force: a record with those is the general family's
// (laws/linear_oscillator, two-way).
//
// The net acceleration g = F0/m - a_g is linear on each segment
// (net_acceleration.hpp), so every event is a root of a polynomial of degree
// one or two on a segment:
//   - a stick ends where g crosses +-Rs/m: a linear root, found segment by
//     segment from the values at the segment's ends (g is monotone there);
//   - a slip ends where v = 0: a quadratic on each segment, split at its
//     vertex into monotone halves (slip_piece.hpp). No sampling step, nothing
//     to miss.
// The state is carried from segment to segment in the work type (long double
// for double), so 10^5 segments lose no double digit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "engine/engine_core.hpp"
#include "engine/event_loop.hpp"
#include "engine/scalar_traits.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "laws/rigid_block_record/net_acceleration.hpp"
#include "laws/rigid_block_record/slip_piece.hpp"

namespace frictionref::detail {

// True if the rigid-block laws solve `model`: a ground motion with no
// spring, damper or harmonic force (harmonics of zero amplitude are none).
template <class Real>
bool is_rigid_block_record(const BasicModel<Real>& model) {
  if (!model.ground_motion || model.stiffness != 0 || model.damping != 0 || model.amplitude != 0)
    return false;
  for (const auto& h : model.harmonics)
    if (h.amplitude != 0) return false;
  return true;
}

// Throws InvalidInput unless is_rigid_block_record(model).
template <class Real>
void require_rigid_block_record(const BasicModel<Real>& model) {
  const char* rule =
      "is solved by the rigid-block laws only without a spring, damper or harmonic force";
  if (model.stiffness != 0) throw InvalidInput("stiffness", to_text(model.stiffness), rule);
  if (model.damping != 0) throw InvalidInput("damping", to_text(model.damping), rule);
  if (model.amplitude != 0) throw InvalidInput("amplitude", to_text(model.amplitude), rule);
  if (!is_rigid_block_record(model)) throw InvalidInput("harmonics", "given", rule);
}

template <class Real>
class RigidBlockRecordFamily {
 public:
  using Work = work_t<Real>;
  using Traits = ScalarTraits<Real>;
  using Net = NetAcceleration<Work>;
  using Segment = typename Net::Segment;

  RigidBlockRecordFamily(const BasicModel<Real>& model, const Real& t_end, const Work& tau0,
                         const Work& tau_end, BasicSummary<Real>& summary)
      : net_((require_rigid_block_record(model), model.ground_motion), Work(model.omega),
             Work(model.force_offset) / Work(model.mass)),
        omega_(model.omega),
        mu_(Work(model.friction) / Work(model.mass)),
        mu_static_(Work(model.static_limit()) / Work(model.mass)),
        one_way_(model.one_way),
        tau_end_(tau_end),
        summary_(&summary) {
    using std::fabs;
    // A priori bounds: |v| <= |v0| + (max |g| + mu) (t_end - t0).
    // max_i (offset + |a_i|) is offset + max_i |a_i|: rounding is monotone.
    const Work offset = fabs(Work(model.force_offset)) / Work(model.mass);
    const Work g_max = offset + Work(model.ground_motion->pga());
    const Work span = (tau_end - tau0) / omega_;
    const Work speed = fabs(Work(model.v0)) + (g_max + mu_) * span;
    const Work travel = fabs(Work(model.x0)) + speed * span;
    const Work limit(MotionLimits::largest_motion);
    if (!(speed < limit) || !(travel < limit))
      throw InvalidInput("t_end", to_text(t_end),
                         "lets the block's velocity or travel under the ground motion reach "
                         "1e300 (max |a_g| x duration); shorten the horizon");
  }

  int direction_at_rest(const Work& tau, const Work& /*x*/) const {
    const Segment s = net_.segment(net_.segment_at(tau));
    return direction_from(Net::value(s, tau), s.slope);
  }

  Breakaway<Work> stick_end(const Work& tau, const Work& /*x*/);
  SlipEnd<Work> slip_end(const PhaseStart<Work>& start);

 private:
  // The at-rest rule: +1 / -1 where |g| > Rs/m (in g's direction), or g on
  // the band's edge and moving out of it; 0 (stays) otherwise. One-way: +1 only.
  int direction_from(const Work& g, const Work& slope) const {
    if (g > mu_static_ || (g == mu_static_ && slope > 0)) return 1;
    if (one_way_) return 0;
    if (g < -mu_static_ || (g == -mu_static_ && slope < 0)) return -1;
    return 0;
  }

  Net net_;
  Work omega_;
  Work mu_;         // R / m
  Work mu_static_;  // Rs / m
  bool one_way_;
  Work tau_end_;
  BasicSummary<Real>* summary_;
};

template <class Real>
auto RigidBlockRecordFamily<Real>::stick_end(const Work& tau, const Work& /*x*/)
    -> Breakaway<Work> {
  Breakaway<Work> result;
  const std::size_t first = net_.segment_at(tau);
  // Interior segments that begin after tau (k > first) and end before the
  // horizon (k < last) may be skipped on their sample values.
  const std::size_t last = std::min(net_.first_ending_at_or_after(tau_end_), net_.samples());
  const double band = Net::band_in_double(mu_static_);
  for (std::size_t k = first; k < net_.segments(); ++k) {
    // Most of a stick's segments lie well inside the band: skip them on
    // their sample values alone (net_acceleration.hpp).
    if (k > first && k >= 1 && k < last && net_.strictly_inside(k, band, one_way_)) {
      ++summary_->sign_tests;
      continue;
    }
    const Segment s = net_.segment(k);
    const Work from = s.begin > tau ? s.begin : tau;
    if (!(from < tau_end_)) break;
    const Work to = s.end < tau_end_ ? s.end : tau_end_;
    ++summary_->sign_tests;
    // At the piece's start (a jump at the record's ends, or the edge).
    const Work g_from = Net::value(s, from);
    if (const int d = direction_from(g_from, s.slope); d != 0 && from > tau) {
      result = {true, from, d};
      return result;
    }
    if (s.slope == 0) continue;
    // g is monotone on the piece: it leaves the band at most once, on the
    // side it moves towards.
    const Work g_to = Net::value(s, to);
    const int side = s.slope > 0 ? 1 : -1;
    if (side < 0 && one_way_) continue;
    const Work edge = side * mu_static_;
    if (side * g_to > mu_static_) {
      ++summary_->root_function_calls;
      Work crossing = s.begin + (edge - s.at_begin) / s.slope;
      // A crossing at the segment's end is left to the next segment's
      // start, which decides from the sample's own value and the slope after
      // it: g at the end comes from this slope and is the sample's value
      // only to rounding (a rounding above the edge broke away where g only
      // touched it and turned back, R = Rs = 0: found by fuzzing).
      if (!(crossing < s.end) && s.end < tau_end_ && k + 1 < net_.segments()) continue;
      if (!(crossing >= from)) crossing = from;
      if (crossing > to) crossing = to;
      result = {true, crossing, side};
      return result;
    }
  }
  return result;
}

template <class Real>
auto RigidBlockRecordFamily<Real>::slip_end(const PhaseStart<Work>& start) -> SlipEnd<Work> {
  const int s = start.sign;
  Work tau = start.tau, x = start.x, v = start.v;
  for (std::size_t k = net_.segment_at(tau); k < net_.segments(); ++k) {
    const Segment seg = net_.segment(k);
    const Work to = seg.end < tau_end_ ? seg.end : tau_end_;
    if (!(to > tau)) {
      if (!(tau < tau_end_)) break;
      continue;
    }
    SlipPiece<Work> piece{x, v, Net::value(seg, tau) - s * mu_, seg.slope * omega_};
    // From rest the slip starts on the band's edge: in exact arithmetic
    // s A >= 0 there; a rounding below is the edge itself.
    if (v == 0 && s * piece.acceleration < 0) piece.acceleration = 0;
    const Work length = omega_ == 1 ? to - tau : (to - tau) / omega_;  // exact when w = 1
    ++summary_->sign_tests;
    const Work h = piece.first_stop(s, length, summary_->root_function_calls);
    if (h >= 0) {
      const Work tau_stop = h >= length ? to : tau + h * omega_;
      SlipEnd<Work> end;
      end.stops = true;
      end.tau = tau_stop;
      end.x = piece.position_at(h);
      end.v = 0;
      end.acceleration = piece.acceleration_at(h);
      // What follows the stop: the at-rest rule at the stop.
      const Segment after = net_.segment(net_.segment_at(tau_stop));
      const int next = direction_from(Net::value(after, tau_stop), after.slope);
      if (next == s && v == 0 && !(tau_stop - tau > Traits::time_resolution(tau))) {
        // Slid from rest and stopped again within the time resolution, the
        // rule still saying "on": g falls through the band faster than the
        // engine resolves (a jerk of 6e229: found by fuzzing), and going on
        // would stop again at once, for ever. The mass stays; the stick's
        // search takes it from here.
        end.next_direction = 0;
        return end;
      }
      if (next == s) {
        // A touch: v = 0 at an instant, the slip goes on the same way.
        ++summary_->touches;
        tau = tau_stop;
        x = end.x;
        v = 0;
        k = net_.segment_at(tau) - 1;  // the loop's ++k comes back to it
        continue;
      }
      end.next_direction = next;
      return end;
    }
    // No stop on this piece: carry the state to its end.
    x = piece.position_at(length);
    v = piece.velocity_at(length);
    tau = to;
    if (!(tau < tau_end_)) {
      SlipEnd<Work> end;
      end.tau = tau_end_;
      end.x = x;
      end.v = v;
      end.acceleration = piece.acceleration_at(length);
      return end;
    }
  }
  SlipEnd<Work> end;
  end.tau = tau_end_;
  end.x = x;
  end.v = v;
  return end;
}

}  // namespace frictionref::detail
