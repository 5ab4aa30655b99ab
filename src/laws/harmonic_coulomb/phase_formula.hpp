// Dense output of the seed's model: the state inside an emitted phase from
// its law. For double, a slip is evaluated first on the fast path
// (double_double_slip.hpp: four times at once in double-double, answers only
// where they are provably the correctly rounded doubles), and in long double
// (one sin_cos per evaluation) where that path cannot decide.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <type_traits>

#include "engine/phase_formula.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/fast_slip_rows.hpp"
#include "laws/harmonic_coulomb/double_double_slip.hpp"
#include "laws/harmonic_coulomb/phase_law.hpp"

namespace frictionref::detail {

template <class Real>
class HarmonicCoulombFormula final : public PhaseFormula<Real> {
 public:
  using Work = work_t<Real>;

  HarmonicCoulombFormula(const BasicModel<Real>& model, const BasicPhase<Real>& phase)
      : model_(model),
        phase_(phase),
        omega_(model.omega),
        law_(model, phase.kind, omega_ * Work(phase.t_begin), Work(phase.x_begin),
             Work(phase.v_begin)) {
    if constexpr (std::is_same_v<Real, double>) {
      if (phase.kind != PhaseKind::stick && double_double_lanes_available()) {
        fast_.emplace(SeedSlipStart{model.omega, model.amplitude, model.mass, model.friction,
                                    slip_sign(phase.kind), phase.t_begin, phase.x_begin,
                                    phase.v_begin});
        if (!fast_->usable()) fast_.reset();
      }
    }
  }

  std::unique_ptr<const PhaseFormula<Real>> for_phase(
      const BasicPhase<Real>& phase) const override {
    return std::make_unique<HarmonicCoulombFormula>(model_, phase);
  }

  BasicState<Real> at(const Real& t) const override {
    BasicState<Real> state{t, 0, 0, 0, phase_.kind};
    columns(&t, 1, &state.x, &state.v, &state.a);
    return state;
  }

  void at_many(const Real* t, std::size_t n, BasicState<Real>* out) const override {
    states_from_columns(*this, phase_.kind, t, n, out);
  }

  void columns(const Real* t, std::size_t n, Real* x, Real* v, Real* a) const override {
    if constexpr (std::is_same_v<Real, double>) {
      if (fast_)
        return fast_slip_rows(*fast_, phase_, t, n, x, v, a,
                              [this](double ti) { return long_double_at(ti); });
    }
    columns_of_states([this](const Real& time) { return long_double_at(time); }, t, n, x, v, a);
  }

  // The state from the long double law alone (what the fast path must agree
  // with; tests compare the two).
  BasicState<Real> long_double_at(const Real& t) const {
    if (phase_.kind == PhaseKind::stick) return rest_state(phase_, t);
    const auto point = law_.point(omega_ * Work(t));
    // v = s (s v).
    return slip_state(phase_, t, Real(law_.position(point)), Real(Work(law_.sign()) * point.speed),
                      Real(law_.acceleration_at(point.at)));
  }

  // The fast path's answer alone, where it decides (tests).
  bool fast_at(const Real& t, BasicState<Real>& state) const {
    if constexpr (std::is_same_v<Real, double>) {
      return fast_ && fast_slip_row(*fast_, phase_, t, state);
    } else {
      (void)t;
      (void)state;
      return false;
    }
  }

 private:
  BasicModel<Real> model_;
  BasicPhase<Real> phase_;
  Work omega_;
  PhaseLaw<Work> law_;
  std::optional<DoubleDoubleSlip> fast_;  // slips of double models, where the CPU allows
};

}  // namespace frictionref::detail
