// The seed's fast path's closed form on the lanes (double_double_slip.hpp)
// and its row loop, for the translation units of each lane width:
// double_double_slip.cpp (four lanes, AVX2) and double_double_slip_wide.cpp
// (eight, AVX-512), which instantiate evaluate_lanes for their own width.
// Only for those translation units (their flags: src/CMakeLists.txt).
#pragma once

#include <cstddef>

#include "laws/harmonic_coulomb/double_double_slip.hpp"
#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_rows.hpp"
#include "numeric/double_double_sum.hpp"
#include "numeric/double_double_table.hpp"
#include "numeric/double_double_trig.hpp"

// The closed form in the lanes' own namespace (one per width).
namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {
namespace seed_slip_form {

// The closed form (double_double_slip.hpp), one text for the lanes' values
// (Pair) and for the bounds on their errors (Envelope), each a sum of
// products (double_double_sum.hpp). The coefficients come negated where the
// form subtracts (an envelope is the same for both signs).
template <class V>
V velocity_at(const V& v0, const V& minus_b, const V& minus_sr, const V& tau, const V& cos_tau) {
  Sum<V> v(v0);  // v0 - b cos tau - sr tau
  v.add(minus_b, cos_tau);
  v.add(minus_sr, tau);
  return v.total();
}
template <class V>
V acceleration_at(const V& wb, const V& minus_wsr, const V& sin_tau) {
  Sum<V> a(minus_wsr);  // wb sin tau - wsr
  a.add(wb, sin_tau);
  return a.total();
}
template <class V>
V position_at(const V& x0, const V& w_over_omega, const V& minus_half_sr_over_omega,
              const V& minus_b_over_omega, const V& h, const V& sin_tau) {
  Sum<V> x(x0);  // x0 + h w / omega - h^2 sr / (2 omega) - sin tau b / omega
  x.add(w_over_omega, h);
  x.add(minus_half_sr_over_omega, h * h);
  x.add(minus_b_over_omega, sin_tau);
  return x.total();
}

}  // namespace seed_slip_form
}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes

namespace frictionref::detail {

template <int kWidth>
void DoubleDoubleSlip::evaluate_lanes(const double* t, std::size_t n, double* x, double* v,
                                      double* a, unsigned char* decided) const {
  static_assert(kWidth == lanes::kLanes, "instantiated where the lanes have this width");
  using namespace lanes;  // NOLINT: the lanes' arithmetic throughout
  const DoubleDoubleTrigTable& table = double_double_trig_table();
  const Lanes omega = splat(omega_);
  const Pair angle{splat(a_hi_), splat(a_lo_)};
  const Pair base_angle = lanes_of(base_angle_), v0 = lanes_of(v0_), minus_b = -lanes_of(b_),
             minus_sr = -lanes_of(sr_), wb = lanes_of(wb_), minus_wsr = -lanes_of(wsr_),
             x0 = lanes_of(x0_), w_over_omega = lanes_of(w_over_omega_),
             minus_b_over_omega = -lanes_of(b_over_omega_),
             minus_half_sr_over_omega = -lanes_of(half_sr_over_omega_);
  const lanes::Index base = lanes::splat_index(base_index_);
  for (std::size_t i = 0; i < n; i += kWidth) {
    const std::size_t used = lanes::group_size(i, n);
    const Lanes time = lanes::group_times(t, i, used);
    const Pair tau = lanes::two_prod(omega, time);  // w t exactly
    const Pair y = tau - base_angle;
    const Mask in_range = magnitude(y.hi) <= splat(kLargestAngle);
    const Trig trig = sin_cos(y, base, table);
    const Pair h = tau - angle;
    const Pair velocity = lanes::seed_slip_form::velocity_at(v0, minus_b, minus_sr, tau, trig.cos);
    const Pair acceleration = lanes::seed_slip_form::acceleration_at(wb, minus_wsr, trig.sin);
    const Pair position = lanes::seed_slip_form::position_at(
        x0, w_over_omega, minus_half_sr_over_omega, minus_b_over_omega, h, trig.sin);
    const lanes::RangePick pick(h.hi);
    const Lanes velocity_error = pick(velocity_error_);
    const Lanes acceleration_error = pick(acceleration_error_);
    const Lanes position_error = pick(position_error_);
    const lanes::Decisions ok{in_range & lanes::decided(position, position_error),
                              in_range & lanes::decided(velocity, velocity_error),
                              in_range & lanes::decided(acceleration, acceleration_error)};
    lanes::store_group(i, used, position, velocity, acceleration, ok, x, v, a, decided);
  }
}

}  // namespace frictionref::detail
