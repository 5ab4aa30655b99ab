// The general model's long double oscillator (oscillator.hpp) for its dense
// output: built on first need, since the fast paths decide most rows without
// it, and shared by the formulas of one model's phases
// (PhaseFormula::for_phase), so that a sampler builds it once per model
// rather than once per phase (its forcing bounds, steady responses and
// transition functions cost more than a phase's rows on the fast path).
#pragma once

#include <memory>
#include <mutex>

#include "engine/scalar_traits.hpp"
#include "frictionref/model.hpp"
#include "laws/linear_oscillator/oscillator.hpp"

namespace frictionref::detail {

template <class Real>
class SharedOscillator {
 public:
  using Work = work_t<Real>;

  explicit SharedOscillator(const BasicModel<Real>& model) : model_(model) {}
  SharedOscillator(const SharedOscillator&) = delete;
  SharedOscillator& operator=(const SharedOscillator&) = delete;

  const BasicModel<Real>& model() const { return model_; }

  // Built once, also when formulas are used from several threads.
  const Oscillator<Work>& oscillator() const {
    std::call_once(built_,
                   [this] { oscillator_ = std::make_unique<const Oscillator<Work>>(model_); });
    return *oscillator_;
  }

 private:
  BasicModel<Real> model_;
  mutable std::once_flag built_;
  mutable std::unique_ptr<const Oscillator<Work>> oscillator_;
};

}  // namespace frictionref::detail
