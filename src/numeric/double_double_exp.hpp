// The exponential on four lanes in double-double (numeric/double_double_lanes.hpp),
// with the bound on its error (docs/theory.md 10.6). For the translation units
// compiled with -mavx2 -mfma -ffp-contract=off only, entered only where
// double_double_lanes_available().
#pragma once

#include <immintrin.h>

#include "numeric/double_double_lanes.hpp"
#include "numeric/double_double_table.hpp"
#include "numeric/double_double_trig.hpp"

namespace frictionref::detail::lanes {

// Relative error of exp below, for an exact argument: the reduction's three
// double-double sums (2^-104 of 0.35 each), ln 2's parts beyond ln2_3 times
// |k| <= 1022 (2^-140), the series' four double-double steps (a product
// within 5u^2 and a sum within 3.01u^2 of about 1 each: 2^-101.5), its terms
// from w^4 / 4! (below 2^-52.5 for |w| <= 2^-12) on in double (2^-105) and
// beyond w^8 / 8! (2^-111), the table's and the coefficients' rounding
// (2^-106 each) and the last product (5u^2): together below 2^-99. The bound
// is 8 times that.
// Below e^-600 the low part loses bits to underflow: there the error is
// below 2^-1000 absolute instead (kUnderflowSlack).
inline constexpr double kExpError = 0x1p-96;
// The series' terms summed in double-double: w^n / n! for n < 4.
inline constexpr int kDoubleDoubleTerms = 4;

// e^z for -708 <= z.hi <= 0 (other lanes, NaN included, are clamped into
// that range: their answer is meaningless, but the table is never read
// outside; the caller masks them). z = k ln 2 + m / 2048 + w with |w| <=
// 1/4096: e^z = 2^k e^(m/2048) e^w, e^(m/2048) from the table and e^w from
// its series to w^8 / 8!.
__attribute__((always_inline)) inline Pair exp_of(const Pair& argument,
                                                  const DoubleDoubleExpTable& t) {
  const Lanes clamped = _mm256_max_pd(_mm256_min_pd(argument.hi, splat(0)), splat(-708));
  const Pair z{clamped, clamped == argument.hi ? argument.lo : splat(0)};
  const Lanes k = nearest_integer(z.hi * t.inverse_ln2);
  // z - k ln 2 as a pair: k ln2_1 is exact (42 bits times |k| < 2^11) and so
  // is its 2Sum with z.hi; the rest in double-double sums.
  const Pair r = two_sum(z.hi, -k * t.ln2_1);
  const Pair k2 = two_prod(k, splat(t.ln2_2));
  const Pair d =
      add(add(add(r, Pair{z.lo, splat(0)}), Pair{-k2.hi, -k2.lo}), Pair{-k * t.ln2_3, splat(0)});
  // d.hi - m / 2048 is exact (a multiple of ulp(d.hi), below |d.hi|).
  constexpr double kStep = 1.0 / DoubleDoubleExpTable::kSteps;
  const Lanes m = nearest_integer(d.hi * DoubleDoubleExpTable::kSteps);
  const Pair w = fast_two_sum(d.hi - m * kStep, d.lo);
  // The terms from w^4 / 4! on are below 2^-52.5: summed in double (their
  // rounding below 2^-105 in all), as tail = sum_{n >= 4} w^(n-4) / n!; the
  // first four in double-double, Horner's steps on a short chain.
  Lanes tail = splat(t.factorial_hi[DoubleDoubleExpTable::kTerms]);
  for (int n = DoubleDoubleExpTable::kTerms - 1; n >= kDoubleDoubleTerms; --n)
    tail = fused(tail, w.hi, splat(t.factorial_hi[n]));
  const auto coefficient = [&t](int n) {
    return Pair{splat(t.factorial_hi[n]), splat(t.factorial_lo[n])};
  };
  Pair series = add(coefficient(kDoubleDoubleTerms - 1), Pair{w.hi * tail, splat(0)});
  for (int n = kDoubleDoubleTerms - 2; n >= 0; --n)
    series = add(multiply(series, w), coefficient(n));
  const __m128i index =
      _mm_add_epi32(_mm256_cvtpd_epi32(m), _mm_set1_epi32(DoubleDoubleExpTable::kHalf));
  const Pair table{gather(t.exp_hi, index), gather(t.exp_lo, index)};
  const Pair product = multiply(table, series);
  // 2^k, k >= -1022: a normal double built from its exponent bits.
  const __m256i bits = _mm256_slli_epi64(
      _mm256_cvtepi32_epi64(_mm_add_epi32(_mm256_cvtpd_epi32(k), _mm_set1_epi32(1023))), 52);
  const Lanes scale = _mm256_castsi256_pd(bits);
  return {product.hi * scale, product.lo * scale};
}

}  // namespace frictionref::detail::lanes
