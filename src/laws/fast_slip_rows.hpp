// A slip's dense rows through a fast path (double_double_slip.hpp, or
// double_double_oscillator.hpp for the general model's linear slips), the
// rows it cannot decide from the long double closed form (Ziv's strategy):
// the seed's dense output and the general model's.
#pragma once

#include <algorithm>
#include <cstddef>

#include "engine/phase_formula.hpp"
#include "numeric/decided_values.hpp"

namespace frictionref::detail {

// Whether the fast path decides the row at t: all its values, or at the
// phase's own ends, where x and v are the stored states (slip_state), the
// acceleration alone (a slip's first row has v = 0 after a stop, which no
// bound decides).
inline bool row_decided(unsigned char decided, const BasicPhase<double>& phase, double t) {
  return decided == kAllDecided ||
         ((decided & kAccelerationDecided) && (t == phase.t_begin || t == phase.t_end));
}

// The rows at t[0..n) as columns x, v, a. Fast: DoubleDoubleSlip or
// DoubleDoubleOscillator (their evaluate(), which writes every row); the rows
// it leaves undecided, and the phase's own ends, are then written again.
template <class Fast, class LongDoubleAt>
void fast_slip_rows(const Fast& fast, const BasicPhase<double>& phase, const double* t,
                    std::size_t n, double* x, double* v, double* a,
                    const LongDoubleAt& long_double_at) {
  constexpr std::size_t kChunk = 64, kGroup = 8;
  const double t_begin = phase.t_begin, t_end = phase.t_end;
  // The common row, decided and inside the phase, stays as written.
  const auto common = [&](unsigned char decided, double time) {
    return (decided == kAllDecided) & (time > t_begin) & (time < t_end);  // no branches
  };
  unsigned char decided[kChunk];
  for (std::size_t i = 0; i < n; i += kChunk) {
    const std::size_t m = std::min(kChunk, n - i);
    fast.evaluate(t + i, m, x + i, v + i, a + i, decided);
    for (std::size_t k = 0; k < m; ++k) {
      if (k % kGroup == 0 && m - k >= kGroup) {  // a whole group at once, without branches
        bool all = true;
        for (std::size_t j = 0; j < kGroup; ++j) all &= common(decided[k + j], t[i + k + j]);
        if (all) {
          k += kGroup - 1;
          continue;
        }
      }
      const std::size_t r = i + k;
      const double time = t[r];
      if (common(decided[k], time)) continue;
      put_row(row_decided(decided[k], phase, time) ? slip_state(phase, time, x[r], v[r], a[r])
                                                   : long_double_at(time),
              r, x, v, a);
    }
  }
}

// The fast path's answer alone at t, where it decides (tests).
template <class Fast>
bool fast_slip_row(const Fast& fast, const BasicPhase<double>& phase, double t,
                   BasicState<double>& state) {
  double x, v, a;
  unsigned char decided;
  fast.evaluate(&t, 1, &x, &v, &a, &decided);
  if (!row_decided(decided, phase, t)) return false;
  state = slip_state(phase, t, x, v, a);
  return true;
}

}  // namespace frictionref::detail
