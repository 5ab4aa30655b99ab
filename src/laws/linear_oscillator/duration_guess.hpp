// First guesses for the polish of a phase's end (family.hpp): the duration of
// an earlier phase of the same kind and direction, laid from the new phase's
// start. In a periodic steady state the phases repeat to rounding, so the
// guess is within a few ulps of the root and the certified Halley polish
// (halley_polish.hpp) accepts after one evaluation, where the secant of the
// bracket's ends needs two or three. Of the last few such phases the one
// whose start lies the nearest to a whole number of periods of every
// harmonic back is taken: with harmonics of 1 and 2.5 the motion repeats
// every second forcing period, and the phase one period back is not its
// twin. It is only a guess: it is used where it lies strictly inside the
// certified bracket, and the polish's own error bound, not the guess,
// decides the root (the seed's laws predict their stops in closed form
// instead, docs/theory.md 3.5). The same twin also lends its search's first
// proven step (first_zero.hpp), which the new search tries first.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace frictionref::detail {

template <class Work>
class DurationGuess {
 public:
  // The harmonics' frequencies (relative to w) that set the period.
  explicit DurationGuess(std::vector<double> frequencies) : q_(std::move(frequencies)) {}

  // direction: +1 or -1 (a slip's sign; for a stick, that of the slip that
  // ended in it); 0 is not remembered.
  // first_step: the length of its search's first proven step (0: none).
  void remember(int direction, const Work& start, const Work& end, const Work& first_step = 0) {
    if (direction == 0) return;
    History& h = history(direction);
    h.entries[h.next] = {start, end - start, first_step};
    h.next = (h.next + 1) % kDepth;
    if (h.size < kDepth) ++h.size;
  }

  // start + the chosen duration: where the phase that began at `start`
  // should end.
  std::optional<Work> after(int direction, const Work& start) const {
    const Entry* e = twin(direction, start);
    if (!e) return std::nullopt;
    return start + e->duration;
  }

  // The first proven step of the twin's search (0 where there is none).
  Work first_step(int direction, const Work& start) const {
    const Entry* e = twin(direction, start);
    return e ? e->first_step : Work(0);
  }

 private:
  static constexpr std::size_t kDepth = 4;
  struct Entry {
    Work start = 0, duration = 0, first_step = 0;
  };
  struct History {
    std::array<Entry, kDepth> entries{};
    std::size_t next = 0, size = 0;
  };

  // Of the last phases alike, the one whose start lies the nearest to a
  // whole number of periods back (none without a positive duration).
  const Entry* twin(int direction, const Work& start) const {
    if (direction == 0) return nullptr;
    const History& h = history(direction);
    const Entry* best = nullptr;
    double best_mismatch = 0;
    for (std::size_t k = 1; k <= h.size; ++k) {  // the latest first
      const Entry& e = h.entries[(h.next + kDepth - k) % kDepth];
      const double mismatch = period_mismatch(static_cast<double>(start - e.start));
      if (!best || mismatch < best_mismatch - 1e-9) {
        best = &e;
        best_mismatch = mismatch;
      }
      if (best_mismatch < 1e-6) break;  // a whole number of periods back: its twin
    }
    if (!best || !(best->duration > 0)) return nullptr;
    return best;
  }

  // How far a shift of the start by delta is from a whole number of periods
  // of every harmonic, in radians summed over them.
  double period_mismatch(double delta) const {
    double sum = 0;
    for (const double q : q_) {
      const double turns = q * delta / (2 * M_PI);
      sum += 2 * M_PI * std::fabs(turns - std::nearbyint(turns));
    }
    return sum;
  }

  History& history(int direction) { return direction > 0 ? positive_ : negative_; }
  const History& history(int direction) const { return direction > 0 ? positive_ : negative_; }

  std::vector<double> q_;
  History positive_, negative_;
};

// Where the polish of a bracket [lo, hi] starts: at the search's aim where
// the bracket ends there (its point is at hand), else at the prediction where
// it lies strictly inside, else nowhere in particular (the secant decides).
template <class Work>
std::optional<Work> polish_start(const std::optional<Work>& predicted, const Work& aim,
                                 const Work& lo, const Work& hi) {
  if (hi == aim) return aim;
  if (predicted && *predicted > lo && *predicted < hi) return predicted;
  return std::nullopt;
}

}  // namespace frictionref::detail
