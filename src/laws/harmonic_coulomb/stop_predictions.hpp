// Predicted stops of the seed's model (docs/theory.md 3.5).
//
// A slip from rest that starts at the same forcing phase (mod 2 pi, and mod
// pi with the sign flipped: the motion is odd under t -> t + pi / w) as an
// earlier one stops at nearly the same time after its start; in a steady
// state, exactly. A few start phases are kept with the slip's length and the
// derivative of that length with respect to the start, for a first-order
// guess that Halley's method then polishes (one evaluation per stop in a
// steady state).
#pragma once

#include <array>
#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "laws/harmonic_coulomb/force_crossings.hpp"

namespace frictionref::detail {

template <class Work>
class StopPredictions {
 public:
  struct Prediction {
    bool valid = false;
    Work phase = 0;  // start phase mod 2 pi (in [-pi, pi]) of the equivalent forward slip
    Work length = 0;
    Work dlength_dstart = 0;
  };

  // A prediction is used for starts within this many radians of its own (its
  // first-order guess is then off by ~1e-3 at worst, which Halley's method
  // removes in two steps).
  static constexpr double kWindow = 0.05;

  // The start phase of a slip of sign s starting at tau, as the phase of the
  // equivalent forward slip, in [-pi, pi] give or take rounding: only compared
  // with other such phases within kWindow, so the period count need not be
  // exact.
  static Work normalised_phase(const Work& tau, int s) {
    const Work shifted = s > 0 ? tau : tau - boost::math::constants::pi<Work>();
    return shifted -
           boost::math::constants::two_pi<Work>() * ForceCrossings<Work>::periods_in(shifted);
  }

  // The prediction for a start at `phase`, or nullptr.
  const Prediction* find(const Work& phase) const {
    const int slot = slot_for(phase);
    return slot >= 0 ? &slots_[slot] : nullptr;
  }

  // First-order guess of the stop of a slip from rest starting at tau.
  static Work guess(const Prediction& p, const Work& tau, const Work& phase) {
    return tau + p.length + p.dlength_dstart * (phase - p.phase);
  }

  // Records the stop `length` after a start at `phase`; dstop_dstart is
  // d(stop time)/d(start time) there. Replaces the slot of this start phase,
  // else the oldest one.
  void remember(const Work& phase, const Work& length, const Work& dstop_dstart) {
    int slot = slot_for(phase);
    if (slot < 0) {
      slot = next_slot_;
      next_slot_ = (next_slot_ + 1) % static_cast<int>(slots_.size());
    }
    slots_[slot] = {true, phase, length, dstop_dstart - 1};
  }

 private:
  int slot_for(const Work& phase) const {
    using std::fabs;
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].valid && fabs(phase - slots_[i].phase) < Work(kWindow))
        return static_cast<int>(i);
    return -1;
  }

  std::array<Prediction, 4> slots_{};
  int next_slot_ = 0;
};

}  // namespace frictionref::detail
