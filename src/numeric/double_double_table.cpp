#include "numeric/double_double_table.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

namespace frictionref::detail {
namespace {

using Fifty = boost::multiprecision::cpp_bin_float_50;

// x rounded to `bits` significant bits below 2^top (x in [2^(top-1), 2^top)).
Fifty rounded_to_bits(const Fifty& x, int top, int bits) {
  const Fifty scale = ldexp(Fifty(1), bits - top);
  return round(x * scale) / scale;
}

// hi + lo = value to 2^-106 relative.
void split(const Fifty& value, double& hi, double& lo) {
  hi = static_cast<double>(value);
  lo = static_cast<double>(value - hi);
}

DoubleDoubleTrigTable make_table() {
  DoubleDoubleTrigTable t{};
  const Fifty step = boost::math::constants::pi<Fifty>() / 128;
  // The first quadrant from 50 digits; the others by exact symmetry, as in
  // sin_cos.cpp.
  constexpr int kQuadrant = DoubleDoubleTrigTable::kSize / 4;
  double s_hi[kQuadrant], s_lo[kQuadrant], c_hi[kQuadrant], c_lo[kQuadrant];
  for (int j = 0; j < kQuadrant; ++j) {
    split(sin(step * j), s_hi[j], s_lo[j]);
    split(cos(step * j), c_hi[j], c_lo[j]);
  }
  for (int j = 0; j < DoubleDoubleTrigTable::kSize; ++j) {
    const int r = j % kQuadrant;
    double sh = 0, sl = 0, ch = 0, cl = 0;
    switch (j / kQuadrant) {
      case 0:
        sh = s_hi[r];
        sl = s_lo[r];
        ch = c_hi[r];
        cl = c_lo[r];
        break;
      case 1:
        sh = c_hi[r];
        sl = c_lo[r];
        ch = -s_hi[r];
        cl = -s_lo[r];
        break;
      case 2:
        sh = -s_hi[r];
        sl = -s_lo[r];
        ch = -c_hi[r];
        cl = -c_lo[r];
        break;
      default:
        sh = -c_hi[r];
        sl = -c_lo[r];
        ch = s_hi[r];
        cl = s_lo[r];
        break;
    }
    t.entry[j] = {sh, sl, ch, cl};
  }
  // pi/128 is in [2^-6, 2^-5).
  const Fifty r1 = rounded_to_bits(step, -5, 38);
  t.reduce1 = static_cast<double>(r1);
  t.reduce2 = static_cast<double>(step - r1);
  t.reduce3 = static_cast<double>(step - r1 - Fifty(t.reduce2));
  const Fifty b1 = rounded_to_bits(step, -5, 23);
  t.base1 = static_cast<double>(b1);
  t.base2 = static_cast<double>(step - b1);
  t.base3 = static_cast<double>(step - b1 - Fifty(t.base2));
  t.steps_per_radian = static_cast<double>(1 / step);
  split(Fifty(1) / 6, t.sixth_hi, t.sixth_lo);
  return t;
}

DoubleDoubleExpTable make_exp_table() {
  DoubleDoubleExpTable t{};
  // e^(m/2048) by repeated products of e^(+-1/2048) from 1: 710 roundings of
  // 50 digits, far below the pairs' own 2^-106.
  constexpr int kHalf = DoubleDoubleExpTable::kHalf;
  const Fifty up = exp(Fifty(1) / DoubleDoubleExpTable::kSteps), down = 1 / up;
  Fifty above = 1, below = 1;
  split(above, t.entry[kHalf].hi, t.entry[kHalf].lo);
  for (int m = 1; m <= kHalf; ++m) {
    above *= up;
    below *= down;
    split(above, t.entry[kHalf + m].hi, t.entry[kHalf + m].lo);
    split(below, t.entry[kHalf - m].hi, t.entry[kHalf - m].lo);
  }
  const Fifty ln2 = boost::math::constants::ln_two<Fifty>();
  // ln 2 is in [2^-1, 2^0).
  const Fifty l1 = rounded_to_bits(ln2, 0, 42);
  t.ln2_1 = static_cast<double>(l1);
  t.ln2_2 = static_cast<double>(ln2 - l1);
  t.ln2_3 = static_cast<double>(ln2 - l1 - Fifty(t.ln2_2));
  t.inverse_ln2 = static_cast<double>(1 / ln2);
  return t;
}

}  // namespace

const DoubleDoubleExpTable& double_double_exp_table() {
  static const DoubleDoubleExpTable table = make_exp_table();
  return table;
}

bool double_double_lanes_available() {
  static const bool available = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return available;
}

namespace {
bool wide_lanes_allowed = true;
}  // namespace

bool double_double_wide_lanes_available() {
  static const bool available =
      double_double_lanes_available() && __builtin_cpu_supports("avx512f");
  return available && wide_lanes_allowed;
}

void allow_double_double_wide_lanes(bool allowed) { wide_lanes_allowed = allowed; }

std::size_t eight_lane_rows(std::size_t n) {
  return double_double_wide_lanes_available() ? n - n % 8 : 0;
}

const DoubleDoubleTrigTable& double_double_trig_table() {
  static const DoubleDoubleTrigTable table = make_table();
  return table;
}

}  // namespace frictionref::detail
