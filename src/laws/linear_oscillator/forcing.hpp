// The driving force of the general model in the engine's units (docs/theory.md
// 7.1): with tau = w t (w = model.omega) and forces as velocity changes per
// radian of tau,
//
//   g(tau) = f0 + sum_j a_j sin(q_j tau + phi_j),
//   f0 = F0 / (m w),  a_j = B_j / (m w),  q_j = w_j / w,
//
// where term 0 is the first harmonic B sin(w t) (q = 1, phi = 0) when B != 0.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <vector>

#include "frictionref/model.hpp"
#include "numeric/integer_power.hpp"

namespace frictionref::detail {

template <class Work>
struct ForcingTerm {
  Work a;      // amplitude [velocity per radian of tau]
  Work q;      // frequency relative to w; > 0
  Work phase;  // [rad]
};

template <class Work>
class Forcing {
 public:
  Forcing() = default;
  template <class Real>
  explicit Forcing(const BasicModel<Real>& model) {
    const Work mw = Work(model.mass) * Work(model.omega);
    constant_ = Work(model.force_offset) / mw;
    if (model.amplitude != 0) terms_.push_back({Work(model.amplitude) / mw, Work(1), Work(0)});
    for (const auto& h : model.harmonics)
      if (h.amplitude != 0)
        terms_.push_back(
            {Work(h.amplitude) / mw, Work(h.omega) / Work(model.omega), reduced_phase(h.phase)});
    for (int k = 0; k < kBounds; ++k) {
      bounds_[k] = 0;
      for (const auto& term : terms_) {
        using std::fabs;
        bounds_[k] += fabs(term.a) * integer_power(term.q, k);
      }
    }
  }

  const std::vector<ForcingTerm<Work>>& terms() const { return terms_; }
  // phi mod 2 pi in [-pi, pi], computed in 50 digits: q tau + phi then keeps
  // the relative accuracy of q tau however large the given phase.
  template <class Real>
  static Work reduced_phase(const Real& phase) {
    using std::fabs;
    if (fabs(phase) <= 4) return Work(phase);
    using Wide = boost::multiprecision::cpp_bin_float_50;
    const Wide two_pi = boost::math::constants::two_pi<Wide>();
    Wide reduced = fmod(Wide(phase), two_pi);
    if (reduced > boost::math::constants::pi<Wide>()) reduced -= two_pi;
    if (reduced < -boost::math::constants::pi<Wide>()) reduced += two_pi;
    return static_cast<Work>(reduced);
  }

  const Work& constant() const { return constant_; }
  bool oscillates() const { return !terms_.empty(); }

  // sum_j |a_j| q_j^k >= |d^k/dtau^k (g - f0)| everywhere, k = 0..4.
  const Work& bound(int k) const { return bounds_[k]; }

 private:
  static constexpr int kBounds = 5;
  std::vector<ForcingTerm<Work>> terms_;
  Work constant_ = 0;
  Work bounds_[kBounds] = {0, 0, 0, 0, 0};
};

}  // namespace frictionref::detail
