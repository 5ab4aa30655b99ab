// Compiled with -mavx2 -mfma -ffp-contract=off (src/CMakeLists.txt) and
// entered only where double_double_lanes_available(). It includes nothing
// that defines inline functions of the library or the standard library, so
// no AVX2 copy of a shared inline function can be chosen by the linker for
// the rest of the program.
#include "laws/harmonic_coulomb/double_double_slip.hpp"

#include "laws/harmonic_coulomb/double_double_slip_rows.hpp"
#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_table.hpp"
#include "numeric/double_double_trig.hpp"

namespace frictionref::detail {

// The eight lanes' rows: double_double_slip_wide.cpp.
extern template void DoubleDoubleSlip::evaluate_lanes<8>(const double*, std::size_t, double*,
                                                         double*, double*, unsigned char*) const;
namespace {

using lanes::Bounded;
using lanes::envelope;
using lanes::exact;
using lanes::finite;
using lanes::first;
using lanes::keep;
using lanes::kRange;
using lanes::Lanes;
using lanes::lanes_of;
using lanes::magnitude;
using lanes::Mask;
using lanes::moderate;
using lanes::Pair;
using lanes::quotient;
using lanes::splat;
using lanes::Trig;
using lanes::trig_error;
using lanes::seed_slip_form::acceleration_at;
using lanes::seed_slip_form::position_at;
using lanes::seed_slip_form::velocity_at;

}  // namespace

void double_double_sin_cos(double hi, double lo, double out[5]) {
  const DoubleDoubleTrigTable& table = double_double_trig_table();
  const Trig trig = sin_cos(Pair{splat(hi), splat(lo)}, _mm_set1_epi32(0), table);
  out[0] = first(trig.sin.hi);
  out[1] = first(trig.sin.lo);
  out[2] = first(trig.cos.hi);
  out[3] = first(trig.cos.lo);
  out[4] = first(
      trig_error(splat(0), magnitude(lanes::nearest_integer(splat(hi) * table.steps_per_radian))));
}

DoubleDoubleSlip::DoubleDoubleSlip(const SeedSlipStart& s) {
  if (!(finite(s.omega) && finite(s.amplitude) && finite(s.mass) && finite(s.friction) &&
        finite(s.force_offset) && finite(s.t_begin) && finite(s.x_begin) && finite(s.v_begin)))
    return;
  if (!(s.omega > 0 && s.mass > 0 && (s.sign == 1 || s.sign == -1))) return;
  if (!(moderate(s.omega) && moderate(s.mass) && moderate(s.amplitude) && moderate(s.friction) &&
        moderate(s.force_offset) && moderate(s.omega * s.mass)))
    return;
  const DoubleDoubleTrigTable& table = double_double_trig_table();
  const Lanes omega = splat(s.omega);
  const Pair a = lanes::two_prod(omega, splat(s.t_begin));  // w t_a exactly
  if (!(__builtin_fabs(first(a.hi)) <= 0x1p24)) return;
  // j_a pi/128 nearest w t_a (|j_a| < 2^30), to 2^-79 for |w t_a| <= 2^24.
  const Lanes j = lanes::nearest_integer(a.hi * table.steps_per_radian);
  const Bounded base_angle = lanes::table_angle(j, table);
  const long long j_a = static_cast<long long>(first(j));
  base_index_ = static_cast<int>(j_a & (DoubleDoubleTrigTable::kSize - 1));

  const Pair mass_omega = lanes::two_prod(splat(s.mass), omega);
  const Bounded b = quotient(s.amplitude, mass_omega);
  const Bounded r = quotient(s.friction, mass_omega);
  const Bounded inverse_omega = quotient(1.0, Pair{omega, splat(0)});
  const Bounded angle = exact(a);
  const Bounded start_offset = angle - base_angle;  // |.| <= pi/256: no table step
  const Trig start_trig = sin_cos(start_offset.value, _mm_set1_epi32(base_index_), table);
  const Lanes start_error = trig_error(start_offset.error, splat(1));
  const Bounded start_sin{start_trig.sin, start_error}, start_cos{start_trig.cos, start_error};
  // s r - f0: the constant part of the force against the slip (the seed's
  // bounds untouched where F0 = 0).
  const Bounded s_r = s.sign > 0 ? r : -r;
  const Bounded sr = s.force_offset == 0 ? s_r : s_r - quotient(s.force_offset, mass_omega);
  const Bounded moving = exact(splat(s.v_begin)) + b * start_cos;  // v_a + b cos a
  const Bounded b_over_omega = b * inverse_omega;

  base_angle_ = keep(base_angle);
  v0_ = keep(moving + sr * angle);
  b_ = keep(b);
  sr_ = keep(sr);
  wb_ = keep(exact(omega) * b);
  wsr_ = keep(exact(omega) * sr);
  x0_ = keep(exact(splat(s.x_begin)) + b_over_omega * start_sin);
  w_over_omega_ = keep(moving * inverse_omega);
  b_over_omega_ = keep(b_over_omega);
  half_sr_over_omega_ = keep(lanes::scaled(sr * inverse_omega, 0.5));
  omega_ = s.omega;
  a_hi_ = first(a.hi);
  a_lo_ = first(a.lo);
  const Constant* const all[] = {
      &base_angle_,        &v0_, &b_, &sr_, &wb_, &wsr_, &x0_, &w_over_omega_, &b_over_omega_,
      &half_sr_over_omega_};
  for (const Constant* c : all)
    if (!finite(*c)) return;

  // Bounds on the errors of x, v and a for |h| up to 2, 8, 64 and 513 rad (one
  // range per lane), from the closed form on envelopes of its operands:
  // |tau| <= |w t_a| + h_max, |y| = |tau - j_a pi/128| <= h_max + pi/256. A
  // time takes the bounds of the smallest range that holds its own h, so its
  // answer depends on nothing else.
  static_assert(sizeof kRange / sizeof kRange[0] == kRanges && kRanges == 4, "a range per lane");
  const Lanes h_max{kRange[0], kRange[1], kRange[2], kRange[3]};
  const Lanes tau_max = splat(__builtin_fabs(a_hi_)) + h_max + 1;
  const lanes::Envelope tau{exact(tau_max)};
  const lanes::Envelope h{
      {{h_max, splat(0)},
       lanes::kAddError * (tau_max + __builtin_fabs(a_hi_)) + lanes::kUnderflowSlack}};
  const Lanes y_error = base_angle_.error +
                        lanes::kAddError * (tau_max + __builtin_fabs(base_angle_.hi)) +
                        lanes::kUnderflowSlack;
  const Lanes steps_max = (h_max + 1) * table.steps_per_radian + 1;
  const lanes::Envelope trig{{{splat(1 + 0x1p-50), splat(0)}, trig_error(y_error, steps_max)}};
  const Lanes velocity =
      velocity_at(envelope(v0_), envelope(b_), envelope(sr_), tau, trig).bound.error;
  const Lanes acceleration = acceleration_at(envelope(wb_), envelope(wsr_), trig).bound.error;
  const Lanes position =
      position_at(envelope(x0_), envelope(w_over_omega_), envelope(half_sr_over_omega_),
                  envelope(b_over_omega_), h, trig)
          .bound.error;
  for (int k = 0; k < kRanges; ++k) {
    velocity_error_[k] = velocity[k];
    acceleration_error_[k] = acceleration[k];
    position_error_[k] = position[k];
    if (!(finite(velocity[k]) && finite(acceleration[k]) && finite(position[k]))) return;
  }
  usable_ = true;
}

void DoubleDoubleSlip::evaluate(const double* t, std::size_t n, double* x, double* v, double* a,
                                unsigned char* decided) const {
  const std::size_t wide = eight_lane_rows(n);
  if (wide > 0) evaluate_lanes<8>(t, wide, x, v, a, decided);
  if (wide < n) evaluate_lanes<4>(t + wide, n - wide, x + wide, v + wide, a + wide, decided + wide);
}

template void DoubleDoubleSlip::evaluate_lanes<4>(const double*, std::size_t, double*, double*,
                                                  double*, unsigned char*) const;

}  // namespace frictionref::detail
