// What the dense fast paths' tests compare rows with: the double nearest a
// 50-digit value, rows equal bit for bit, the times and rows they sample in a
// slip, the checks of a slip's end rows, and of the rows on four and on eight
// lanes.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <vector>

#include "frictionref/phase.hpp"
#include "numeric/double_double_table.hpp"

namespace frictionref::testing {

using Fifty = boost::multiprecision::cpp_bin_float_50;

// The double nearest x (ties cannot occur at 50 digits for these values).
inline double nearest(const Fifty& x) {
  const double d = static_cast<double>(x);
  double best = d;
  for (double n : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)})
    if (abs(Fifty(n) - x) < abs(Fifty(best) - x)) best = n;
  return best;
}

// Bitwise, so that -0 and +0 or NaNs would count as different.
inline bool same_row(const State& s, const State& r) {
  return std::memcmp(&s.x, &r.x, sizeof(double)) == 0 &&
         std::memcmp(&s.v, &r.v, sizeof(double)) == 0 &&
         std::memcmp(&s.a, &r.a, sizeof(double)) == 0 && s.t == r.t && s.phase == r.phase;
}

// The times at which the tests probe a slip's decided values: four spread
// over it and four crowded towards its stop (where v -> 0 and the bounds are
// tested hardest), each drawn with one call of unit() (uniform on [0, 1));
// those that round onto an end of the phase are left out.
template <class Unit>
std::vector<double> probe_times(const Phase& phase, Unit& unit) {
  std::vector<double> times;
  for (int j = 0; j < 8; ++j) {
    const double fraction = j < 4 ? unit() : 1 - std::pow(10.0, -12 * unit());
    const double t = phase.t_begin + fraction * phase.duration();
    if (t > phase.t_begin && t < phase.t_end) times.push_back(t);
  }
  return times;
}

// A slip's rows at 1/6, 1/2 and 5/6 of its duration, as the tests sample
// them: through the formula's batch (at_many: the fast path with its
// fallback) and through its long double path alone.
struct SlipRow {
  double t;
  State batch, long_double;
  bool inside;  // t strictly inside the phase (not rounded onto an end)
};
template <class Formula>
std::array<SlipRow, 3> slip_rows(const Formula& formula, const Phase& phase) {
  constexpr int kTimes = 3;
  double times[kTimes];
  for (int j = 0; j < kTimes; ++j) times[j] = phase.t_begin + phase.duration() * (j + 0.5) / kTimes;
  State batch[kTimes];
  formula.at_many(times, kTimes, batch);
  std::array<SlipRow, kTimes> rows;
  for (int j = 0; j < kTimes; ++j)
    rows[j] = {times[j], batch[j], formula.long_double_at(times[j]),
               times[j] > phase.t_begin && times[j] < phase.t_end};
  return rows;
}

// The end-row tests' counts: rows, those the fast path decides, and those of
// them unlike the long double path's.
struct EndRowCounts {
  std::uint64_t rows = 0, decided = 0, differing = 0;
};

// A slip's rows at its own ends (a curve's event rows), through the
// formula's batch, checked: x and v are the stored states; where the fast
// path decides the row (on its acceleration alone there), the batch gives the
// fast row and its acceleration is exact_a(t), the correctly rounded
// 50-digit value; elsewhere the batch gives the long double path's row.
// describe() names the model in a failure's message.
template <class Formula, class ExactA, class Describe>
void check_end_rows(const Formula& formula, const Phase& phase, const ExactA& exact_a,
                    const Describe& describe, EndRowCounts& counts) {
  const double times[2] = {phase.t_begin, phase.t_end};
  State batch[2];
  formula.at_many(times, 2, batch);
  for (int j = 0; j < 2; ++j) {
    ++counts.rows;
    const State slow = formula.long_double_at(times[j]);
    ASSERT_EQ(batch[j].x, j ? phase.x_end : phase.x_begin) << describe();
    ASSERT_EQ(batch[j].v, j ? phase.v_end : phase.v_begin) << describe();
    State fast;
    if (!formula.fast_at(times[j], fast)) {
      ASSERT_TRUE(same_row(batch[j], slow)) << describe() << " t=" << times[j];
      continue;
    }
    ++counts.decided;
    ASSERT_TRUE(same_row(batch[j], fast)) << describe() << " t=" << times[j];
    ASSERT_EQ(fast.a, exact_a(times[j])) << describe() << " t=" << times[j];
    counts.differing += !same_row(fast, slow);
  }
}

// The counts printed, and the floor every end-row test holds them to: over
// 3,000 rows, more than half of them decided.
inline void expect_end_rows_tested(const EndRowCounts& counts) {
  std::cout << counts.decided << " of " << counts.rows << " end rows decided by the fast path, "
            << counts.differing << " of them not the long double path's\n";
  EXPECT_GT(counts.rows, 3000u);
  EXPECT_GT(counts.decided, counts.rows / 2);
}

// The rows of the fast path's eight lanes against those of its four. Rows on
// eight lanes are allowed (the default) while this lives.
class WideLanesAllowedAfter {
 public:
  WideLanesAllowedAfter() = default;
  WideLanesAllowedAfter(const WideLanesAllowedAfter&) = delete;
  WideLanesAllowedAfter& operator=(const WideLanesAllowedAfter&) = delete;
  ~WideLanesAllowedAfter() { detail::allow_double_double_wide_lanes(true); }
};

// A slip's batch of 21 rows (its ends and 19 times evenly between: two groups
// of eight lanes and a rest of five), through the formula's batch with rows
// on eight lanes and again on four: the same states, bit for bit. A row one
// width decides and the other does not would differ wherever the long double
// path's row is not the correctly rounded one (a quarter of rows on the
// random models): the decisions are compared as well. Counts the rows.
template <class Formula, class Describe>
void check_lane_widths(const Formula& formula, const Phase& phase, const Describe& describe,
                       std::uint64_t& rows) {
  constexpr int kTimes = 21;
  double times[kTimes];
  for (int j = 0; j < kTimes; ++j)
    times[j] = j == kTimes - 1 ? phase.t_end : phase.t_begin + phase.duration() * j / (kTimes - 1);
  State wide[kTimes], narrow[kTimes];
  const WideLanesAllowedAfter restore;
  detail::allow_double_double_wide_lanes(true);
  formula.at_many(times, kTimes, wide);
  detail::allow_double_double_wide_lanes(false);
  formula.at_many(times, kTimes, narrow);
  for (int j = 0; j < kTimes; ++j) {
    ++rows;
    ASSERT_TRUE(same_row(wide[j], narrow[j])) << describe() << " t=" << times[j];
  }
}

}  // namespace frictionref::testing
