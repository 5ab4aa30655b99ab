// The net driving acceleration of a rigid block under a ground motion,
// g(tau) = F0 / m - a_g(t), tau = w t (docs/theory.md 9.2): linear on each
// sample interval, constant F0 / m before the first sample and after the
// last (where a_g may jump to and from 0). The record's samples are split
// into segments, numbered
//
//   0          (-inf, tau_0)            g = F0 / m
//   i + 1      [tau_i, tau_{i+1})       g linear, i = 0 .. n - 2
//   n          [tau_{n-1}, +inf)        g = F0 / m
//
// so a search walks segments in order and never meets a kink inside one.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>

#include "frictionref/ground_motion.hpp"

namespace frictionref::detail {

template <class Work>
class NetAcceleration {
 public:
  // g on one segment: g(tau) = at_begin + slope (tau - begin), tau in [begin, end).
  struct Segment {
    std::size_t index;
    Work begin;  // -infinity for segment 0
    Work end;    // +infinity for the last
    Work at_begin;
    Work slope;  // per unit of tau
  };

  // Reads the record's samples where they are (shared, so that an
  // evaluator outliving the caller's model keeps them): a dense-output
  // evaluator is built per slip, and copying 10^4 samples each time would
  // cost more than the slip itself.
  NetAcceleration(std::shared_ptr<const GroundMotion> record, const Work& omega, const Work& offset)
      : record_(std::move(record)),
        offset_(offset),
        omega_(omega),
        t_(record_->t.data()),
        a_(record_->a.data()),
        n_(record_->t.size()),
        offset_double_(static_cast<double>(offset)) {}

  std::size_t segments() const { return n_ + 1; }

  // The segment that holds tau (the right one at a sample time).
  std::size_t segment_at(const Work& tau) const {
    std::size_t low = 0, count = n_;  // upper_bound over tau_i = w t_i
    while (count > 0) {
      const std::size_t step = count / 2;
      if (!(tau < tau_at(low + step))) {
        low += step + 1;
        count -= step + 1;
      } else {
        count = step;
      }
    }
    return low;
  }

  Segment segment(std::size_t k) const {
    const Work infinity = std::numeric_limits<Work>::infinity();
    const std::size_t n = n_;
    if (k == 0) return {0, -infinity, tau_at(0), offset_, Work(0)};
    if (k >= n) return {n, tau_at(n - 1), infinity, offset_, Work(0)};
    const std::size_t i = k - 1;
    const Work a0(a_[i]), a1(a_[i + 1]);
    const Work tau0 = tau_at(i), tau1 = tau_at(i + 1);
    // The slope from the samples' difference, so g at the segment's end is
    // offset - a_{i+1} to rounding.
    const Work slope = -(a1 - a0) / (tau1 - tau0);
    return {k, tau0, tau1, offset_ - a0, slope};
  }

  // True if g lies strictly inside the band (-band, band) (below_only: below
  // band) at both samples of the interior segment k (1 <= k < samples), by
  // more than value()'s rounding there (a few ulps of the magnitudes; the
  // slack is 2^-40 of them): then g, linear between them, reaches the band
  // nowhere on the segment, and a stick may skip it without the division
  // segment() costs. Same result as the full test, faster.
  //
  // In double (a stick walks every sample with it): `band` is the band as
  // band_in_double() gives it, and the slack of 2^-39 covers double's own
  // rounding (a few 2^-53 of the same magnitudes), so that a segment passed
  // here also passes the test in the work type with slack 2^-40.
  bool strictly_inside(std::size_t k, double band, bool below_only) const {
    return strictly_inside(k, offset_double_, band, 0, 0, below_only);
  }
  // The same test for offset - a_g in place of g (a general model's stick:
  // the offset then holds the spring's force), with a further allowance
  // `extra + |a_k - a_{k-1}| * per_change` (the caller's own tolerances: the
  // move of its force within its time resolution, its other terms).
  bool strictly_inside(std::size_t k, double offset, double band, double extra, double per_change,
                       bool below_only) const {
    using std::fabs;
    const double a0 = a_[k - 1], a1 = a_[k];
    const double g0 = offset - a0, g1 = offset - a1;
    double slack = (fabs(a0) + fabs(a1) + fabs(offset)) * 0x1p-39;
    // (Folded away where the caller passes constant zeros: the rigid block's
    // stick walks every sample with this test.)
    if (extra != 0 || per_change != 0) slack += extra + fabs(a1 - a0) * per_change;
    if (below_only) return g0 + slack < band && g1 + slack < band;
    return fabs(g0) + slack < band && fabs(g1) + slack < band;
  }
  // A band for strictly_inside: rounded towards 0 (a double not above it).
  static double band_in_double(const Work& band) {
    double b = static_cast<double>(band);
    if (Work(b) > band) b = std::nextafter(b, 0.0);
    return b;
  }
  // The first segment k >= 1 whose end is at or after tau (samples() if none
  // among the interior ones).
  std::size_t first_ending_at_or_after(const Work& tau) const {
    std::size_t low = 0, count = n_;  // lower_bound over tau_i
    while (count > 0) {
      const std::size_t step = count / 2;
      if (tau_at(low + step) < tau) {
        low += step + 1;
        count -= step + 1;
      } else {
        count = step;
      }
    }
    return low;
  }
  std::size_t samples() const { return n_; }
  // The end of segment k (+infinity for the last).
  Work segment_end(std::size_t k) const {
    return k < n_ ? tau_at(k) : std::numeric_limits<Work>::infinity();
  }

  // g at tau on segment s (tau in [s.begin, s.end]; the left limit at s.end).
  static Work value(const Segment& s, const Work& tau) {
    if (s.slope == 0) return s.at_begin;
    return s.at_begin + s.slope * (tau - s.begin);
  }

 private:
  Work tau_at(std::size_t i) const { return omega_ * Work(t_[i]); }

  std::shared_ptr<const GroundMotion> record_;
  Work offset_;      // F0 / m
  Work omega_;       // tau = w t
  const double* t_;  // the samples' times
  const double* a_;  // a_g at t_i
  std::size_t n_;
  double offset_double_;  // F0 / m rounded to double (within 2^-53 of it)
};

}  // namespace frictionref::detail
