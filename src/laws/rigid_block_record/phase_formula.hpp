// Dense output of a rigid block under a ground motion: inside a slip, the
// state is carried from the phase's start to each segment it crosses once
// (as the engine did), then evaluated by the segment's closed form.
#pragma once

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/rigid_block_record/net_acceleration.hpp"
#include "laws/rigid_block_record/slip_piece.hpp"

namespace frictionref::detail {

template <class Real>
class RigidBlockRecordFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;
  using Net = NetAcceleration<Work>;

  RigidBlockRecordFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : model_(model),
        phase_(phase),
        net_(model.ground_motion, Work(model.omega), Work(model.force_offset) / Work(model.mass)),
        omega_(model.omega),
        sign_(phase.kind == PhaseKind::slip_forward ? 1 : -1) {
    if (phase.kind == PhaseKind::stick) return;
    const Work mu = Work(model.friction) / Work(model.mass);
    Work tau = omega_ * Work(phase.t_begin);
    const Work tau_end = omega_ * Work(phase.t_end);
    Work x(phase.x_begin), v(phase.v_begin);
    for (std::size_t k = net_.segment_at(tau); k < net_.segments(); ++k) {
      const auto seg = net_.segment(k);
      SlipPiece<Work> piece{x, v, Net::value(seg, tau) - sign_ * mu, seg.slope * omega_};
      if (v == 0 && sign_ * piece.acceleration < 0) piece.acceleration = 0;
      starts_.push_back(tau);
      pieces_.push_back(piece);
      if (!(seg.end < tau_end)) break;
      const Work length = (seg.end - tau) / omega_;
      x = piece.position_at(length);
      v = piece.velocity_at(length);
      tau = seg.end;
    }
  }

  std::unique_ptr<const PhaseFormula<Real>> for_phase(
      const BasicPhase<Real>& phase) const override {
    return std::make_unique<RigidBlockRecordFormula>(model_, phase);
  }

  BasicState<Real> at(const Real& t) const override {
    if (pieces_.empty()) return rest_state(phase_, t);  // a stick
    const auto [piece, h] = piece_at(t);
    return slip_state(phase_, t, Real(piece.position_at(h)), Real(piece.velocity_at(h)),
                      Real(piece.acceleration_at(h)));
  }

 private:
  std::pair<SlipPiece<Work>, Work> piece_at(const Real& t) const {
    const Work tau = omega_ * Work(t);
    std::size_t j = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), tau) -
                                             starts_.begin());
    j = j == 0 ? 0 : j - 1;
    return {pieces_[j], (tau - starts_[j]) / omega_};
  }

  BasicModel<Real> model_;
  BasicPhase<Real> phase_;
  Net net_;
  Work omega_;
  int sign_;
  std::vector<Work> starts_;             // tau at each piece's start
  std::vector<SlipPiece<Work>> pieces_;  // the slip on each segment it crosses
};

}  // namespace frictionref::detail
