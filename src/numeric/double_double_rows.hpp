// The rows of a dense fast path in groups of four (or eight) lanes (docs/theory.md 10):
// a group's times, the error bound of the smallest range of h = w t - w t_a
// that holds each lane (one bound per range, computed once per phase), and
// the answers stored. For the translation units compiled with -mavx2 -mfma
// -ffp-contract=off only (double_double_slip.cpp, double_double_oscillator.cpp).
#pragma once

#include <cstddef>

#include "numeric/decided_values.hpp"
#include "numeric/double_double_lanes.hpp"

namespace frictionref::detail::lanes {
inline namespace FRICTIONREF_LANES_NAMESPACE {

// The ranges of |h| with bounds of their own: a row takes those of the
// smallest range that holds its own |h|, so that its answer depends on the
// phase's start and its own time only.
inline constexpr int kRanges = 4;
inline constexpr double kRange[kRanges] = {2, 8, 64, 513};

// How many of t[i], t[i + 1], ... (of n) the group starting at i holds.
inline std::size_t group_size(std::size_t i, std::size_t n) {
  constexpr std::size_t kGroup = kLanes;
  return n - i < kGroup ? n - i : kGroup;
}

// The group's times; a short last group repeats its last time in the unused lanes.
// (A full group with one load: lanes written one at a time and read back
// as a vector stall the load on the stores, some 30 % of a seed row.)
inline Lanes group_times(const double* t, std::size_t i, std::size_t used) {
  if (used == static_cast<std::size_t>(kLanes)) {
    Lanes time;
    __builtin_memcpy(&time, t + i, sizeof time);
    return time;
  }
  Lanes time;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kLanes); ++k)
    time[k] = t[i + (k < used ? k : used - 1)];
  return time;
}

// Per lane, the bound of the smallest range holding |h| (|h| <= |h.hi| (1 + 2^-50)).
class RangePick {
 public:
  explicit RangePick(Lanes h_hi) {
    for (int k = 0; k < kRanges; ++k) in_[k] = magnitude(h_hi) <= splat(kRange[k] * (1 - 0x1p-50));
  }
  // bound[k]: the bound of range k.
  Lanes operator()(const double* bound) const {
    Lanes chosen = splat(bound[kRanges - 1]);
    for (int k = kRanges - 2; k >= 0; --k) chosen = in_[k] ? splat(bound[k]) : chosen;
    return chosen;
  }

 private:
  Mask in_[kRanges];
};

// Which of a group's values are decided, lane by lane.
struct Decisions {
  Mask position, velocity, acceleration;
};

// The group's answers: x, v, a and which of them each lane decides (the
// bits of decided_values.hpp).
inline void store_group(std::size_t i, std::size_t used, const Pair& position, const Pair& velocity,
                        const Pair& acceleration, const Decisions& ok, double* x, double* v,
                        double* a, unsigned char* decided) {
  const Mask bits = (ok.position & static_cast<long long>(kPositionDecided)) |
                    (ok.velocity & static_cast<long long>(kVelocityDecided)) |
                    (ok.acceleration & static_cast<long long>(kAccelerationDecided));
  if (used == static_cast<std::size_t>(kLanes)) {  // vector stores, and the lanes' low bytes packed
    __builtin_memcpy(x + i, &position.hi, sizeof position.hi);
    __builtin_memcpy(v + i, &velocity.hi, sizeof velocity.hi);
    __builtin_memcpy(a + i, &acceleration.hi, sizeof acceleration.hi);
#if FRICTIONREF_LANES == 4
    const __m256i words = _mm256_permutevar8x32_epi32(reinterpret_cast<__m256i>(bits),
                                                      _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0));
    const __m128i bytes = _mm_shuffle_epi8(
        _mm256_castsi256_si128(words),
        _mm_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1));
    _mm_storeu_si32(decided + i, bytes);
#else
    _mm_storel_epi64(reinterpret_cast<__m128i*>(decided + i),
                     _mm512_maskz_cvtepi64_epi8(kAllLanes, reinterpret_cast<__m512i>(bits)));
#endif
    return;
  }
  for (std::size_t k = 0; k < used; ++k) {
    x[i + k] = position.hi[k];
    v[i + k] = velocity.hi[k];
    a[i + k] = acceleration.hi[k];
    decided[i + k] = static_cast<unsigned char>(bits[k]);
  }
}

}  // namespace FRICTIONREF_LANES_NAMESPACE
}  // namespace frictionref::detail::lanes
