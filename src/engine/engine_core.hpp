// The implementation behind the public BasicExactEngine: an event loop
// (event_loop.hpp) running one family of phase laws. The public class holds
// a pointer to this interface, so the laws, their state and their helpers
// stay out of the public headers (pattern: Ceres' internal/).
#pragma once

#include <memory>

#include "engine/root_finding.hpp"
#include "frictionref/exact_engine.hpp"

namespace frictionref::detail {

template <class Real>
class EngineCore {
 public:
  virtual ~EngineCore() = default;
  virtual bool next(BasicPhase<Real>& phase) = 0;
  virtual const BasicSummary<Real>& summary() const = 0;
  virtual const BasicModel<Real>& model() const = 0;
  virtual const Real& t_end() const = 0;
};

// The event loop with the family of laws that fits the model: the seed's
// closed-form critical times for BasicModel::is_harmonic_coulomb(), the
// general linear-oscillator laws otherwise. Validates; throws InvalidInput.
template <class Real>
std::unique_ptr<EngineCore<Real>> make_engine_core(const BasicModel<Real>& model,
                                                   const Real& t_end,
                                                   const SolveOptions& options);

// A root solver that lost its bracket or hit its iteration cap (an internal
// invariant broken), thrown by the laws and reported as
// Termination::numerical_failure by the event loop.
struct RootFailure {
  RootStatus status;
};

template <class Result>
const Result& checked(const Result& root) {
  if (!root.ok()) throw RootFailure{root.status};
  return root;
}

}  // namespace frictionref::detail
