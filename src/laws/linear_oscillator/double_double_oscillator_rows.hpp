// The general model's fast path's closed form on the lanes
// (double_double_oscillator.hpp), one text for the lanes' values and for the
// constructor's bounds, and its row loop, for the translation units of each
// lane width: double_double_oscillator.cpp (four lanes, AVX2) and
// double_double_oscillator_wide.cpp (eight, AVX-512), which instantiate
// evaluate_lanes for their own width. Only for those translation units
// (their flags: src/CMakeLists.txt).
#pragma once

#include <cstddef>

#include "laws/linear_oscillator/double_double_oscillator.hpp"
#include "numeric/double_double_exp.hpp"
#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_rows.hpp"
#include "numeric/double_double_sum.hpp"
#include "numeric/double_double_table.hpp"
#include "numeric/double_double_trig.hpp"

// The closed form in the lanes' own namespace (one per width).
namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {
namespace oscillator_form {

constexpr double kLargestAngle = 512;  // of q_j h + offset and of nu h
constexpr double kLargestDecay = 708;  // of sigma h, kappa h: e^-708 is still normal

// The closed form (double_double_oscillator.hpp), one text for the lanes'
// values (Pair) and for the bounds on their errors (Envelope): x, v and a
// each a sum of products (double_double_sum.hpp).
template <class V>
struct State {
  V x, v, a;
};
template <class V>
struct Sums {
  Sum<V> x, v, a;
  State<V> total() const { return {x.total(), v.total(), a.total()}; }
};
template <class V>
V phase_of(const V& offset, const V& q, const V& h) {
  return offset + q * h;
}
// A term's share: its coefficients on sin and cos in x, v and a.
template <class V>
void add_share(Sums<V>& s, const V& x_sin, const V& x_cos, const V& v_sin, const V& v_cos,
               const V& a_sin, const V& a_cos, const V& sine, const V& cosine) {
  s.x.add(x_sin, sine);
  s.x.add(x_cos, cosine);
  s.v.add(v_sin, sine);
  s.v.add(v_cos, cosine);
  s.a.add(a_sin, sine);
  s.a.add(a_cos, cosine);
}
// The free oscillation's share: its coefficients on e^{-sigma h} cos nu h
// and e^{-sigma h} sin nu h, a term's share on those products.
template <class V>
void add_free(Sums<V>& s, const V& x_cos, const V& x_sin, const V& v_cos, const V& v_sin,
              const V& a_cos, const V& a_sin, const V& decay, const V& cosine, const V& sine) {
  add_share(s, x_sin, x_cos, v_sin, v_cos, a_sin, a_cos, decay * sine, decay * cosine);
}

// A decay's share: its coefficients on e^{-kappa h} in x, v and a.
template <class V>
void add_decay(Sums<V>& s, const V& x, const V& v, const V& a, const V& decay) {
  s.x.add(x, decay);
  s.v.add(v, decay);
  s.a.add(a, decay);
}
// The sums' start, the free motion's polynomial part: x = x0 + x1 h + x2 h^2,
// v = v0 + v1 h, a = a0 (a slip without spring or damper: a parabola), or
// its first terms (a damper alone: x0 + x1 h and v0; a spring: x0 alone).
template <class V>
Sums<V> polynomial(int degree, const V& x0, const V& x1, const V& x2, const V& v0, const V& v1,
                   const V& a0, const V& h) {
  Sums<V> s{Sum<V>(x0), Sum<V>(v0), Sum<V>(a0)};
  if (degree >= 1) s.x.add(x1, h);
  if (degree >= 2) {
    s.x.add(x2, h * h);
    s.v.add(v1, h);
  }
  return s;
}

}  // namespace oscillator_form
}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes

