// Double-double arithmetic on four (or eight) lanes at once, with a running error bound
// per value: the arithmetic of the fast paths (docs/theory.md 10).
//
// A value is hi + lo (|lo| <= ulp(hi) / 2) in each lane of a vector register,
// and a Bounded value also carries e >= |hi + lo - exact|. The algorithms and
// their relative error bounds (u = 2^-53) are those proved by Joldes, Muller
// and Popescu, "Tight and rigorous error bounds for basic building blocks of
// double-word arithmetic", ACM TOMS 44(2), 2017: DWTimesDW3 (5u^2 in the
// paper's statement, 4u^2 with its later proof), 2Sum, Fast2Sum and 2Prod
// (exact). The sum is their SloppyDWPlusDW ending in 2Sum instead of
// Fast2Sum: its two roundings, of x.lo + y.lo and of s.lo + that, are below
// u^2 (|x.hi| + |y.hi|) and 2u^2 (1 + 2u) (|x.hi| + |y.hi|), an absolute bound
// that holds through cancellation (its relative error does not, so the bound
// is taken from the operands). The bounds used here exceed those, and every
// error term is taken from |hi| (|hi + lo| <= |hi| (1 + u)); a final
// factor 1 + 2^-40 in `decided` covers that and the rounding of the error
// arithmetic itself (fewer than 2^10 operations per value). An absolute
// 2^-1000 per operation covers any loss to underflow.
//
// Only for translation units compiled with -mavx2 -mfma -ffp-contract=off
// (src/CMakeLists.txt), which run only on a CPU that has both (the callers
// check `double_double_lanes_available()` first). A translation unit
// compiled with -mavx512f and FRICTIONREF_LANES=8 gets eight lanes instead
// (the dense rows' wide copies, run only where
// double_double_wide_lanes_available()): the same operations on each lane,
// so the same answers, in an inline namespace of its own.
#pragma once

#include <immintrin.h>

#include "numeric/double_double_constant.hpp"

#ifndef FRICTIONREF_LANES
#define FRICTIONREF_LANES 4
#endif
#if FRICTIONREF_LANES == 4
#define FRICTIONREF_LANES_NAMESPACE avx2
#elif FRICTIONREF_LANES == 8
#define FRICTIONREF_LANES_NAMESPACE avx512
#else
#error "FRICTIONREF_LANES is 4 (AVX2) or 8 (AVX-512)"
#endif

namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {

inline constexpr int kLanes = FRICTIONREF_LANES;
using Lanes = double __attribute__((vector_size(8 * kLanes)));    // kLanes doubles
using Mask = long long __attribute__((vector_size(8 * kLanes)));  // -1 where true, 0 where false

#if FRICTIONREF_LANES == 4
using Index = __m128i;  // a 32-bit integer per lane
inline Lanes splat(double x) { return Lanes{x, x, x, x}; }
inline Lanes magnitude(Lanes a) { return _mm256_andnot_pd(splat(-0.0), a); }
inline Lanes fused(Lanes a, Lanes b, Lanes c) { return _mm256_fmadd_pd(a, b, c); }  // a b + c
inline Lanes nearest_integer(Lanes a) {
  return _mm256_round_pd(a, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}
inline Lanes square_root_of(Lanes a) { return _mm256_sqrt_pd(a); }
inline Lanes smaller(Lanes a, Lanes b) { return _mm256_min_pd(a, b); }  // b where either is NaN
inline Lanes larger(Lanes a, Lanes b) { return _mm256_max_pd(a, b); }
inline Index splat_index(int i) { return _mm_set1_epi32(i); }
inline Index add(Index a, Index b) { return _mm_add_epi32(a, b); }
inline Index bits_and(Index a, Index b) { return _mm_and_si128(a, b); }
inline Index index_of(Lanes integral) { return _mm256_cvtpd_epi32(integral); }
// 2^k per lane for integral k in [-1022, 1023], from its exponent bits.
inline Lanes power_of_two(Lanes k) {
  return _mm256_castsi256_pd(
      _mm256_slli_epi64(_mm256_cvtepi32_epi64(add(index_of(k), splat_index(1023))), 52));
}
#else
// (The zero-masking forms with every lane selected: GCC 12's plain forms
// start from _mm512_undefined_*, which -Wmaybe-uninitialized flags.)
using Index = __m256i;
inline constexpr __mmask8 kAllLanes = 0xff;
inline Lanes splat(double x) { return Lanes{x, x, x, x, x, x, x, x}; }
inline Lanes magnitude(Lanes a) { return _mm512_abs_pd(a); }
inline Lanes fused(Lanes a, Lanes b, Lanes c) { return _mm512_fmadd_pd(a, b, c); }
inline Lanes nearest_integer(Lanes a) {
  return _mm512_maskz_roundscale_pd(kAllLanes, a, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}
inline Lanes square_root_of(Lanes a) { return _mm512_sqrt_pd(a); }
inline Lanes smaller(Lanes a, Lanes b) { return _mm512_maskz_min_pd(kAllLanes, a, b); }
inline Lanes larger(Lanes a, Lanes b) { return _mm512_maskz_max_pd(kAllLanes, a, b); }
inline Index splat_index(int i) { return _mm256_set1_epi32(i); }
inline Index add(Index a, Index b) { return _mm256_add_epi32(a, b); }
inline Index bits_and(Index a, Index b) { return _mm256_and_si256(a, b); }
inline Index index_of(Lanes integral) { return _mm512_maskz_cvtpd_epi32(kAllLanes, integral); }
inline Lanes power_of_two(Lanes k) {
  const __m512i exponent =
      _mm512_maskz_cvtepi32_epi64(kAllLanes, add(index_of(k), splat_index(1023)));
  return _mm512_castsi512_pd(_mm512_maskz_slli_epi64(kAllLanes, exponent, 52));
}
// a in lanes 0-3, b in lanes 4-7.
inline Lanes joined(__m256d a, __m256d b) {
  return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
}
#endif

struct Pair {
  Lanes hi, lo;
};

// a + b exactly (Knuth's 2Sum).
inline Pair two_sum(Lanes a, Lanes b) {
  const Lanes s = a + b;
  const Lanes bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// a + b exactly where |a| >= |b| or a = 0 (Dekker's Fast2Sum).
inline Pair fast_two_sum(Lanes a, Lanes b) {
  const Lanes s = a + b;
  return {s, b - (s - a)};
}

// a b exactly (2Prod with a fused multiply-add).
inline Pair two_prod(Lanes a, Lanes b) {
  const Lanes p = a * b;
  return {p, fused(a, b, -p)};
}

// x + y with |error| <= 3.01u^2 (|x.hi| + |y.hi|) (above), normalized.
inline Pair add(Pair x, Pair y) {
  const Pair s = two_sum(x.hi, y.hi);
  return two_sum(s.hi, s.lo + (x.lo + y.lo));
}

// DWTimesDW3: relative error <= 5u^2.
inline Pair multiply(Pair x, Pair y) {
  const Pair c = two_prod(x.hi, y.hi);
  const Lanes low = fused(x.lo, y.hi, fused(x.hi, y.lo, x.lo * y.lo));
  return fast_two_sum(c.hi, c.lo + low);
}

inline Pair operator+(Pair x, Pair y) { return add(x, y); }
inline Pair operator-(Pair x) { return {-x.hi, -x.lo}; }
inline Pair operator-(Pair x, Pair y) { return add(x, -y); }
inline Pair operator*(Pair x, Pair y) { return multiply(x, y); }

inline constexpr double kAddError = 0x1p-104;       // >= 3.01u^2 (1 + u), of |x.hi| + |y.hi|
inline constexpr double kMultiplyError = 0x1p-103;  // >= 5u^2 (1 + u)
inline constexpr double kUnderflowSlack = 0x1p-1000;

// A double-double value with |hi + lo - exact| <= error in each lane.
struct Bounded {
  Pair value;
  Lanes error;
};

inline Bounded exact(Lanes x) { return {{x, splat(0)}, splat(0)}; }
inline Bounded exact(Pair x) { return {x, splat(0)}; }

inline Bounded operator+(const Bounded& x, const Bounded& y) {
  const Pair z = add(x.value, y.value);
  return {z, (x.error + y.error) +
                 (kAddError * (magnitude(x.value.hi) + magnitude(y.value.hi)) + kUnderflowSlack)};
}

inline Bounded operator-(const Bounded& x) { return {{-x.value.hi, -x.value.lo}, x.error}; }
inline Bounded operator-(const Bounded& x, const Bounded& y) { return x + (-y); }

inline Bounded operator*(const Bounded& x, const Bounded& y) {
  const Pair z = multiply(x.value, y.value);
  const Lanes propagated =
      magnitude(x.value.hi) * y.error + magnitude(y.value.hi) * x.error + x.error * y.error;
  return {z, propagated + (kMultiplyError * magnitude(z.hi) + kUnderflowSlack)};
}

// Exact scaling by a power of two (no underflow in the engine's ranges: the
// slack covers it anyway).
inline Bounded scaled(const Bounded& x, double power_of_two) {
  return {{x.value.hi * power_of_two, x.value.lo * power_of_two},
          x.error * __builtin_fabs(power_of_two) + kUnderflowSlack};
}

// n / d with |error| <= 2^-100 |n / d| (9 u^2 by the residual's analysis:
// n - q0 d.hi is exact by Sterbenz's lemma).
inline Bounded quotient(double n, const Pair& d) {
  const Lanes q0 = splat(n) / d.hi;
  const Pair p = two_prod(q0, d.hi);
  const Lanes residual = ((splat(n) - p.hi) - p.lo) - q0 * d.lo;
  const Pair q = fast_two_sum(q0, residual / d.hi);
  return {q, magnitude(q0) * 0x1p-100 + kUnderflowSlack};
}

// x / y, for constants (once per phase): q0 = x.hi / y.hi corrected by the
// residual x - q0 y in double-double (rounding within 2^-98 |q|, generous
// against the 15u^2 of Joldes, Muller and Popescu's DWDivDW), and the
// operands' errors carried: |x / y - x' / y'| <= (e_x + |q| e_y) / (|y| - e_y).
// Where |y.hi| does not exceed e_y the error is infinite.
inline Bounded operator/(const Bounded& x, const Bounded& y) {
  const Lanes q0 = x.value.hi / y.value.hi;
  const Pair residual = x.value - Pair{q0, splat(0)} * y.value;
  const Pair q = fast_two_sum(q0, (residual.hi + residual.lo) / y.value.hi);
  const Lanes size = magnitude(q.hi) * (1 + 0x1p-50);
  const Lanes room = magnitude(y.value.hi) * (1 - 0x1p-50) - y.error;
  const Lanes carried = (x.error + size * y.error) / room * (1 + 0x1p-40);
  const Lanes error = room > splat(0) ? carried : splat(__builtin_inf());
  return {q, error + (size * 0x1p-98 + kUnderflowSlack)};
}

// sqrt(x) for x.hi > 0 (constants): s0 = sqrt(x.hi) corrected by one Newton
// step in double-double (within 2^-98 |s|), and |sqrt x - sqrt x'| <= e_x /
// sqrt(x.hi - e_x). Where x.hi does not exceed e_x the error is infinite.
inline Bounded square_root(const Bounded& x) {
  const Lanes s0 = square_root_of(x.value.hi);
  const Pair square = two_prod(s0, s0);
  const Pair residual = x.value - square;
  const Pair s = fast_two_sum(s0, (residual.hi + residual.lo) / (2 * s0));
  const Lanes room = x.value.hi * (1 - 0x1p-50) - x.error;
  const Lanes carried = x.error / square_root_of(room) * (1 + 0x1p-40);
  const Lanes error = room > splat(0) ? carried : splat(__builtin_inf());
  return {s, error + (magnitude(s0) * 0x1p-98 + kUnderflowSlack)};
}

// A bound on a family of Bounded values: value.hi >= |value| and error >=
// the error of each member. Subtraction adds, so each result bounds the
// magnitude of every signed instance of the same expression, and its error
// (every term monotone in the operands' magnitudes and errors) bounds theirs.
struct Envelope {
  Bounded bound;
};
inline Envelope operator+(const Envelope& x, const Envelope& y) { return {x.bound + y.bound}; }
inline Envelope operator-(const Envelope& x, const Envelope& y) { return {x.bound + y.bound}; }
inline Envelope operator*(const Envelope& x, const Envelope& y) { return {x.bound * y.bound}; }

// Lanes where the exact value (within `error` of hi + lo, hi + lo normalized)
// rounds to hi in round-to-nearest: then hi is the correctly rounded double.
// fl(hi + w) == hi for w above lo + error and for w below lo - error brackets
// the exact value between two numbers that both round to hi (rounding is
// monotone); w is taken wide enough that its own rounding cannot bring it
// inside. Non-finite lanes and tiny magnitudes (< 2^-900) are never decided.
inline Mask decided(const Pair& y, Lanes error) {
  const Lanes hi = y.hi;
  const Lanes lo = y.lo;
  const Lanes margin = error * (1 + 0x1p-40) + magnitude(hi) * 0x1p-104;
  const Lanes up = hi + (lo + margin);
  const Lanes down = hi + (lo - margin);
  return (up == hi) & (down == hi) & (magnitude(hi) > splat(0x1p-900)) &
         (magnitude(hi) < splat(0x1p1000));
}

// Helpers of the fast paths' constructors, on plain doubles and constants.
inline double first(Lanes x) { return x[0]; }
inline bool finite(double x) { return x - x == 0; }
inline double absolute(double x) { return x < 0 ? -x : x; }
// Finite and zero or within 2^+-500: far from under- and overflow, so that
// the quotients' residuals are exact (the engine's models are far inside).
inline bool moderate(double x) {
  return finite(x) && (x == 0 || (absolute(x) >= 0x1p-500 && absolute(x) <= 0x1p500));
}
// A constant kept from the first lane of a Bounded value, and back on all lanes.
inline DoubleDoubleConstant keep(const Bounded& c) {
  return {first(c.value.hi), first(c.value.lo), first(c.error)};
}
inline bool finite(const DoubleDoubleConstant& c) {
  return finite(c.hi) && finite(c.lo) && finite(c.error);
}
inline Pair lanes_of(const DoubleDoubleConstant& c) { return {splat(c.hi), splat(c.lo)}; }
// The envelope of a constant: its magnitude and its error.
inline Envelope envelope(const DoubleDoubleConstant& c) {
  return Envelope{{{splat(absolute(c.hi) + absolute(c.lo)), splat(0)}, splat(c.error)}};
}

}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes
