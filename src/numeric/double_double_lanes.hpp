// Double-double arithmetic on four lanes at once, with a running error bound
// per value: the arithmetic of the fast paths (docs/theory.md 10).
//
// A value is hi + lo (|lo| <= ulp(hi) / 2) in each lane of an AVX2 register,
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
// check `double_double_lanes_available()` first).
#pragma once

#include <immintrin.h>

#include "numeric/double_double_constant.hpp"

namespace frictionref::detail::lanes {

using Lanes = double __attribute__((vector_size(32)));    // four doubles
using Mask = long long __attribute__((vector_size(32)));  // -1 where true, 0 where false

inline Lanes splat(double x) { return Lanes{x, x, x, x}; }
inline Lanes magnitude(Lanes a) { return _mm256_andnot_pd(splat(-0.0), a); }
inline Lanes fused(Lanes a, Lanes b, Lanes c) { return _mm256_fmadd_pd(a, b, c); }  // a b + c
inline Lanes nearest_integer(Lanes a) {
  return _mm256_round_pd(a, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}

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
  const Lanes s0 = _mm256_sqrt_pd(x.value.hi);
  const Pair square = two_prod(s0, s0);
  const Pair residual = x.value - square;
  const Pair s = fast_two_sum(s0, (residual.hi + residual.lo) / (2 * s0));
  const Lanes room = x.value.hi * (1 - 0x1p-50) - x.error;
  const Lanes carried = x.error / _mm256_sqrt_pd(room) * (1 + 0x1p-40);
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

}  // namespace frictionref::detail::lanes
