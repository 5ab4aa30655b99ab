// The constants of the double-double sin and cos (numeric/double_double_lanes
// users): sin and cos of j pi/128 as double-double pairs, and pi/128 split
// into parts whose products with small integers are exact. All rounded once
// from 50-digit values (double_double_table.cpp), as sin_cos.cpp's table.
#pragma once

#include <cstddef>

namespace frictionref::detail {

struct DoubleDoubleTrigTable {
  static constexpr int kSize = 256;  // table step pi/128
  // One entry's four values side by side: a lane reads them with one load
  // (four loads and a transpose cost less than four gathers).
  struct alignas(32) Entry {
    double sin_hi, sin_lo, cos_hi, cos_lo;
  };
  Entry entry[kSize];
  // pi/128 = reduce1 + reduce2 + reduce3 + (< 2^-150): reduce1 has 38
  // significant bits, so j * reduce1 is exact for |j| < 2^15.
  double reduce1, reduce2, reduce3;
  // pi/128 = base1 + base2 + base3 + (< 2^-135): base1 has 23 significant
  // bits, so j * base1 is exact for |j| < 2^30.
  double base1, base2, base3;
  double steps_per_radian;    // 128 / pi, rounded
  double sixth_hi, sixth_lo;  // 1/6 as a pair
};

// Built once (thread-safe), about 2 ms.
const DoubleDoubleTrigTable& double_double_trig_table();

// The constants of the double-double exponential (double_double_exp.hpp):
// e^(m/2048) for |m| <= kHalf as pairs (22 KiB) and ln 2 split so that k
// ln2_1 is exact for |k| < 2^11. Rounded once from 50 digits.
struct DoubleDoubleExpTable {
  static constexpr int kSteps = 2048;  // table step 1/kSteps
  static constexpr int kHalf = 710;    // m in [-710, 710]: |m| / 2048 >= ln 2 / 2
  struct alignas(16) Entry {
    double hi, lo;
  };
  Entry entry[2 * kHalf + 1];  // e^((i - kHalf) / kSteps), side by side as the trig table's
  double ln2_1, ln2_2, ln2_3;  // ln 2 = ln2_1 + ln2_2 + ln2_3 + (< 2^-150); ln2_1: 42 bits
  double inverse_ln2;          // 1 / ln 2, rounded
};

const DoubleDoubleExpTable& double_double_exp_table();

// True where this CPU has AVX2 and FMA, the instructions of
// numeric/double_double_lanes.hpp (its users run only then).
bool double_double_lanes_available();

// True where the fast paths' rows run on eight lanes (AVX-512F), the same
// answers as on four (the *_wide.cpp translation units): where this CPU has
// AVX-512F and tests have not turned them off.
bool double_double_wide_lanes_available();
// How many of a call's n rows a fast path evaluates on eight lanes: its whole
// groups of eight where double_double_wide_lanes_available(), else none. The
// rest (and a call of fewer rows, as a single sample's) takes four lanes: the
// same answers, row by row.
std::size_t eight_lane_rows(std::size_t n);
// Tests: false keeps the rows on four lanes (to compare both widths), true
// allows eight again where the CPU has them. Not for concurrent use.
void allow_double_double_wide_lanes(bool allowed);

}  // namespace frictionref::detail
