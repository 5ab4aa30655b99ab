// The exponential on four (or eight) lanes in double-double (numeric/double_double_lanes.hpp),
// with the bound on its error (docs/theory.md 10.6). For the translation units
// compiled with -mavx2 -mfma -ffp-contract=off only, entered only where
// double_double_lanes_available().
#pragma once

#include <immintrin.h>

#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_table.hpp"

namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {

// Relative error of exp below (docs/theory.md 10.6), u = 2^-53, for an exact
// argument z normalized (|z.lo| <= u |z.hi|), -708 <= z.hi <= 0:
//   - the reduction d = z - k ln 2 (|k| <= 1022): k ln2_2 + k ln2_3 rounded
//     once (|k ln2_2| < 2^-33: 2^-86), the sum with r.lo + z.lo (below
//     2^-32.9: 2^-86) and r.lo + z.lo (2^-96): 2^-84.9 absolute in d, so
//     relative in e^z;
//   - w = d - m / 2048 = y + e (|y| <= 2^-11.99, |e| <= u |y|): e^w = 1 + y
//     + y^2 / 2 + y^3 / 6 + ... + y^6 / 720 + e + y e, dropping y^7 / 7!
//     (2^-96.3) and y^2 e / 2 (2^-89); 1 + y + y^2 / 2 exact (Fast2Sum,
//     2Prod), the terms from y^3 on in double (2^-88.5 of their 2^-38.5),
//     the low parts' three sums rounded at 2^-38.3 (3 * 2^-91.3): 2^-87.3;
//   - the table's rounding (2^-106) and the product with it (5 u^2).
// Together below 2^-84.4; the bound is 16 times that. Below e^-600 the low
// part loses bits to underflow: there the error is below 2^-1000 absolute
// instead (kUnderflowSlack).
inline constexpr double kExpError = 0x1p-80;

// The table entries at index (one per lane, in the table), as a pair of
// lanes: as trig_entries, lanes 0 and 2 in one register, 1 and 3 in the
// other, so that the in-lane unpacks give the lanes in order.
inline Pair exp_entries(const DoubleDoubleExpTable::Entry* table, Index index) {
  using Half = double __attribute__((vector_size(32)));  // two entries, or a value of four lanes
  const auto two = [table](int i, int j) -> Half {
    return _mm256_set_m128d(_mm_load_pd(&table[j].hi), _mm_load_pd(&table[i].hi));
  };
#if FRICTIONREF_LANES == 4
  const Half even = two(_mm_cvtsi128_si32(index), _mm_extract_epi32(index, 2));
  const Half odd = two(_mm_extract_epi32(index, 1), _mm_extract_epi32(index, 3));
  return {_mm256_unpacklo_pd(even, odd), _mm256_unpackhi_pd(even, odd)};
#else
  const Half even_low = two(_mm256_extract_epi32(index, 0), _mm256_extract_epi32(index, 2));
  const Half odd_low = two(_mm256_extract_epi32(index, 1), _mm256_extract_epi32(index, 3));
  const Half even_high = two(_mm256_extract_epi32(index, 4), _mm256_extract_epi32(index, 6));
  const Half odd_high = two(_mm256_extract_epi32(index, 5), _mm256_extract_epi32(index, 7));
  return {joined(_mm256_unpacklo_pd(even_low, odd_low), _mm256_unpacklo_pd(even_high, odd_high)),
          joined(_mm256_unpackhi_pd(even_low, odd_low), _mm256_unpackhi_pd(even_high, odd_high))};
#endif
}

// e^z for -708 <= z.hi <= 0 (other lanes, NaN included, are clamped into
// that range: their answer is meaningless, but the table is never read
// outside; the caller masks them). z = k ln 2 + m / 2048 + w with |w| <=
// 2^-11.99: e^z = 2^k e^(m/2048) e^w, e^(m/2048) from the table and e^w
// from its series to w^6 / 6!, the terms from w^3 on in double: a short
// chain, accurate to the sine's and cosine's 2^-76 and beyond.
__attribute__((always_inline)) inline Pair exp_of(const Pair& argument,
                                                  const DoubleDoubleExpTable& t) {
  const Lanes clamped = larger(smaller(argument.hi, splat(0)), splat(-708));
  const Pair z{clamped, clamped == argument.hi ? argument.lo : splat(0)};
  const Lanes k = nearest_integer(z.hi * t.inverse_ln2);
  // z - k ln 2 = r + low: k ln2_1 is exact (42 bits times |k| < 2^11), and
  // so is its 2Sum with z.hi; the rest rounded in double.
  const Pair r = two_sum(z.hi, -k * t.ln2_1);
  const Lanes low = (r.lo + z.lo) - fused(k, splat(t.ln2_2), k * t.ln2_3);
  // r.hi - m / 2048 is exact (a multiple of ulp(r.hi), at most |r.hi|).
  constexpr double kStep = 1.0 / DoubleDoubleExpTable::kSteps;
  const Lanes m = nearest_integer(r.hi * DoubleDoubleExpTable::kSteps);
  const Pair w = two_sum(r.hi - m * kStep, low);
  const Lanes y = w.hi;
  const Pair square = two_prod(y, y);
  const Lanes cube_on =
      y * square.hi *
      (1.0 / 6 + y * (1.0 / 24 + y * (1.0 / 120 + y * (1.0 / 720))));  // y^3 / 3! + ... + y^6 / 6!
  const Pair one_y = fast_two_sum(splat(1), y);
  const Pair leading = fast_two_sum(one_y.hi, 0.5 * square.hi);  // 1 + y + y^2 / 2, with lows
  const Lanes rest = (leading.lo + one_y.lo) + (w.lo + (fused(y, w.lo, 0.5 * square.lo) + cube_on));
  const Pair series = fast_two_sum(leading.hi, rest);
  const Index index = add(index_of(m), splat_index(DoubleDoubleExpTable::kHalf));
  const Pair table = exp_entries(t.entry, index);
  const Pair product = multiply(table, series);
  // 2^k, k >= -1022: a normal double built from its exponent bits.
  const Lanes scale = power_of_two(k);
  return {product.hi * scale, product.lo * scale};
}

}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes
