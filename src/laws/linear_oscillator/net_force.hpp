// The net non-friction force on a mass at rest (docs/theory.md 7.5), in the
// engine's units: n(tau) = g(tau) - rho^2 y at a fixed position y = w x. The
// mass stays while |n| <= rs; the event search runs on
//
//   f(tau) = rs^2 - n^2 = (rs - n)(rs + n),
//
// smooth, positive inside the band and zero exactly where |n| = rs, with
// f' = -2 n n', f'' = -2 (n'^2 + n n''), f''' = -2 (3 n' n'' + n n''') and
// |n^(k)| <= sum |a| q^k for k >= 1 (forcing.hpp), plus the record's slope
// |d| for k = 1: with a ground record, n holds on one of its segments, where
// the record's part is linear (record_forcing.hpp).
//
// One-way (a block that never moves towards negative x) only the band's
// upper edge ends a stick: the search runs on f = rs - n instead (jet_upper),
// with f' = -n', f'' = -n'', f''' = -n'''.
//
// The gap rs - |n| is also computed from the band's edge on n's side s,
// (rs - s f0) + s rho^2 y - s h (h the harmonics), where that is sharper: with
// F0 near +-Rs and k x small, f0 - rho^2 y rounds to the ulps of F0 while the
// slip's closed form (which subtracts s r from f0 first) resolves far less;
// the two disagreed inside that rounding, and a stop the slip resolved was
// followed by a breakaway N from the position could not tell apart, over
// and over (found by fuzzing).
#pragma once

#include <cmath>
#include <limits>

#include "laws/linear_oscillator/oscillator.hpp"
#include "numeric/first_zero.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Work>
class NetForce {
 public:
  struct Point {
    Work n = 0, d1 = 0, d2 = 0;  // n, n', n''
    Work e_n = 0, e_d1 = 0, e_d2 = 0;
    Work gap = 0, e_gap = 0;  // rs - |n|, the sharper of its two forms
  };

  // `piece`: the record's segment the force is looked at on (none without a
  // record), and [from, to] the part of it the bounds need hold on: a stick
  // searched to a horizon early in a long segment must not take the record's
  // value at the segment's far end for its own (a ramp to 9.7e-3 over 1284 s
  // made the rounding margin 1e20 times rs^2 at t = 2e-14, and every stick
  // "broke away" one resolution after it began: found by fuzzing).
  NetForce(const Oscillator<Work>& oscillator, const Work& y, const RecordPiece<Work>& piece = {},
           const Work& from = -std::numeric_limits<Work>::infinity(),
           const Work& to = std::numeric_limits<Work>::infinity())
      : o_(&oscillator),
        offset_(oscillator.forcing().constant() - oscillator.rho2() * y),
        piece_(piece) {
    using std::fabs;
    const Forcing<Work>& f = oscillator.forcing();
    mag_offset_ = fabs(oscillator.forcing().constant()) + oscillator.rho2() * fabs(y);
    spring_ = oscillator.rho2() * y;
    for (int side = 0; side < 2; ++side) {
      const Work s = side == 0 ? Work(1) : Work(-1);
      edge_[side] = oscillator.rs() - s * oscillator.forcing().constant();
      mag_edge_[side] = fabs(edge_[side]) + fabs(spring_);
    }
    record_max_ =
        piece.max_abs(from > piece.begin ? from : piece.begin, to < piece.end ? to : piece.end);
    n0_ = fabs(offset_) + f.bound(0) + record_max_;
  }

  Point point(const Work& tau) const {
    using std::fabs;
    const Work eps = std::numeric_limits<Work>::epsilon();
    Point p;
    p.n = offset_;
    Work h = 0;
    Work mag_n = mag_offset_, mag_d1 = 0, mag_d2 = 0;
    Work phase_n = 0, phase_d1 = 0, phase_d2 = 0;
    for (const auto& term : o_->forcing().terms()) {
      const Work theta = term.q * tau + term.phase;
      const SinCos<Work> sc = sin_cos(theta);
      const Work abs_a = fabs(term.a);
      const Work q2 = term.q * term.q;
      p.n += term.a * sc.sin;
      h += term.a * sc.sin;
      p.d1 += term.a * term.q * sc.cos;
      p.d2 -= term.a * q2 * sc.sin;
      mag_n += abs_a;
      mag_d1 += abs_a * term.q;
      mag_d2 += abs_a * q2;
      // The argument is rounded by up to |theta| ulps (radians per ulp).
      const Work arg = fabs(theta) + fabs(term.phase);
      phase_n += abs_a * arg;
      phase_d1 += abs_a * term.q * arg;
      phase_d2 += abs_a * q2 * arg;
    }
    if (piece_.slope != 0 || piece_.at_begin != 0) {
      const Work record = piece_.value(tau);
      p.n += record;
      h += record;
      p.d1 += piece_.slope;
      mag_n += piece_.magnitude(tau);
      mag_d1 += fabs(piece_.slope);
    }
    const Work k = kUlps * eps;
    p.e_n = k * mag_n + eps * phase_n;
    p.e_d1 = k * mag_d1 + eps * phase_d1;
    p.e_d2 = k * mag_d2 + eps * phase_d2;
    const Work rs = o_->rs();
    p.gap = rs - fabs(p.n);
    p.e_gap = p.e_n + 2 * eps * rs;
    const int side = p.n >= 0 ? 0 : 1;
    const Work s = side == 0 ? Work(1) : Work(-1);
    const Work e_edge = k * (mag_edge_[side] + (mag_n - mag_offset_)) + eps * phase_n;
    if (e_edge < p.e_gap) {
      p.gap = edge_[side] + s * (spring_ - h);
      p.e_gap = e_edge;
    }
    return p;
  }

  // The jet of f = rs^2 - n^2.
  Jet<Work> jet(const Point& p) const {
    using std::fabs;
    const Work rs = o_->rs();
    const Work eps = std::numeric_limits<Work>::epsilon();
    Jet<Work> j;
    const Work an = fabs(p.n), a1 = fabs(p.d1), a2 = fabs(p.d2);
    j.f = p.gap * (rs + an);
    j.d1 = -2 * p.n * p.d1;
    j.d2 = -2 * (p.d1 * p.d1 + p.n * p.d2);
    j.e0 = (rs + an) * p.e_gap * 2 + 4 * eps * fabs(j.f);
    j.e1 = 2 * (a1 * p.e_n + an * p.e_d1) * 2 + 4 * eps * fabs(j.d1);
    j.e2 = 2 * (2 * a1 * p.e_d1 + a2 * p.e_n + an * p.e_d2) * 2 + 8 * eps * (a1 * a1 + an * a2);
    j.tail = an + p.e_n;  // for third_bound: |n| here
    return j;
  }

  // The jet of f = rs - n (one-way: the upper edge alone), and >= |f'''| = |n'''|.
  Jet<Work> jet_upper(const Point& p) const {
    using std::fabs;
    const Work eps = std::numeric_limits<Work>::epsilon();
    Jet<Work> j;
    if (p.n >= 0) {  // rs - |n|, in its sharper form
      j.f = p.gap;
      j.e0 = p.e_gap;
    } else {  // rs + |n| > rs: far from zero
      j.f = o_->rs() - p.n;
      j.e0 = p.e_n + 2 * eps * fabs(j.f);
    }
    j.d1 = -p.d1;
    j.d2 = -p.d2;
    j.e1 = p.e_d1;
    j.e2 = p.e_d2;
    return j;
  }
  Work third_bound_upper() const {
    return o_->forcing().bound(3) * (1 + 64 * std::numeric_limits<Work>::epsilon());
  }

  // >= |f'''| on [tau, tau + h], given the jet at tau: |n| there grows by at
  // most N1 h, which can be far below the global bound of |n| (a harmonic of
  // huge amplitude and tiny frequency hardly moves over the horizon; its
  // amplitude in N0 made the steps so short that the search hit its cap:
  // found by fuzzing).
  Work third_bound(const Jet<Work>& at, const Work& h) const {
    using std::fabs;
    const Forcing<Work>& f = o_->forcing();
    const Work n1 = f.bound(1) + fabs(piece_.slope);
    const Work local = at.tail + n1 * h;
    const Work n0 = local < n0_ ? local : n0_;
    return 2 * (3 * n1 * f.bound(2) + n0 * f.bound(3)) *
           (1 + 64 * std::numeric_limits<Work>::epsilon());
  }

  // >= |n| everywhere on the piece: |f0 - rho^2 y| + sum |a| + max |r_g|.
  Work magnitude_bound() const {
    using std::fabs;
    return fabs(offset_) + o_->forcing().bound(0) + record_max_;
  }

  // >= the rounding-error bound e0 of the jet of f wherever |n| is within
  // rounding of rs, for |tau| <= tau_max.
  Work value_error_bound(const Work& tau_max) const {
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work rs = o_->rs();
    const Work e_n = rounding_near_edge(tau_max);
    // f = rs^2 - n^2 errs by 2 |n| e_n + e_n^2 and its own rounding. The
    // bound only matters where f is near 0, i.e. |n| within e_n of rs: not
    // the largest |n| (a slow harmonic of huge amplitude, or an offset f0
    // balanced by rho^2 y, would make the margin far larger than the
    // rounding at the crossing and delay the breakaway: found by fuzzing).
    const Work n = rs + e_n;
    return (rs + n) * e_n * 2 + 4 * eps * (rs + n) * (rs + n);
  }

  // The same for f = rs - n (jet_upper).
  Work value_error_bound_upper(const Work& tau_max) const {
    const Work eps = std::numeric_limits<Work>::epsilon();
    return rounding_near_edge(tau_max) + 4 * eps * o_->rs();
  }

 private:
  // >= the rounding bound e_n of n wherever |n| is within rounding of rs,
  // for |tau| <= tau_max.
  Work rounding_near_edge(const Work& tau_max) const {
    using std::fabs;
    const Work eps = std::numeric_limits<Work>::epsilon();
    Work mag_n = mag_offset_ + record_max_, phase_n = 0;
    for (const auto& term : o_->forcing().terms()) {
      mag_n += fabs(term.a);
      phase_n += fabs(term.a) * (term.q * tau_max + 2 * fabs(term.phase));
    }
    // The offset's part as sharp as the gap's form at a reachable edge
    // (point() above) allows.
    const Work rs = o_->rs();
    const Work reach = o_->forcing().bound(0) + record_max_;
    Work mag_offset = 0;
    bool reachable = false;
    for (int side = 0; side < 2; ++side) {
      const Work s = side == 0 ? Work(1) : Work(-1);
      if (s * offset_ + reach + kUlps * eps * (mag_offset_ + reach) < rs) continue;  // never near
      reachable = true;
      const Work sharpest = mag_edge_[side] < mag_offset_ ? mag_edge_[side] : mag_offset_;
      if (sharpest > mag_offset) mag_offset = sharpest;
    }
    if (reachable) mag_n += mag_offset - mag_offset_;
    return kUlps * eps * mag_n + eps * phase_n;
  }

  static constexpr int kUlps = 64;
  const Oscillator<Work>* o_;
  Work offset_;                // f0 - rho^2 y
  RecordPiece<Work> piece_;    // the record's part on the segment looked at
  Work record_max_ = 0;        // >= |r_g| on it
  Work mag_offset_;            // |f0| + rho^2 |y|
  Work spring_ = 0;            // rho^2 y
  Work edge_[2] = {0, 0};      // rs - s f0 for s = +1, -1
  Work mag_edge_[2] = {0, 0};  // |rs - s f0| + rho^2 |y|
  Work n0_ = 0;                // >= |n| everywhere
};

}  // namespace frictionref::detail
