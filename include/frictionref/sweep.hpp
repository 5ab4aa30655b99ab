// A sweep over lambda = R / B: for each lambda, the exact engine is streamed
// over a number of forcing periods and the last full period is measured as
// the steady state that the simulation reached (the simulated regime, the
// fraction of time at rest, the distance slid, the stops and reversals). It is
// set next to the regime that a closed form gives where one applies (the
// threshold lambda* for the seed's model, Den Hartog's non-stop solution for
// a spring without damper), so the two can be compared point by point
// (docs/cli.md, "sweep").
//
// Every lambda runs SweepOptions::base (by default the seed's model
// m = B = w = 1 from x0 = 0) with R = lambda B, Rs = static_ratio R, t0 = 0
// and v0 as given. For the default model times are forcing phases w t in
// radians, velocities are in B/(m w) and lengths in B/(m w^2). Nothing is
// stored per phase: memory per lambda is one SweepPoint.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/types.hpp"

namespace frictionref {

struct SweepOptions {
  // Initial velocity of every run [length / time; B/(m w) for the default
  // model]; finite.
  double v0 = 0;
  // Forcing periods simulated before the measured one ends; >= 1 and <= max_periods.
  // The run goes from t = 0 to periods T + pi/(2 w) and the measured period is
  // the last T of it (see sweep_window); T = 2 pi / w for the seed's model.
  std::uint64_t periods = 100;
  // Worker threads for sweep(); 0: std::thread::hardware_concurrency() (1 if unknown).
  unsigned threads = 0;
  // The model of every run apart from its friction, initial velocity and
  // start time (the general model, docs/theory.md 7): mass, amplitude B (> 0,
  // since lambda = R / B), omega, stiffness, damping, force offset, extra
  // harmonics (with a common period with w: classification.hpp's
  // forcing_period) and x0. Each run sets R = lambda B, Rs = static_ratio R,
  // v0 from above and t0 = 0, so base.friction, base.static_friction, base.v0
  // and base.t0 must keep their defaults (0, unset, 0, 0). The default is the
  // seed's model with m = B = w = 1 and x0 = 0.
  Model base;
  // Rs / R of every run: the static friction is this multiple of the sliding
  // friction at every lambda (a property of the surfaces, as map's lambda
  // axis keeps it); finite, >= 1. 1: Rs = R.
  double static_ratio = 1;

  static constexpr std::uint64_t max_periods = 1'000'000;

  // Throws InvalidInput naming the field ("v0", "periods", "static_ratio",
  // or the base model's field: "mass", "amplitude", "harmonics[1].omega", ...)
  // and the rule.
  void validate() const;
};

// The closed form that gives SweepPoint::regime_threshold for a base model.
enum class SweepThreshold {
  // The seed's model (no spring, damper, offset or extra harmonics, Rs = R;
  // any m, B, w, x0): regime_for(lambda), by lambda* = 2 / sqrt(4 + pi^2).
  lambda_star,
  // A spring without damper, offset or extra harmonics (any Rs / R):
  // continuous where Den Hartog's non-stop solution exists and is stable
  // (den_hartog.hpp, as classify() decides); no closed form elsewhere.
  den_hartog,
  // Any other model: no closed form gives the regime.
  none,
};
// "lambda-star", "den-hartog", "none"
std::string_view to_string(SweepThreshold rule);
// Which closed form applies to options.base and options.static_ratio.
SweepThreshold sweep_threshold_rule(const SweepOptions& options);

// The measured period of a run with `periods` periods of the seed's model
// with w = 1, as user times. Its ends lie at force maxima (w t = pi/2 mod
// 2 pi). No event of any steady state lies there for lambda > 0: breakaways
// are at asin(lambda) < pi/2 and pi + asin(lambda); dead-band stops after
// pi - asin(lambda) > pi/2 (forward) or before asin(lambda) (backward, mod
// 2 pi); continuous reversals at tau1 < pi/2 and tau1 + pi. So each periodic
// event is counted exactly once, whatever the rounding of the window's ends.
struct SweepWindow {
  double begin = 0;  // 2 pi (periods - 1) + pi/2
  double end = 0;    // 2 pi periods + pi/2: the engine's horizon
};
SweepWindow sweep_window(std::uint64_t periods);
// The same for any base model (SweepOptions::base): with T the forcing's
// common period (n periods 2 pi / w of the first harmonic), from
// (2 pi n (periods - 1) + pi/2) / w to (2 pi n periods + pi/2) / w, in long
// double and rounded once. The same numbers as sweep_window(periods) for
// w = 1 and n = 1. For the general model the steady events have no known
// place, so none is kept off the window's ends by construction; an event
// within rounding of an end (a coincidence of the parameters) may be counted
// in the measured period or in the one before it. Throws InvalidInput if the
// forcing has no common period (classification.hpp's forcing_period).
SweepWindow sweep_window(std::uint64_t periods, const Model& base);

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
// (For the seed's model with w = 1; in the forcing phase w t for any w.)
double sweep_unresolved_distance(std::uint64_t periods);

// What one lambda's run shows in its measured (last) period.
struct SweepPoint {
  double lambda = 0;
  // Time at rest in the measured period divided by its length T: in [0, 1].
  double stuck_fraction = 0;
  // Distance slid in the measured period, the integral of |v| dt: the sum of
  // |x_end - x_begin| over its slips (cut at the window's ends) [length;
  // B/(m w^2) for the default model].
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
  // The regime a closed form gives (threshold_rule): regime_for(lambda) by
  // the exact threshold lambda* for the seed's model; continuous where Den
  // Hartog's non-stop solution exists and is stable for a spring without
  // damper. Empty where no closed form decides it (every other model, and
  // Den Hartog's models where the non-stop solution does not hold).
  std::optional<Regime> regime_threshold;
  SweepThreshold threshold_rule = SweepThreshold::lambda_star;
  // reached_end, or how the engine stopped early (an internal error; the
  // figures are then those of the part that was computed).
  Termination termination = Termination::reached_end;

  // A closed form gives the regime and the simulation shows the same one.
  bool regimes_agree() const {
    return regime_threshold.has_value() && regime_simulated == *regime_threshold;
  }
  // A closed form gives the regime and the simulation shows another one.
  bool regimes_differ() const {
    return regime_threshold.has_value() && regime_simulated != *regime_threshold;
  }
};

// One lambda (finite, >= 0): streams the engine over the run and measures the
// window. Throws InvalidInput for a bad lambda or options (a friction
// R = lambda B beyond the range of double is named "friction"), or if the
// engine refuses the model (its motion would leave the range of double, or
// its time scales are below the engine's resolution).
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
