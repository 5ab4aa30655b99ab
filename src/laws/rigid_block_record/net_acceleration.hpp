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
#include <cstddef>
#include <limits>
#include <vector>

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

  NetAcceleration(const GroundMotion& record, const Work& omega, const Work& offset)
      : offset_(offset), tau_(record.t.size()), a_(record.a.size()) {
    for (std::size_t i = 0; i < tau_.size(); ++i) {
      tau_[i] = omega * Work(record.t[i]);
      a_[i] = Work(record.a[i]);
    }
  }

  std::size_t segments() const { return tau_.size() + 1; }

  // The segment that holds tau (the right one at a sample time).
  std::size_t segment_at(const Work& tau) const {
    return static_cast<std::size_t>(std::upper_bound(tau_.begin(), tau_.end(), tau) - tau_.begin());
  }

  Segment segment(std::size_t k) const {
    const Work infinity = std::numeric_limits<Work>::infinity();
    const std::size_t n = tau_.size();
    if (k == 0) return {0, -infinity, tau_.front(), offset_, Work(0)};
    if (k >= n) return {n, tau_.back(), infinity, offset_, Work(0)};
    const std::size_t i = k - 1;
    // The slope from the samples' difference, so g at the segment's end is
    // offset - a_{i+1} to rounding.
    const Work slope = -(a_[i + 1] - a_[i]) / (tau_[i + 1] - tau_[i]);
    return {k, tau_[i], tau_[i + 1], offset_ - a_[i], slope};
  }

  // g at tau on segment s (tau in [s.begin, s.end]; the left limit at s.end).
  static Work value(const Segment& s, const Work& tau) {
    if (s.slope == 0) return s.at_begin;
    return s.at_begin + s.slope * (tau - s.begin);
  }

 private:
  Work offset_;            // F0 / m
  std::vector<Work> tau_;  // w t_i
  std::vector<Work> a_;    // a_g at tau_i
};

}  // namespace frictionref::detail
