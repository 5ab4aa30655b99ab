// Sine and cosine on four (or eight) lanes in double-double (numeric/double_double_lanes.hpp),
// with the bound on their error: the table reduction of docs/theory.md 10.3.
// For the translation units compiled with -mavx2 -mfma -ffp-contract=off only
// (the fast paths of the dense output), entered only where
// double_double_lanes_available().
#pragma once

#include <immintrin.h>

#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_table.hpp"

namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {

// The error of sin_cos beyond its argument's, for |d| <= 0.01228 (docs/theory.md
// 10.3): the d^4 terms of cos d - 1 (below 9.5e-10) with eleven roundings
// of u, 1.2e-24; the sum formulas' terms rounded in double, 2.2e-25; the
// dropped products S.lo (cos d - 1 + d^2/2) and C.lo (sin d - d.hi +
// d.hi^3/6), 5.4e-26; sin d beyond d.hi - d.hi^3/6 (series, roundings),
// 3.8e-27; the table, 1.2e-32. Together 1.5e-24 < 2^-79; the bound is 9
// times that. The reduction adds |j| 2^-94 (two roundings of terms up to
// |j| 2^-44: |j| 2^-96).
inline constexpr double kTrigError = 0x1p-76;
inline constexpr double kReductionErrorPerStep = 0x1p-94;
struct Trig {
  Pair sin, cos;
};

// The bound on sin_cos's error for an argument within `argument_error` of
// y and a reduction by |j| <= j_max steps.
inline Lanes trig_error(Lanes argument_error, Lanes j_max) {
  return argument_error + (kTrigError + j_max * kReductionErrorPerStep);
}

// The table entries at index (one per lane, each 0 <= index < the table's
// size), as lanes: a load and a transpose per four lanes, about 2.5 times
// faster than a gather per value on this machine (docs/benchmarks.md).
struct TrigEntries {
  Lanes sin_hi, sin_lo, cos_hi, cos_lo;
};
using Quarter = double __attribute__((vector_size(32)));  // one entry, or a value of four lanes
// The entries i0..i3 transposed: sin_hi, sin_lo, cos_hi and cos_lo of the four.
inline void transposed(const DoubleDoubleTrigTable::Entry* table, int i0, int i1, int i2, int i3,
                       Quarter out[4]) {
  const Quarter r0 = _mm256_load_pd(&table[i0].sin_hi);
  const Quarter r1 = _mm256_load_pd(&table[i1].sin_hi);
  const Quarter r2 = _mm256_load_pd(&table[i2].sin_hi);
  const Quarter r3 = _mm256_load_pd(&table[i3].sin_hi);
  const Quarter highs01 = _mm256_unpacklo_pd(r0, r1);  // sin_hi 0 1, cos_hi 0 1
  const Quarter lows01 = _mm256_unpackhi_pd(r0, r1);   // sin_lo 0 1, cos_lo 0 1
  const Quarter highs23 = _mm256_unpacklo_pd(r2, r3);
  const Quarter lows23 = _mm256_unpackhi_pd(r2, r3);
  out[0] = _mm256_permute2f128_pd(highs01, highs23, 0x20);
  out[1] = _mm256_permute2f128_pd(lows01, lows23, 0x20);
  out[2] = _mm256_permute2f128_pd(highs01, highs23, 0x31);
  out[3] = _mm256_permute2f128_pd(lows01, lows23, 0x31);
}
inline TrigEntries trig_entries(const DoubleDoubleTrigTable::Entry* table, Index index) {
#if FRICTIONREF_LANES == 4
  Quarter e[4];
  transposed(table, _mm_cvtsi128_si32(index), _mm_extract_epi32(index, 1),
             _mm_extract_epi32(index, 2), _mm_extract_epi32(index, 3), e);
  return {e[0], e[1], e[2], e[3]};
#else
  Quarter low[4], high[4];
  transposed(table, _mm256_extract_epi32(index, 0), _mm256_extract_epi32(index, 1),
             _mm256_extract_epi32(index, 2), _mm256_extract_epi32(index, 3), low);
  transposed(table, _mm256_extract_epi32(index, 4), _mm256_extract_epi32(index, 5),
             _mm256_extract_epi32(index, 6), _mm256_extract_epi32(index, 7), high);
  return {joined(low[0], high[0]), joined(low[1], high[1]), joined(low[2], high[2]),
          joined(low[3], high[3])};
#endif
}

// sin and cos of base pi/128 + y, for |y.hi| <= 2^9 and base in 0..255
// (error: trig_error with |j| the table steps taken, below 2^15).
// Inlined into the row loop, as it was measured (docs/benchmarks.md).
__attribute__((always_inline)) inline Trig sin_cos(const Pair& y, Index base,
                                                   const DoubleDoubleTrigTable& t) {
  const Lanes j = nearest_integer(y.hi * t.steps_per_radian);
  // d = y - j pi/128: j reduce1 and its difference with y.hi are exact; the
  // rest are terms below |j| 2^-44.
  const Pair r = two_sum(y.hi, -j * t.reduce1);
  const Pair jr2 = two_prod(j, splat(t.reduce2));
  const Lanes low = ((r.lo + y.lo) - jr2.hi) - (jr2.lo + j * t.reduce3);
  const Pair d = two_sum(r.hi, low);
  // sin d = d.hi + c3 + sin_small with c3 = -d.hi^3 / 6 as a pair (exact
  // products, 1/6 as a pair) and sin_small = d.lo, d.lo's first-order share
  // and the terms from d^5 on (below 2.4e-12). cos d = 1 + q_hi + q_lo with
  // q_hi = -d.hi^2 / 2 exactly. Series truncated below 3e-29.
  const Pair square = two_prod(d.hi, d.hi);
  const Lanes d2 = square.hi;
  const Pair cube = two_prod(d.hi, square.hi);
  const Lanes cube_lo = cube.lo + d.hi * square.lo;
  const Pair c3_top = two_prod(cube.hi, splat(-t.sixth_hi));
  const Lanes c3_hi = c3_top.hi;
  const Lanes c3_lo = c3_top.lo - (cube.hi * t.sixth_lo + cube_lo * t.sixth_hi);
  const Lanes sin_small =
      ((c3_lo - d.lo * d2 * 0.5) +
       d.hi * (d2 * d2) * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))) +
      d.lo;
  const Lanes q_hi = -0.5 * square.hi;
  const Lanes q_lo =
      (-0.5 * square.lo - d.hi * d.lo) +
      d2 * d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 + d2 * (-1.0 / 3628800))));
  const Index index =
      bits_and(add(index_of(j), base), splat_index(DoubleDoubleTrigTable::kSize - 1));
  const TrigEntries entries = trig_entries(t.entry, index);
  const Lanes &s_hi = entries.sin_hi, &s_lo = entries.sin_lo;
  const Lanes &c_hi = entries.cos_hi, &c_lo = entries.cos_lo;
  // sin = S + S q + C sin d and cos = C + C q - S sin d. The products of the
  // leading parts are exact and so is their sum with S or C; every other
  // term is below 1e-9 (rounded in double), the smallest added first.
  const Pair p1 = two_prod(s_hi, q_hi);
  const Pair p2 = two_prod(c_hi, d.hi);
  const Pair p5 = two_prod(c_hi, c3_hi);
  const Pair a1 = two_sum(p1.hi, p5.hi);
  const Pair a2 = two_sum(p2.hi, a1.hi);
  const Pair a3 = two_sum(s_hi, a2.hi);
  const Lanes sin_rest = ((((s_lo + p1.lo + p2.lo + p5.lo) + (a1.lo + a2.lo + a3.lo)) +
                           (s_lo * q_hi + c_lo * d.hi + c_lo * c3_hi)) +
                          c_hi * sin_small) +
                         s_hi * q_lo;
  const Pair p3 = two_prod(c_hi, q_hi);
  const Pair p4 = two_prod(-s_hi, d.hi);
  const Pair p6 = two_prod(-s_hi, c3_hi);
  const Pair b1 = two_sum(p3.hi, p6.hi);
  const Pair b2 = two_sum(p4.hi, b1.hi);
  const Pair b3 = two_sum(c_hi, b2.hi);
  const Lanes cos_rest = ((((c_lo + p3.lo + p4.lo + p6.lo) + (b1.lo + b2.lo + b3.lo)) +
                           (c_lo * q_hi - s_lo * d.hi - s_lo * c3_hi)) -
                          s_hi * sin_small) +
                         c_hi * q_lo;
  return {two_sum(a3.hi, sin_rest), two_sum(b3.hi, cos_rest)};
}

// k pi/128 as a bounded pair, |k| < 2^30: the table angle nearest a phase
// at a slip's start (base1 k is exact, base2 k exact as a pair).
inline Bounded table_angle(Lanes k, const DoubleDoubleTrigTable& t) {
  const Lanes k3 = k * t.base3;
  return exact(k * t.base1) + exact(two_prod(k, splat(t.base2))) +
         Bounded{{k3, splat(0)}, magnitude(k3) * 0x1p-52 + magnitude(k) * 0x1p-130};
}

}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes
