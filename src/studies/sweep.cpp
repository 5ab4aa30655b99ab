// The lambda sweep (sweep.hpp): one streamed engine run per lambda, measured
// over its last period, and a pool of std::threads taking chunks of lambdas
// from an atomic counter.
#include "frictionref/sweep.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "frictionref/classification.hpp"
#include "frictionref/den_hartog.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/steady_state.hpp"
#include "studies/parallel_for.hpp"

namespace frictionref {
namespace {

std::string text(double value) { return detail::shortest_text(value); }

void require_lambda(const char* name, double lambda) {
  if (!std::isfinite(lambda)) throw InvalidInput(name, text(lambda), "must be a finite number");
  if (!(lambda >= 0)) throw InvalidInput(name, text(lambda), "must be >= 0");
}

// The run at one lambda: the base model with R = lambda B, Rs = ratio R, v0.
// For the default base this is m = B = w = 1, R = lambda (exactly: B = 1).
Model sweep_model(double lambda, const SweepOptions& options) {
  Model model = options.base;
  model.friction = lambda * model.amplitude;
  if (!std::isfinite(model.friction))
    throw InvalidInput("lambda", text(lambda), "R = lambda B must be a finite number");
  // Rs = ratio R >= R for ratio >= 1 (rounding is monotone); left unset for
  // ratio 1, so the seed's model stays the seed's model.
  if (options.static_ratio != 1) {
    model.static_friction = options.static_ratio * model.friction;
    if (!std::isfinite(*model.static_friction))
      throw InvalidInput("static_ratio", text(options.static_ratio),
                         "Rs = S lambda B must be a finite number");
  }
  model.v0 = options.v0;
  model.t0 = 0;
  // R (or Rs) beyond the range of double: named as the friction.
  model.validate();
  return model;
}

// n: the forcing's common period in periods 2 pi / w of the first harmonic
// (1 without extra harmonics, or when they are multiples of w).
std::uint64_t periods_of_first_harmonic(const Model& base) {
  if (base.harmonics.empty()) return 1;
  const std::optional<double> period = forcing_period(base);
  if (!period) {
    // Name the last harmonic that takes part (the one that broke the period).
    std::size_t last = 0;
    for (std::size_t i = 0; i < base.harmonics.size(); ++i)
      if (base.harmonics[i].amplitude != 0) last = i;
    throw InvalidInput("harmonics[" + std::to_string(last) + "].omega",
                       text(base.harmonics[last].omega),
                       "has no common period with the other forcing frequencies (ratios p/q "
                       "with q <= 1000, a period of at most 1000 periods 2 pi / w); the sweep "
                       "measures one forcing period");
  }
  const double n = std::round(*period * base.omega / boost::math::constants::two_pi<double>());
  return static_cast<std::uint64_t>(std::max(1.0, n));
}

}  // namespace

std::string_view to_string(SweepThreshold rule) {
  switch (rule) {
    case SweepThreshold::lambda_star:
      return "lambda-star";
    case SweepThreshold::den_hartog:
      return "den-hartog";
    case SweepThreshold::none:
      break;
  }
  return "none";
}

SweepThreshold sweep_threshold_rule(const SweepOptions& options) {
  const Model& base = options.base;
  const bool seed = base.stiffness == 0 && base.damping == 0 && base.force_offset == 0 &&
                    base.harmonics.empty() && options.static_ratio == 1;
  if (seed) return SweepThreshold::lambda_star;
  if (den_hartog_applies(base)) return SweepThreshold::den_hartog;
  return SweepThreshold::none;
}

void SweepOptions::validate() const {
  if (!std::isfinite(v0)) throw InvalidInput("v0", text(v0), "must be a finite number");
  if (periods < 1) throw InvalidInput("periods", std::to_string(periods), "must be >= 1");
  if (periods > max_periods)
    throw InvalidInput("periods", std::to_string(periods), "must be <= 10^6");
  if (!std::isfinite(static_ratio))
    throw InvalidInput("static_ratio", text(static_ratio), "must be a finite number");
  if (!(static_ratio >= 1))
    throw InvalidInput("static_ratio", text(static_ratio),
                       "must be >= 1 (static friction Rs = ratio R is at least the sliding "
                       "friction R)");
  base.validate();
  base.refuse_ground_motion(
      "is not taken by sweep: it measures steady states, which a record (a transient) does "
      "not have (newmark runs records x yield accelerations)");
  if (!(base.amplitude > 0))
    throw InvalidInput("amplitude", text(base.amplitude), "must be > 0 (lambda = R / B)");
  const auto set_by_sweep = [](const char* name, double value, const char* rule) {
    throw InvalidInput(name, text(value), rule);
  };
  if (base.friction != 0)
    set_by_sweep("friction", base.friction,
                 "must be 0 in the base model: the sweep sets R = lambda B");
  if (base.static_friction)
    set_by_sweep("static_friction", *base.static_friction,
                 "must be unset in the base model: the sweep sets Rs = static_ratio R");
  if (base.v0 != 0)
    set_by_sweep("v0", base.v0, "must be 0 in the base model: the sweep takes SweepOptions::v0");
  if (base.t0 != 0)
    set_by_sweep("t0", base.t0, "must be 0 in the base model: every run starts at t = 0");
  (void)periods_of_first_harmonic(base);
}

SweepWindow sweep_window(std::uint64_t periods) { return sweep_window(periods, Model{}); }

SweepWindow sweep_window(std::uint64_t periods, const Model& base) {
  if (periods < 1) throw InvalidInput("periods", "0", "must be >= 1");
  // In long double, rounded once to double: each end is within about half an
  // ulp of (2 pi n k + pi/2) / w.
  const long double n = static_cast<long double>(periods_of_first_harmonic(base));
  const long double w = base.omega;
  const long double two_pi_l = boost::math::constants::two_pi<long double>();
  const long double half_pi_l = boost::math::constants::half_pi<long double>();
  SweepWindow window;
  window.begin =
      static_cast<double>((two_pi_l * n * static_cast<long double>(periods - 1) + half_pi_l) / w);
  window.end =
      static_cast<double>((two_pi_l * n * static_cast<long double>(periods) + half_pi_l) / w);
  return window;
}

double sweep_unresolved_distance(std::uint64_t periods) {
  // 4.1104: the dead band per unit of lambda - lambda*, (4 + pi^2)^(3/2) / (4 pi).
  return 8 * std::numeric_limits<double>::epsilon() * sweep_window(periods).end / 4.1104;
}

SweepPoint sweep_point(double lambda, const SweepOptions& options) {
  require_lambda("lambda", lambda);
  options.validate();
  const Model model = sweep_model(lambda, options);
  const SweepWindow window = sweep_window(options.periods, options.base);
  ExactEngine engine(model, window.end);

  SweepPoint point;
  point.lambda = lambda;
  point.threshold_rule = sweep_threshold_rule(options);
  if (point.threshold_rule == SweepThreshold::lambda_star) {
    point.regime_threshold = regime_for(lambda);
  } else if (point.threshold_rule == SweepThreshold::den_hartog) {
    const DenHartogSolution solution = den_hartog(model);
    if (solution.non_stop && solution.stable) point.regime_threshold = Regime::continuous;
  }

  double rest = 0;   // time at rest inside the window
  double slide = 0;  // distance slid inside the window
  std::uint32_t breakaways = 0;
  bool have_previous = false;
  PhaseKind previous = PhaseKind::stick;
  PhaseKind last = PhaseKind::stick;
  Phase phase;
  while (engine.next(phase)) {
    last = phase.kind;
    if (phase.t_end > window.begin) {
      const bool starts_inside = phase.t_begin >= window.begin;
      if (phase.kind == PhaseKind::stick) {
        rest += phase.t_end - (starts_inside ? phase.t_begin : window.begin);
      } else {
        const double x_begin =
            starts_inside ? phase.x_begin : evaluate(model, phase, window.begin).x;
        slide += std::fabs(phase.x_end - x_begin);
      }
      // The boundary at phase.t_begin is an event of the window.
      if (starts_inside && have_previous) {
        if (previous == PhaseKind::stick) {
          ++breakaways;
        } else if (phase.kind == PhaseKind::stick) {
          ++point.stops_per_period;
        } else if (phase.kind != previous) {
          ++point.reversals_per_period;
        }
      }
    }
    previous = phase.kind;
    have_previous = true;
  }
  point.termination = engine.summary().termination;

  const double length = window.end - window.begin;
  point.stuck_fraction = std::min(1.0, rest / length);
  point.slide_per_period = slide;
  if (last == PhaseKind::stick && breakaways == 0) {
    point.regime_simulated = Regime::stops;
  } else if (rest > 0) {
    point.regime_simulated = Regime::dead_bands;
  } else {
    point.regime_simulated = Regime::continuous;
  }
  return point;
}

std::vector<double> sweep_grid(long double from_exact, long double to_exact, std::size_t points) {
  const double from = static_cast<double>(from_exact);
  const double to = static_cast<double>(to_exact);
  require_lambda("lambda_from", from);
  require_lambda("lambda_to", to);
  if (!(to >= from))
    throw InvalidInput("lambda_to", text(to), "must be >= lambda_from = " + text(from));
  if (points == 0) throw InvalidInput("points", "0", "must be >= 1");
  if (points == 1 && to != from)
    throw InvalidInput("points", "1", "a single lambda needs lambda_to = lambda_from");
  if (points >= 2 && to == from)
    throw InvalidInput("points", std::to_string(points),
                       "must be 1 when lambda_from = lambda_to (one lambda)");
  std::vector<double> lambdas(points);
  lambdas[0] = from;
  if (points >= 2) {
    // In long double, rounded once: with decimal ends read by strtold, the
    // grid lands on the doubles nearest its decimal values (0.8, not the
    // 0.7999999999999999 of 4 * (1.2 / 6) in double).
    const long double span = to_exact - from_exact;
    const long double intervals = static_cast<long double>(points - 1);
    for (std::size_t i = 1; i + 1 < points; ++i)
      lambdas[i] = static_cast<double>(from_exact + span * static_cast<long double>(i) / intervals);
    lambdas[points - 1] = to;
    for (std::size_t i = 1; i < points; ++i) {
      if (!(lambdas[i] > lambdas[i - 1]))
        throw InvalidInput("points", std::to_string(points),
                           "the grid from " + text(from) + " to " + text(to) +
                               " would repeat lambda values (its step is below the spacing of "
                               "doubles)");
    }
  }
  return lambdas;
}

std::vector<SweepPoint> sweep(const std::vector<double>& lambdas, const SweepOptions& options,
                              const SweepProgress& progress) {
  options.validate();
  double largest = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (double lambda : lambdas) {
    require_lambda("lambda", lambda);
    largest = std::max(largest, lambda);
    smallest = std::min(smallest, lambda);
  }
  // The engine's own checks (motion within the range of double) grow with
  // R: the largest lambda is the hardest case for the seed's model; the
  // smallest is checked as well for the general model. Raised here, before
  // any thread.
  if (!lambdas.empty()) {
    const double end = sweep_window(options.periods, options.base).end;
    for (const double lambda : {largest, smallest}) {
      const ExactEngine probe(sweep_model(lambda, options), end);
      (void)probe;
    }
  }

  std::vector<SweepPoint> points(lambdas.size());
  // A point costs about 1 us per period.
  detail::parallel_for(
      lambdas.size(), options.threads,
      [&](std::size_t i) { points[i] = sweep_point(lambdas[i], options); }, progress);
  return points;
}

}  // namespace frictionref
