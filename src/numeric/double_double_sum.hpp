// A sum of double-double products s_0 + c_1 f_1 + ... + c_n f_n on four
// lanes, normalized once at its end, and the bound on its error (docs/theory.md
// 10.2): the dense rows' x, v and a. Cheaper than a double-double product
// and sum per term (13 operations against about 23): the leading parts'
// products are exact (2Prod) and so is their running sum (2Sum); every
// lower-order term goes to one plain double, rounded as it comes.
//
// The bound, with u = 2^-53, operands normalized (|lo| <= u |hi|) and M_k =
// |s_0.hi| + sum_{j <= k} |c_j.hi| |f_j.hi|: the k-th term's rounding is
// below u^2 M_k (12.1 + 4.1 k):
//   - its product: c.lo f.lo dropped (u^2), c.lo f.hi rounded (u^2), the
//     fused c.hi f.lo + that rounded (2.01 u^2): 4.01 u^2 |c.hi f.hi|;
//   - P.lo + low rounded (3.01 u^2 |c.hi f.hi|), S.lo + that (u^2 |S.hi| +
//     3.02 u^2 |c.hi f.hi|), where |S.hi| <= M_k (1 + u)^k;
//   - the low part's own sum rounded: u |lo_k|, |lo_k| <= u M_k (1 + 4.01 k)
//     (1 + u)^k (the first low part and k terms of at most u |S.hi| +
//     3.01 u |c f| each).
// The bound used, u^2 M_k (16 + 8 k), exceeds that for k < 2^40 with the
// (1 + u)^k factors. The operands' own errors are carried as in a product
// (double_double_lanes.hpp).
//
// Only for translation units compiled with -mavx2 -mfma -ffp-contract=off, as
// double_double_lanes.hpp.
#pragma once

#include "numeric/double_double_lanes.hpp"

namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {

inline constexpr double kSumErrorPerMass = 0x1p-106;  // u^2, times (16 + 8 k) M_k

template <class V>
class Sum;

// The lanes' values.
template <>
class Sum<Pair> {
 public:
  explicit Sum(const Pair& start) : hi_(start.hi), lo_(start.lo) {}

  // += c f, for c and f normalized.
  void add(const Pair& c, const Pair& f) {
    const Pair product = two_prod(c.hi, f.hi);
    const Lanes low = fused(c.hi, f.lo, c.lo * f.hi);
    const Pair s = two_sum(hi_, product.hi);
    hi_ = s.hi;
    lo_ = lo_ + (s.lo + (product.lo + low));
  }

  // The sum, normalized.
  Pair total() const { return two_sum(hi_, lo_); }

 private:
  Lanes hi_, lo_;
};

// A bound on every signed instance of the same sum (an Envelope's
// magnitudes and errors): the mass M_k and the error.
template <>
class Sum<Envelope> {
 public:
  explicit Sum(const Envelope& start) : mass_(start.bound.value.hi), error_(start.bound.error) {}

  void add(const Envelope& c, const Envelope& f) {
    const Lanes size_c = c.bound.value.hi, size_f = f.bound.value.hi;
    const Lanes propagated =
        size_c * f.bound.error + size_f * c.bound.error + c.bound.error * f.bound.error;
    mass_ = mass_ + size_c * size_f;
    ++terms_;
    error_ =
        error_ + propagated + (kSumErrorPerMass * (16 + 8 * terms_) * mass_ + 8 * kUnderflowSlack);
  }

  // |total| <= M_n (1 + u)^n, and its error.
  Envelope total() const { return Envelope{{{mass_ * (1 + 0x1p-40), splat(0)}, error_}}; }

 private:
  Lanes mass_, error_;
  int terms_ = 0;
};

}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes
