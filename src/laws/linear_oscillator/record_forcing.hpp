// A ground record's part of the general model's forcing (docs/theory.md 9.6):
// the record enters as the force -m a_g(t), in the engine's units
//
//   r(tau) = -a_g(tau / w) / w,
//
// linear on each of the record's segments (numbered as in
// net_acceleration.hpp: the constant 0 before the first sample and from the
// last on, where a_g jumps to and from 0). The closed forms of the slip and
// the stick hold on one segment; the laws walk them in order.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>

#include "frictionref/ground_motion.hpp"
#include "laws/rigid_block_record/net_acceleration.hpp"

namespace frictionref::detail {

// r on one segment: r(tau) = at_begin + slope (tau - begin), tau in [begin, end).
template <class Work>
struct RecordPiece {
  Work begin = -std::numeric_limits<Work>::infinity();
  Work end = std::numeric_limits<Work>::infinity();
  Work at_begin = 0;
  Work slope = 0;  // per unit of tau

  Work value(const Work& tau) const {
    if (slope == 0) return at_begin;
    return at_begin + slope * (tau - begin);
  }
  // The magnitude value(tau)'s rounding is a few ulps of.
  Work magnitude(const Work& tau) const {
    using std::fabs;
    if (slope == 0) return fabs(at_begin);
    return fabs(at_begin) + fabs(slope * (tau - begin));
  }
  // >= |r| on [from, to] within the piece (r is linear: its ends decide).
  Work max_abs(const Work& from, const Work& to) const {
    const Work a = magnitude(from), b = magnitude(to);
    return a > b ? a : b;
  }
};

template <class Work>
class RecordForcing {
 public:
  RecordForcing() = default;  // no record: r = 0
  RecordForcing(std::shared_ptr<const GroundMotion> record, const Work& omega) : omega_(omega) {
    if (record) {
      peak_ = Work(record->pga()) / omega;
      net_.emplace(std::move(record), omega, Work(0));
    }
  }

  bool present() const { return net_.has_value(); }
  // >= |r| everywhere.
  const Work& peak() const { return peak_; }

  // The segment that holds tau (the right one at a sample time).
  RecordPiece<Work> piece_at(const Work& tau) const {
    if (!net_) return {};
    return piece(net_->segment_at(tau));
  }

  // Segments by number (a record present; net_acceleration.hpp), for a
  // stick's walk: the number of the one that holds tau, of the first
  // interior one that ends at or after tau (samples() if none), the segment
  // itself, and the test in double that skips one well inside a band.
  std::size_t segment_at(const Work& tau) const { return net_->segment_at(tau); }
  std::size_t first_ending_at_or_after(const Work& tau) const {
    return net_->first_ending_at_or_after(tau);
  }
  std::size_t samples() const { return net_->samples(); }
  Work segment_end(std::size_t k) const { return net_->segment_end(k); }
  // w r = -a_g on segment k, shifted by `offset`, strictly inside the band
  // (NetAcceleration::strictly_inside: both samples by the slack).
  bool strictly_inside(std::size_t k, double offset, double band, double extra, double per_change,
                       bool below_only) const {
    return net_->strictly_inside(k, offset, band, extra, per_change, below_only);
  }
  RecordPiece<Work> piece(std::size_t k) const {
    const auto s = net_->segment(k);
    RecordPiece<Work> piece;
    piece.begin = s.begin;
    piece.end = s.end;
    piece.at_begin = s.at_begin / omega_;
    piece.slope = s.slope / omega_;
    return piece;
  }

 private:
  std::optional<NetAcceleration<Work>> net_;
  Work omega_ = 1;
  Work peak_ = 0;
};

}  // namespace frictionref::detail
