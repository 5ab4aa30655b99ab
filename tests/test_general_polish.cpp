// The pieces that start the general engine's polish where a steady state
// puts the stop (docs/theory.md 7.4, "Predictions"): the remembered
// durations, and the point with bounds moved to the root by Taylor's theorem,
// checked against the same closed form in 50 digits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "laws/linear_oscillator/duration_guess.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"

namespace frictionref {
namespace {

using detail::DurationGuess;
using detail::LinearSlipLaw;
using detail::Oscillator;

TEST(DurationGuess, NothingWithoutHistoryOrDirection) {
  DurationGuess<long double> guess({1.0});
  EXPECT_FALSE(guess.after(1, 0.0L));
  guess.remember(1, 0.0L, 2.0L);
  EXPECT_FALSE(guess.after(-1, 10.0L));  // the other direction has none
  EXPECT_FALSE(guess.after(0, 10.0L));   // a stick from the initial state
  guess.remember(0, 0.0L, 5.0L);         // not remembered
  ASSERT_TRUE(guess.after(1, 10.0L));
  EXPECT_EQ(*guess.after(1, 10.0L), 12.0L);
}

// With harmonics of frequency 1 and 2.5 the motion repeats every second
// forcing period: of the phases one and two periods back, the latter is the
// twin, and it is taken though the former is more recent.
TEST(DurationGuess, TakesThePhaseAWholeNumberOfPeriodsBack) {
  const long double period = 2 * M_PI;
  DurationGuess<long double> guess({1.0, 2.5});
  guess.remember(1, 0 * period, 0 * period + 1.25L);
  guess.remember(1, 1 * period, 1 * period + 1.75L);
  guess.remember(1, 2 * period, 2 * period + 1.25L);
  const std::optional<long double> next = guess.after(1, 3 * period);
  ASSERT_TRUE(next);
  EXPECT_NEAR(static_cast<double>(*next - 3 * period), 1.75, 1e-15);
  // One harmonic: the latest phase is a whole period back, and it is taken.
  DurationGuess<long double> single({1.0});
  single.remember(1, 0 * period, 0 * period + 1.25L);
  single.remember(1, 1 * period, 1 * period + 1.75L);
  EXPECT_NEAR(static_cast<double>(*single.after(1, 2 * period) - 2 * period), 1.75, 1e-15);
  // The polish starts at the prediction only strictly within the bracket
  // (no aim here), and at the aim where the bracket ends there.
  const std::optional<long double> predicted = single.after(1, 2 * period);
  const long double no_aim = std::numeric_limits<long double>::quiet_NaN();
  EXPECT_TRUE(detail::polish_start(predicted, no_aim, 2 * period + 1, 2 * period + 2));
  EXPECT_FALSE(detail::polish_start(predicted, no_aim, 2 * period + 1.75L, 2 * period + 2));
  EXPECT_EQ(*detail::polish_start(predicted, 2 * period + 2, 2 * period + 1, 2 * period + 2),
            2 * period + 2);
}

// The first step of the twin's search comes from the same twin as the
// duration (none without a remembered one, or from a phase without it).
TEST(DurationGuess, FirstStepFromTheSameTwin) {
  const long double period = 2 * M_PI;
  DurationGuess<long double> guess({1.0, 2.5});
  EXPECT_EQ(guess.first_step(1, 0.0L), 0.0L);
  guess.remember(1, 0 * period, 0 * period + 1.25L, 0.5L);
  guess.remember(1, 1 * period, 1 * period + 1.75L, 0.75L);
  guess.remember(1, 2 * period, 2 * period + 1.25L);  // no first step
  EXPECT_EQ(guess.first_step(1, 3 * period), 0.75L);  // the twin two periods back
  EXPECT_EQ(guess.first_step(1, 4 * period), 0.0L);   // its twin had none
  EXPECT_EQ(guess.first_step(-1, 3 * period), 0.0L);  // the other direction has none
}

// A slip of a spring-damper oscillator with static friction and a second
// harmonic, from rest at tau_a: the point with bounds at tau0, moved by
// delta, lies within its bounds of the 50-digit closed form at tau0 + delta.
// The larger steps are beyond what the engine moves (can_move) but within
// what the bounds are derived for: there the remainders are the error, and a
// remainder left out of a bound would show.
TEST(LinearSlipLaw, MovedPointHoldsItsBounds) {
  using Wide = HighPrecision;
  Model m;
  m.friction = 0.4;
  m.static_friction = 0.6;
  m.stiffness = 1.3;
  m.damping = 0.1;
  m.harmonics.push_back({0.4, 2.5, 0.3});
  const Oscillator<long double> narrow_oscillator(m);
  const Oscillator<Wide> wide_oscillator(model_cast<Wide>(m));
  const long double tau_a = 0.3L, y_a = 0.2L, v_a = 0;
  const LinearSlipLaw<long double> narrow(narrow_oscillator, 1, tau_a, y_a, v_a);
  const LinearSlipLaw<Wide> wide(wide_oscillator, 1, Wide(tau_a), Wide(y_a), Wide(v_a));
  const long double tau0 = 2.1L;
  const auto p = narrow.point(tau0);
  int moved_by_the_engine = 0;
  for (const long double delta : {1e-13L, -2e-12L, 3e-11L, -1e-10L, 1e-6L, -1e-4L, 1e-3L}) {
    SCOPED_TRACE(static_cast<double>(delta));
    const long double tau = tau0 + delta;
    moved_by_the_engine += narrow.can_move(tau0, tau);
    const auto q = narrow.moved(p, tau);
    const auto exact = wide.point(Wide(tau), /*with_bounds=*/false);
    const auto off = [](long double value, const Wide& truth) {
      return static_cast<long double>(abs(Wide(value) - truth));
    };
    EXPECT_LE(off(q.y, exact.y), q.e_y);
    EXPECT_LE(off(q.v, exact.v), q.e_v);
    EXPECT_LE(off(q.d1, exact.d1), q.e_d1);
    EXPECT_LE(off(q.d2, exact.d2), q.e_d2);
    EXPECT_TRUE(std::isinf(q.tail2));  // bound (B) dropped, (A) kept finite
    EXPECT_TRUE(std::isfinite(q.tail));
    if (std::fabs(delta) <= 1e-10L) {
      // Where the engine moves, the values are those of a fresh evaluation
      // to a few ulps of their scale.
      const auto fresh = narrow.point(tau);
      EXPECT_LE(std::fabs(q.v - fresh.v), 1e-17L);
      EXPECT_LE(std::fabs(q.y - fresh.y), 1e-17L);
      EXPECT_LE(std::fabs(q.d1 - fresh.d1), 1e-17L);
    }
  }
  EXPECT_EQ(moved_by_the_engine, 4);
}

}  // namespace
}  // namespace frictionref
