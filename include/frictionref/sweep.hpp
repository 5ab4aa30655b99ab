// A sweep over lambda = R / B: for each lambda, the exact engine is streamed
// over a number of forcing periods and the last full period is measured as
// the steady state that the simulation reached (the simulated regime, the
// fraction of time at rest, the distance slid, the stops and reversals). It is
// set next to the regime that the threshold lambda* gives (regime_for), so
// the two can be compared point by point (docs/cli.md, "sweep").
//
// Every lambda runs the model m = B = w = 1, R = lambda, x0 = 0, t0 = 0 and
// v0 as given (so times are forcing phases w t in radians, velocities are in
// B/(m w) and lengths in B/(m w^2)). Nothing is stored per phase: memory per
// lambda is one SweepPoint.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "frictionref/types.hpp"

namespace frictionref {

struct SweepOptions {
  // Initial velocity of every run [B/(m w)]; finite.
  double v0 = 0;
  // Forcing periods simulated before the measured one ends; >= 1 and <= max_periods.
  // The run goes from t = 0 to 2 pi periods + pi/2 and the measured period is
  // [2 pi (periods - 1) + pi/2, 2 pi periods + pi/2] (see sweep_window).
  std::uint64_t periods = 100;
  // Worker threads for sweep(); 0: std::thread::hardware_concurrency() (1 if unknown).
  unsigned threads = 0;

  static constexpr std::uint64_t max_periods = 1'000'000;

  // Throws InvalidInput naming the field ("v0", "periods") and the rule.
  void validate() const;
};

// The measured period of a run with `periods` periods, as user times (w = 1).
// Its ends lie at force maxima (w t = pi/2 mod 2 pi). No event of any steady
// state lies there for lambda > 0: breakaways are at asin(lambda) < pi/2 and
// pi + asin(lambda); dead-band stops after pi - asin(lambda) > pi/2 (forward)
// or before asin(lambda) (backward, mod 2 pi); continuous reversals at
// tau1 < pi/2 and tau1 + pi. So each periodic event is counted exactly once,
// whatever the rounding of the window's ends.
struct SweepWindow {
  double begin = 0;  // 2 pi (periods - 1) + pi/2
  double end = 0;    // 2 pi periods + pi/2: the engine's horizon
};
SweepWindow sweep_window(std::uint64_t periods);

// How far above lambda* the simulated regime can say `continuous` where the
// threshold says `dead_bands`: 8 eps (2 pi periods + pi/2) / 4.1104, about
// 2.72e-15 periods (2.7e-13 for 100). There the dead band, 4.1104 (lambda -
// lambda*) rad long (docs/theory.md 5.6), is shorter than the engine's time
// resolution 8 eps |w t| at the end of the run (theory.md 4.1), so the stop
// and the breakaway after it merge into a reversal. Everywhere else the two
// regimes agree (docs/cli.md, "sweep", and tests/test_sweep.cpp). The
// transient is not what limits this: from above lambda* the motion is
// periodic from the first breakaway, and below it the reversal map contracts
// by |kappa| = (sin tau1 - lambda) / (sin tau1 + lambda), which tends to 0 at
// lambda*.
double sweep_unresolved_distance(std::uint64_t periods);

// What one lambda's run shows in its measured (last) period.
struct SweepPoint {
  double lambda = 0;
  // Time at rest in the measured period divided by its length 2 pi: in [0, 1].
  double stuck_fraction = 0;
  // Distance slid in the measured period, the integral of |v| dt: the sum of
  // |x_end - x_begin| over its slips (cut at the window's ends) [B/(m w^2)].
  double slide_per_period = 0;
  // Stops in the measured period: slips that end in a stick (v = 0 and rest
  // for a positive time). Reversals (v = 0 without rest) are not stops.
  std::uint32_t stops_per_period = 0;
  // Reversals in the measured period: v = 0 followed at once by the opposite
  // slip. A dead band shorter than the engine's time resolution (8 eps |w t|
  // at the time of the stop) is not resolved and shows as a reversal.
  std::uint32_t reversals_per_period = 0;
  // From the measured period:
  //   stops       the run ends at rest and no breakaway happened in the period
  //               (at rest throughout it, or its motion ended in a stick for good);
  //   dead_bands  otherwise, if the mass was at rest for a positive time in it;
  //   continuous  otherwise (it slid all the time; v = 0 only at reversals).
  Regime regime_simulated = Regime::stops;
  // regime_for(lambda): by the exact threshold lambda*.
  Regime regime_threshold = Regime::stops;
  // reached_end, or how the engine stopped early (an internal error; the
  // figures are then those of the part that was computed).
  Termination termination = Termination::reached_end;

  bool regimes_agree() const { return regime_simulated == regime_threshold; }
};

// One lambda (finite, >= 0): streams the engine over the run and measures the
// window. Throws InvalidInput for a bad lambda or options, or if the engine
// refuses the model (its motion would leave the range of double).
SweepPoint sweep_point(double lambda, const SweepOptions& options);

// `points` lambdas from `from` to `to`: the ends rounded to double, and in
// between from + (to - from) i / (points - 1) evaluated in long double and
// rounded once to double (not accumulated, and not the double step of
// numpy.linspace). Give decimal ends as long double (strtold, or 1.2L) to get
// the doubles nearest the decimal grid: sweep_grid(0, 1.2L, 7) holds 0.8 and
// 1 where a double step gives 0.7999999999999999 and 0.9999999999999999.
// points = 1 needs from == to. Throws InvalidInput ("lambda_from",
// "lambda_to", "points") for non-finite or negative ends, to < from,
// points = 0, points = 1 with from != to, points >= 2 with from == to, or a
// step so small that two lambdas would be equal.
std::vector<double> sweep_grid(long double from, long double to, std::size_t points);

// Called on the thread that called sweep(), about ten times a second and
// once at the end (done == total): lambdas finished so far, and all.
using SweepProgress = std::function<void(std::size_t done, std::size_t total)>;

// sweep_point for every lambda, on options.threads worker threads (dynamic
// chunks taken from an atomic counter). The result is in the order of
// `lambdas` and does not depend on the number of threads: each point is
// computed by itself, the same way, on whichever thread takes it. Validates
// every lambda and the options first (InvalidInput); an exception thrown by
// a worker stops the others and is rethrown here.
std::vector<SweepPoint> sweep(const std::vector<double>& lambdas, const SweepOptions& options,
                              const SweepProgress& progress = {});

}  // namespace frictionref
