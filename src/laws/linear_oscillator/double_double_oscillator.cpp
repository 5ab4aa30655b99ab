// Compiled with -mavx2 -mfma -ffp-contract=off (src/CMakeLists.txt) and
// entered only where double_double_lanes_available(). It includes nothing
// that defines inline functions of the library or the standard library (see
// double_double_slip.cpp).
#include "laws/linear_oscillator/double_double_oscillator.hpp"

#include "laws/linear_oscillator/double_double_oscillator_rows.hpp"
#include "numeric/double_double_exp.hpp"
#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_rows.hpp"
#include "numeric/double_double_sum.hpp"
#include "numeric/double_double_table.hpp"
#include "numeric/double_double_trig.hpp"

namespace frictionref::detail {

// The eight lanes' rows: double_double_oscillator_wide.cpp.
extern template void DoubleDoubleOscillator::evaluate_lanes<8>(const double*, std::size_t, double*,
                                                               double*, double*,
                                                               unsigned char*) const;

namespace {

using lanes::absolute;
using lanes::Bounded;
using lanes::envelope;
using lanes::Envelope;
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
using lanes::Sum;
using lanes::table_angle;
using lanes::Trig;
using lanes::trig_error;
using lanes::oscillator_form::add_decay;
using lanes::oscillator_form::add_free;
using lanes::oscillator_form::add_share;
using lanes::oscillator_form::phase_of;
using lanes::oscillator_form::polynomial;
using lanes::oscillator_form::State;
using lanes::oscillator_form::Sums;

}  // namespace

void double_double_exp(double hi, double lo, double out[3]) {
  const Pair e = lanes::exp_of(Pair{splat(hi), splat(lo)}, double_double_exp_table());
  out[0] = first(e.hi);
  out[1] = first(e.lo);
  out[2] = lanes::kExpError;
}

void double_double_sum(const double* start, const double* c, const double* f, int n,
                       double out[3]) {
  // Each pair as an exact constant: its lanes and its envelope.
  const auto constant = [](const double* p) { return DoubleDoubleConstant{p[0], p[1], 0}; };
  Sum<Pair> sum(lanes_of(constant(start)));
  Sum<Envelope> sum_bound(envelope(constant(start)));
  for (int j = 0; j < n; ++j) {
    sum.add(lanes_of(constant(c + 2 * j)), lanes_of(constant(f + 2 * j)));
    sum_bound.add(envelope(constant(c + 2 * j)), envelope(constant(f + 2 * j)));
  }
  const Pair total = sum.total();
  out[0] = first(total.hi);
  out[1] = first(total.lo);
  out[2] = first(sum_bound.total().bound.error);
}

DoubleDoubleOscillator::DoubleDoubleOscillator(const OscillatorSlipStart& s) {
  if (!(moderate(s.omega) && moderate(s.amplitude) && moderate(s.mass) && moderate(s.friction) &&
        moderate(s.stiffness) && moderate(s.damping) && moderate(s.force_offset) &&
        moderate(s.omega * s.mass) && finite(s.t_begin) && finite(s.x_begin) && finite(s.v_begin)))
    return;
  if (!(s.omega > 0 && s.mass > 0 && s.stiffness >= 0 && s.damping >= 0 &&
        (s.sign == 1 || s.sign == -1) && s.harmonics >= 0 &&
        s.harmonics <= OscillatorSlipStart::kMaxHarmonics))
    return;
  const bool spring = s.stiffness > 0, damper = s.damping > 0;
  for (int j = 0; j < s.harmonics; ++j)
    if (!(moderate(s.harmonic_amplitude[j]) && moderate(s.harmonic_omega[j]) &&
          s.harmonic_omega[j] > 0 && absolute(s.harmonic_phase[j]) <= 0x1p20))
      return;
  const DoubleDoubleTrigTable& table = double_double_trig_table();
  const Lanes omega = splat(s.omega);
  const Pair a = lanes::two_prod(omega, splat(s.t_begin));  // w t_a exactly
  if (!(absolute(first(a.hi)) <= 0x1p24)) return;

  const Pair mass_omega = lanes::two_prod(splat(s.mass), omega);
  const Bounded mass_omega2 = exact(mass_omega) * exact(omega);
  const Bounded rho2 = exact(splat(s.stiffness)) / mass_omega2;  // 0 without a spring
  const Bounded sigma = lanes::scaled(quotient(s.damping, mass_omega), 0.5);
  const Bounded inverse_omega = quotient(1.0, Pair{omega, splat(0)});
  const Bounded omega_b = exact(omega);
  const Bounded r = quotient(s.friction, mass_omega);
  const Bounded sr = s.sign > 0 ? r : -r;
  const Bounded g0 = s.force_offset == 0 ? -sr : quotient(s.force_offset, mass_omega) - sr;
  const Bounded zero = exact(splat(0));
  // The response to g0: with a spring the steady P = g0 / rho^2; with a
  // damper alone the drift g0 / (2 sigma) h; with neither, g0 accelerates
  // the free motion (a parabola).
  const Bounded steady = spring ? g0 / rho2 : zero;
  const Bounded drift = !spring && damper ? g0 / lanes::scaled(sigma, 2) : zero;
  // The free motion's kind, resolvably: otherwise (near critical damping)
  // the long double path alone.
  Bounded nu = zero, mu = zero;
  if (!spring) {
    free_ = damper ? FreeMotion::decays : FreeMotion::parabola;
  } else {
    const Bounded nu2 = rho2 - sigma * sigma;
    if (first(nu2.value.hi) > 4 * first(nu2.error)) {
      free_ = FreeMotion::oscillation;
      nu = lanes::square_root(nu2);
    } else {
      const Bounded mu2 = sigma * sigma - rho2;
      if (!(first(mu2.value.hi) > 4 * first(mu2.error))) return;
      free_ = FreeMotion::decays;
      mu = lanes::square_root(mu2);
    }
  }

  // The forcing terms: the particular solution and its slope at h = 0.
  Bounded y_p = steady, v_p = drift;
  terms_ = 0;
  for (int j = 0; j < 1 + s.harmonics; ++j) {
    const double amplitude = j == 0 ? s.amplitude : s.harmonic_amplitude[j - 1];
    if (amplitude == 0) continue;  // adds exactly nothing (e.g. a model driven by harmonics)
    const Bounded b = quotient(amplitude, mass_omega);
    const Bounded q =
        j == 0 ? exact(splat(1)) : quotient(s.harmonic_omega[j - 1], Pair{omega, splat(0)});
    const Bounded theta = j == 0 ? exact(a) : q * exact(a) + exact(splat(s.harmonic_phase[j - 1]));
    if (!(absolute(first(theta.value.hi)) <= 0x1p24)) return;
    const Lanes k = lanes::nearest_integer(theta.value.hi * table.steps_per_radian);
    const Bounded offset = theta - table_angle(k, table);  // |offset| <= pi/256
    Term& term = term_[terms_++];
    term.base =
        static_cast<int>(static_cast<long long>(first(k)) & (DoubleDoubleTrigTable::kSize - 1));
    const Trig at_start = lanes::sin_cos(offset.value, _mm_set1_epi32(term.base), table);
    const Lanes trig_error_at_start = trig_error(offset.error, splat(1));
    const Bounded sine{at_start.sin, trig_error_at_start};
    const Bounded cosine{at_start.cos, trig_error_at_start};
    // H = (rho^2 - q^2 - 2 i sigma q) / D, D = (rho^2 - q^2)^2 + (2 sigma q)^2;
    // the term b Im(H e^{i theta}) = A sin theta + C cos theta (D > 0: q > 0
    // and a spring or a damper; without either, H = -1 / q^2).
    const Bounded detuning = rho2 - q * q;
    const Bounded friction_part = lanes::scaled(sigma * q, 2);
    const Bounded denominator = detuning * detuning + friction_part * friction_part;
    const Bounded coefficient_sin = b * detuning / denominator;          // A
    const Bounded coefficient_cos = -(b * friction_part / denominator);  // C
    y_p = y_p + (coefficient_sin * sine + coefficient_cos * cosine);
    v_p = v_p + q * (coefficient_sin * cosine - coefficient_cos * sine);
    const Bounded q2 = q * q;
    term.q = keep(q);
    term.offset = keep(offset);
    term.x_sin = keep(coefficient_sin * inverse_omega);
    term.x_cos = keep(coefficient_cos * inverse_omega);
    term.v_sin = keep(-(q * coefficient_cos));
    term.v_cos = keep(q * coefficient_sin);
    term.a_sin = keep(-(omega_b * q2 * coefficient_sin));
    term.a_cos = keep(-(omega_b * q2 * coefficient_cos));
  }

  // The free motion from the rest of the start: y_h(0) = C1, y_h'(0) = D1.
  const Bounded c1 = exact(lanes::two_prod(omega, splat(s.x_begin))) - y_p;
  const Bounded d1 = exact(splat(s.v_begin)) - v_p;
  sigma_ = nu_ = x_cos_ = x_sin_ = v_cos_ = v_sin_ = a_cos_ = a_sin_ = keep(zero);
  x_constant_ = x_linear_ = x_square_ = v_constant_ = v_linear_ = a_constant_ = keep(zero);
  decays_ = 0;
  // A decay e^{-kappa h} with coefficient M in y: (-kappa)^n M in the n-th
  // derivative.
  const auto add_decay_term = [&](const Bounded& kappa, const Bounded& m) {
    Decay& d = decay_[decays_++];
    d.rate = keep(kappa);
    d.x = keep(m * inverse_omega);
    d.v = keep(-(kappa * m));
    d.a = keep(omega_b * (kappa * kappa * m));
  };
  switch (free_) {
    case FreeMotion::oscillation: {
      // P + e^{-sigma h} (C1 cos nu h + C2 sin nu h) and its derivatives.
      const Bounded c2 = (d1 + sigma * c1) / nu;
      const Bounded d2 = -(nu * c1 + sigma * c2);
      const Bounded e1 = nu * d2 - sigma * d1;
      const Bounded e2 = -(nu * d1 + sigma * d2);
      sigma_ = keep(sigma);
      nu_ = keep(nu);
      x_constant_ = keep(steady * inverse_omega);
      x_cos_ = keep(c1 * inverse_omega);
      x_sin_ = keep(c2 * inverse_omega);
      v_cos_ = keep(d1);
      v_sin_ = keep(d2);
      a_cos_ = keep(omega_b * e1);
      a_sin_ = keep(omega_b * e2);
      break;
    }
    case FreeMotion::parabola:
      // C1 + D1 h + g0 h^2 / 2: x = y / w, v = dy/dh, a = w dv/dh.
      x_constant_ = keep(c1 * inverse_omega);
      x_linear_ = keep(d1 * inverse_omega);
      x_square_ = keep(lanes::scaled(g0 * inverse_omega, 0.5));
      v_constant_ = keep(d1);
      v_linear_ = keep(g0);
      a_constant_ = keep(omega_b * g0);
      break;
    case FreeMotion::decays:
      if (spring) {
        // Over-damped: P + A e^{-kappa1 h} + B e^{-kappa2 h}, kappa2 = sigma
        // + mu, kappa1 = rho^2 / kappa2 (sigma - mu without its
        // cancellation), A + B = C1, -kappa1 A - kappa2 B = D1.
        const Bounded kappa2 = sigma + mu;
        const Bounded kappa1 = rho2 / kappa2;
        const Bounded gap = lanes::scaled(mu, 2);  // kappa2 - kappa1
        x_constant_ = keep(steady * inverse_omega);
        add_decay_term(kappa1, (d1 + kappa2 * c1) / gap);
        add_decay_term(kappa2, -((d1 + kappa1 * c1) / gap));
      } else {
        // A damper alone: A + (g0 / 2 sigma) h + B e^{-2 sigma h}, B = -D1 /
        // (2 sigma) (D1 net of the drift), A = C1 - B.
        const Bounded kappa = lanes::scaled(sigma, 2);
        const Bounded b = -(d1 / kappa);
        x_constant_ = keep((c1 - b) * inverse_omega);
        x_linear_ = keep(drift * inverse_omega);
        v_constant_ = keep(drift);
        add_decay_term(kappa, b);
      }
      break;
  }
  omega_ = s.omega;
  a_hi_ = first(a.hi);
  a_lo_ = first(a.lo);
  for (int k = 0; k < decays_; ++k) {
    const Decay& d = decay_[k];
    const Constant* const own[] = {&d.rate, &d.x, &d.v, &d.a};
    for (const Constant* c : own)
      if (!finite(*c)) return;
  }
  const Constant* const shared[] = {&sigma_,      &nu_,       &x_constant_, &x_linear_, &x_square_,
                                    &v_constant_, &v_linear_, &a_constant_, &x_cos_,    &x_sin_,
                                    &v_cos_,      &v_sin_,    &a_cos_,      &a_sin_};
  for (const Constant* c : shared)
    if (!finite(*c)) return;
  for (int j = 0; j < terms_; ++j) {
    const Term& t = term_[j];
    const Constant* const own[] = {&t.q,     &t.offset, &t.x_sin, &t.x_cos,
                                   &t.v_sin, &t.v_cos,  &t.a_sin, &t.a_cos};
    for (const Constant* c : own)
      if (!finite(*c)) return;
  }

  // Bounds on the errors of x, v and a for h up to 2, 8, 64 and 513 rad (one
  // range per lane), from the closed form on envelopes of its operands: the
  // sines and cosines within 1 + 2^-50 with their errors for the largest
  // phase and table steps of the range, each e^{-kappa h} within 1 + 2^-40
  // (kappa, h >= 0) with its error.
  static_assert(kRanges == lanes::kRanges, "a range per lane");
  const Lanes h_max{kRange[0], kRange[1], kRange[2], kRange[3]};
  const Lanes tau_max = splat(absolute(a_hi_)) + h_max + 1;
  const Envelope h{
      {{h_max, splat(0)}, lanes::kAddError * (tau_max + absolute(a_hi_)) + lanes::kUnderflowSlack}};
  const auto trig_envelope = [&](const Envelope& phase) {
    const Lanes steps = phase.bound.value.hi * table.steps_per_radian + 1;
    return Envelope{{{splat(1 + 0x1p-50), splat(0)}, trig_error(phase.bound.error, steps)}};
  };
  const auto decay_envelope = [&](const Constant& rate) {
    const Envelope argument = envelope(rate) * h;
    return Envelope{
        {{splat(1 + 0x1p-40), splat(0)},
         (lanes::kExpError + argument.bound.error) * (1 + 0x1p-6) + lanes::kUnderflowSlack}};
  };
  Sums<Envelope> sums = polynomial(degree(free_, decays_), envelope(x_constant_),
                                   envelope(x_linear_), envelope(x_square_), envelope(v_constant_),
                                   envelope(v_linear_), envelope(a_constant_), h);
  for (int j = 0; j < terms_; ++j) {
    const Term& t = term_[j];
    const Envelope trig = trig_envelope(phase_of(envelope(t.offset), envelope(t.q), h));
    add_share(sums, envelope(t.x_sin), envelope(t.x_cos), envelope(t.v_sin), envelope(t.v_cos),
              envelope(t.a_sin), envelope(t.a_cos), trig, trig);
  }
  if (free_ == FreeMotion::oscillation) {
    const Envelope free_trig = trig_envelope(envelope(nu_) * h);
    add_free(sums, envelope(x_cos_), envelope(x_sin_), envelope(v_cos_), envelope(v_sin_),
             envelope(a_cos_), envelope(a_sin_), decay_envelope(sigma_), free_trig, free_trig);
  }
  for (int k = 0; k < decays_; ++k) {
    const Decay& d = decay_[k];
    add_decay(sums, envelope(d.x), envelope(d.v), envelope(d.a), decay_envelope(d.rate));
  }
  const State<Envelope> bound = sums.total();
  for (int k = 0; k < kRanges; ++k) {
    velocity_error_[k] = bound.v.bound.error[k];
    acceleration_error_[k] = bound.a.bound.error[k];
    position_error_[k] = bound.x.bound.error[k];
    if (!(finite(velocity_error_[k]) && finite(acceleration_error_[k]) &&
          finite(position_error_[k])))
      return;
  }
  usable_ = true;
}

void DoubleDoubleOscillator::evaluate(const double* t, std::size_t n, double* x, double* v,
                                      double* a, unsigned char* decided) const {
  const std::size_t wide = eight_lane_rows(n);
  if (wide > 0) evaluate_lanes<8>(t, wide, x, v, a, decided);
  if (wide < n) evaluate_lanes<4>(t + wide, n - wide, x + wide, v + wide, a + wide, decided + wide);
}

template void DoubleDoubleOscillator::evaluate_lanes<4>(const double*, std::size_t, double*,
                                                        double*, double*, unsigned char*) const;

}  // namespace frictionref::detail