namespace frictionref::detail {

template <int kWidth>
void DoubleDoubleOscillator::evaluate_lanes(const double* t, std::size_t n, double* x, double* v,
                                            double* a, unsigned char* decided) const {
  switch (free_) {
    case FreeMotion::oscillation:
      return evaluate_rows<FreeMotion::oscillation, kWidth>(t, n, x, v, a, decided);
    case FreeMotion::parabola:
      return evaluate_rows<FreeMotion::parabola, kWidth>(t, n, x, v, a, decided);
    case FreeMotion::decays:
      return evaluate_rows<FreeMotion::decays, kWidth>(t, n, x, v, a, decided);
  }
}

template <DoubleDoubleOscillator::FreeMotion kFree, int kWidth>
void DoubleDoubleOscillator::evaluate_rows(const double* t, std::size_t n, double* x, double* v,
                                           double* a, unsigned char* decided) const {
  static_assert(kWidth == lanes::kLanes, "instantiated where the lanes have this width");
  using namespace lanes;                   // NOLINT: the lanes' arithmetic throughout
  using namespace lanes::oscillator_form;  // NOLINT
  const DoubleDoubleTrigTable& table = double_double_trig_table();
  const DoubleDoubleExpTable& exp_table = double_double_exp_table();
  const Lanes omega = splat(omega_);
  const Pair start{splat(a_hi_), splat(a_lo_)};
  // Loaded once: the stores below may alias the members, as far as the
  // compiler knows.
  const Pair sigma = lanes_of(sigma_), nu = lanes_of(nu_);
  const Pair x_constant = lanes_of(x_constant_), x_linear = lanes_of(x_linear_),
             x_square = lanes_of(x_square_), v_constant = lanes_of(v_constant_),
             v_linear = lanes_of(v_linear_), a_constant = lanes_of(a_constant_);
  for (std::size_t i = 0; i < n; i += kWidth) {
    const std::size_t used = lanes::group_size(i, n);
    const Lanes time = lanes::group_times(t, i, used);
    const Pair tau = lanes::two_prod(omega, time);  // w t exactly
    const Pair h = tau - start;
    Mask ok = (h.hi >= splat(0)) & (h.hi <= splat(kRange[kRanges - 1] * (1 - 0x1p-50)));
    Sums<Pair> sums = polynomial(degree(kFree, decays_), x_constant, x_linear, x_square, v_constant,
                                 v_linear, a_constant, h);
    for (int j = 0; j < terms_; ++j) {
      const Term& term = term_[j];
      const Pair phase = phase_of(lanes_of(term.offset), lanes_of(term.q), h);
      ok &= magnitude(phase.hi) <= splat(kLargestAngle);
      const Trig trig = lanes::sin_cos(phase, splat_index(term.base), table);
      add_share(sums, lanes_of(term.x_sin), lanes_of(term.x_cos), lanes_of(term.v_sin),
                lanes_of(term.v_cos), lanes_of(term.a_sin), lanes_of(term.a_cos), trig.sin,
                trig.cos);
    }
    if constexpr (kFree == FreeMotion::oscillation) {
      const Pair decay_argument = sigma * h;
      ok &= decay_argument.hi <= splat(kLargestDecay);
      const Pair decay = lanes::exp_of(-decay_argument, exp_table);
      const Pair free_phase = nu * h;
      ok &= magnitude(free_phase.hi) <= splat(kLargestAngle);
      const Trig free = lanes::sin_cos(free_phase, splat_index(0), table);
      add_free(sums, lanes_of(x_cos_), lanes_of(x_sin_), lanes_of(v_cos_), lanes_of(v_sin_),
               lanes_of(a_cos_), lanes_of(a_sin_), decay, free.cos, free.sin);
    }
    if constexpr (kFree == FreeMotion::decays) {
      for (int k = 0; k < decays_; ++k) {
        const Decay& d = decay_[k];
        const Pair argument = lanes_of(d.rate) * h;
        ok &= argument.hi <= splat(kLargestDecay);
        add_decay(sums, lanes_of(d.x), lanes_of(d.v), lanes_of(d.a),
                  lanes::exp_of(-argument, exp_table));
      }
    }
    const State<Pair> state = sums.total();
    const lanes::RangePick pick(h.hi);
    const lanes::Decisions decisions{ok & lanes::decided(state.x, pick(position_error_)),
                                     ok & lanes::decided(state.v, pick(velocity_error_)),
                                     ok & lanes::decided(state.a, pick(acceleration_error_))};
    lanes::store_group(i, used, state.x, state.v, state.a, decisions, x, v, a, decided);
  }
}

}  // namespace frictionref::detail
