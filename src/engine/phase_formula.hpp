// The closed form of one emitted phase, for dense output (the public
// BasicPhaseEvaluator holds one). Each family of phase laws implements it.
#pragma once

#include <memory>

#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"

namespace frictionref::detail {

template <class Real>
class PhaseFormula {
 public:
  virtual ~PhaseFormula() = default;
  // State at t in [t_begin, t_end] (the stored end state at t_end exactly).
  virtual BasicState<Real> at(const Real& t) const = 0;
};

// The formula of the model's family of laws for `phase`.
template <class Real>
std::unique_ptr<const PhaseFormula<Real>> make_phase_formula(const BasicModel<Real>& model,
                                                             const BasicPhase<Real>& phase);

}  // namespace frictionref::detail
