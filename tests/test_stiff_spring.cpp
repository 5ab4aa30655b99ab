// The stiff-spring (penalty friction) simulator (stiff_spring.hpp), checked
// against what does not come from it: closed forms (the forced undamped
// oscillator, the ringing amplitude of a finite friction spring, the start-up
// impulse), the exact event-driven solution of the library, and the energy
// balance. The measured numbers quoted in docs/stiff-spring.md are printed by
// these tests (grep the test log for "measured:").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "solution_checks.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/stiff_spring.hpp"

namespace frictionref {
namespace {

using testing::seed_model;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using testing::expect_invalid;


// The stability limit, written out here: 2 / sqrt(kf / m).
double limit_of(const Model& model, double kf) { return 2 / std::sqrt(kf / model.mass); }

// Options that archive every time step, with dt = fraction of the limit.
StiffSpringOptions every_step(const Model& model, double kf, double fraction) {
  StiffSpringOptions options;
  options.kf = kf;
  options.dt = fraction * limit_of(model, kf);
  options.output_dt = options.dt;
  return options;
}

std::vector<StiffSample> all_samples(const Model& model, double t_end,
                                     const StiffSpringOptions& options) {
  StiffSpringSimulator simulator(model, t_end, options);
  std::vector<StiffSample> samples;
  StiffSample sample;
  while (simulator.next(sample)) samples.push_back(sample);
  EXPECT_FALSE(simulator.next(sample));  // finished stays finished
  return samples;
}

// Random models over three decades of m, B, w, with lambda in [0, 1.3), any
// v0 up to the forcing's own velocity scale, and kf / (m w^2) in [1e4, 1e7].
struct RandomCase {
  Model model;
  double kf = 0;
  double t_end = 0;
};

std::vector<RandomCase> random_cases(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto decade = [&](double low, double high) {
    return std::pow(10.0, low + (high - low) * unit(rng));
  };
  std::vector<RandomCase> cases;
  for (int i = 0; i < count; ++i) {
    RandomCase c;
    Model& m = c.model;
    m.mass = decade(-1, 1);
    m.amplitude = decade(-1, 1);
    m.omega = decade(-1, 1);
    m.friction = m.amplitude * 1.3 * unit(rng);
    m.v0 = (2 * unit(rng) - 1) * m.amplitude / (m.mass * m.omega);
    m.x0 = 2 * unit(rng) - 1;
    m.t0 = 6 * unit(rng) - 3;
    c.kf = decade(4, 7) * m.mass * m.omega * m.omega;
    c.t_end = m.t0 + 15 / m.omega;  // about 2.4 forcing periods
    cases.push_back(c);
  }
  return cases;
}

// ---------------------------------------------------------------------------
// Options

TEST(StiffSpringOptions, DefaultsValidate) {
  const StiffSpringOptions options;
  EXPECT_EQ(options.kf, 1e7);
  EXPECT_EQ(options.dt, 0.0);
  EXPECT_EQ(options.output_dt, 0.01);
  EXPECT_NO_THROW(options.validate(seed_model(0.3)));
}

TEST(StiffSpringOptions, StabilityLimitIsTwoOverTheSpringFrequency) {
  Model model = seed_model(0.3);
  model.mass = 4;
  StiffSpringOptions options;
  options.kf = 1e6;
  EXPECT_DOUBLE_EQ(options.stability_limit(model), 2 * std::sqrt(4 / 1e6));  // 0.004
}

// The automatic step is at most 0.1 of the limit, divides output_dt, and is
// the largest step that does both.
TEST(StiffSpringOptions, AutomaticStepDividesTheOutputStep) {
  for (const double kf : {1e2, 1e4, 1e7, 3.3e9}) {
    for (const double output_dt : {0.01, 0.25, 1e-3}) {
      Model model = seed_model(0.7);
      StiffSpringOptions options;
      options.kf = kf;
      options.output_dt = output_dt;
      SCOPED_TRACE("kf " + std::to_string(kf) + " output_dt " + std::to_string(output_dt));
      ASSERT_NO_THROW(options.validate(model));
      const double wanted = 0.1 * limit_of(model, kf);
      const double step = options.step(model);
      const std::uint64_t n = options.steps_per_output(model);
      EXPECT_LE(step, wanted * (1 + 1e-12));
      EXPECT_NEAR(static_cast<double>(n) * step, output_dt, 1e-12 * output_dt);
      if (n > 1) {
        EXPECT_GT(output_dt / static_cast<double>(n - 1), wanted);
      }
      if (wanted >= output_dt) {
        EXPECT_EQ(step, output_dt);
      }
    }
  }
}

TEST(StiffSpringOptions, UserStepKeptWhenItDividesElseReduced) {
  const Model model = seed_model(0.7);
  StiffSpringOptions options;
  options.kf = 1e4;  // limit 0.02
  options.output_dt = 0.01;
  options.dt = 0.001;  // 0.01 / 0.001 is 10 up to rounding: kept exactly
  EXPECT_EQ(options.step(model), 0.001);
  EXPECT_EQ(options.steps_per_output(model), 10u);
  options.dt = 0.003;  // not a divisor: 0.01 / 4 = 0.0025
  EXPECT_EQ(options.steps_per_output(model), 4u);
  EXPECT_DOUBLE_EQ(options.step(model), 0.0025);
  options.dt = 0.01;  // dt = output_dt
  EXPECT_EQ(options.step(model), 0.01);
  EXPECT_EQ(options.steps_per_output(model), 1u);
}

TEST(StiffSpringOptions, RefusesBadValuesNamingTheField) {
  const Model model = seed_model(0.3);
  struct Bad {
    double kf, dt, output_dt;
    const char* parameter;
    const char* rule_part;
  };
  for (const Bad& bad : {
           Bad{kNaN, 0, 0.01, "kf", "finite"},
           Bad{kInf, 0, 0.01, "kf", "finite"},
           Bad{0, 0, 0.01, "kf", "> 0"},
           Bad{-1e7, 0, 0.01, "kf", "> 0"},
           Bad{1e7, kNaN, 0.01, "dt", "finite"},
           Bad{1e7, -kInf, 0.01, "dt", "finite"},
           Bad{1e7, -1e-5, 0.01, "dt", ">= 0"},
           Bad{1e7, 0, kNaN, "output_dt", "finite"},
           Bad{1e7, 0, 0, "output_dt", "> 0"},
           Bad{1e7, 0, -0.01, "output_dt", "> 0"},
           Bad{1e4, 0.005, 0.001, "output_dt", ">= dt"},
           Bad{1e7, 1e-9, 1e9, "output_dt", "2^53"},
           Bad{1e300, 0, 1e200, "kf", "2^53"},
       }) {
    StiffSpringOptions options;
    options.kf = bad.kf;
    options.dt = bad.dt;
    options.output_dt = bad.output_dt;
    const InvalidInput error = expect_invalid([&] { options.validate(model); });
    EXPECT_EQ(error.parameter(), bad.parameter) << error.what();
    EXPECT_NE(error.rule().find(bad.rule_part), std::string::npos) << error.what();
  }
}

// A step at or above 2 / sqrt(kf / m) is refused and the message gives the
// limit, so the user can pick a step without doing the arithmetic.
TEST(StiffSpringOptions, StepAboveTheStabilityLimitIsRefusedWithTheLimit) {
  Model model = seed_model(0.3);
  model.mass = 4;
  StiffSpringOptions options;
  options.kf = 1048576;  // 2^20: limit 2 sqrt(2^-18) = 2^-8 = 0.00390625, exactly
  options.output_dt = 0.1;
  for (const double dt : {0.00390625, 0.005, 0.05}) {
    options.dt = dt;
    const InvalidInput error = expect_invalid([&] { options.validate(model); });
    EXPECT_EQ(error.parameter(), "dt");
    EXPECT_NE(error.rule().find("stability limit"), std::string::npos) << error.what();
    EXPECT_NE(error.rule().find("= 0.00390625 "), std::string::npos) << error.what();
  }
  options.dt = 0.0039;
  EXPECT_NO_THROW(options.validate(model));
}

TEST(StiffSpringOptions, ValidatesTheModelFirst) {
  Model model = seed_model(0.3);
  model.mass = -1;
  const InvalidInput error = expect_invalid([&] { StiffSpringOptions().validate(model); });
  EXPECT_EQ(error.parameter(), "mass");
}

// ---------------------------------------------------------------------------
// The stream

TEST(StiffSpringSimulator, RefusesBadHorizonsAndSteps) {
  const Model model = seed_model(0.3);
  const StiffSpringOptions defaults;
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(model, kNaN, defaults); }).parameter(),
            "t_end");
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(model, 0, defaults); }).parameter(), "t_end");
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(model, -1, defaults); }).parameter(),
            "t_end");
  Model far = model;
  far.t0 = 1e20;
  StiffSpringOptions options;
  options.output_dt = 1;
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(far, 2e20, options); }).parameter(),
            "output_dt");
  far.t0 = 1e12;  // output_dt = 1 advances t, the automatic step 6e-5 does not
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(far, 2e12, options); }).parameter(), "kf");
  options.dt = 1e-4;
  EXPECT_EQ(expect_invalid([&] { StiffSpringSimulator(far, 2e12, options); }).parameter(), "dt");
}

// Rows at t0 + k output_dt (computed from k) below t_end - 1e-9 output_dt,
// then t_end: the `curve` grid rule, so rows line up with `curve` output.
TEST(StiffSpringSimulator, SampleTimesFollowTheCurveGrid) {
  struct Grid {
    double t0, t_end, output_dt;
  };
  for (const Grid grid : {Grid{0, 30, 0.01}, Grid{0, 1.005, 0.01}, Grid{-5, 5, 0.5},
                          Grid{0.1, 0.35, 0.1}, Grid{2, 2.0001, 0.01}}) {
    Model model = seed_model(0.7);
    model.t0 = grid.t0;
    StiffSpringOptions options;
    options.kf = 1e5;
    options.output_dt = grid.output_dt;
    const std::vector<StiffSample> samples = all_samples(model, grid.t_end, options);
    std::vector<double> expected;
    for (std::uint64_t k = 0;; ++k) {
      const double t = grid.t0 + static_cast<double>(k) * grid.output_dt;
      if (!(t < grid.t_end - 1e-9 * grid.output_dt)) break;
      expected.push_back(t);
    }
    expected.push_back(grid.t_end);
    ASSERT_EQ(samples.size(), expected.size()) << grid.t0 << " " << grid.t_end;
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(samples[i].t, expected[i]);
    EXPECT_EQ(StiffSpringSimulator(model, grid.t_end, options).total_samples(), expected.size());
  }
}

// The first sample is the initial state with the unloaded spring (z0 = x0).
TEST(StiffSpringSimulator, StartsFromTheInitialStateWithAnUnloadedSpring) {
  Model model = seed_model(0.7, -0.25);
  model.x0 = 1.5;
  model.t0 = 0.3;
  const std::vector<StiffSample> samples = all_samples(model, 1, StiffSpringOptions());
  EXPECT_EQ(samples.front().t, 0.3);
  EXPECT_EQ(samples.front().x, 1.5);
  EXPECT_EQ(samples.front().v, -0.25);
  EXPECT_EQ(samples.front().f, 0.0);
  EXPECT_EQ(samples.front().z, 1.5);
}

// The run does not depend on t_end: a shorter run is a prefix of a longer one,
// and its sample at t_end is the linear interpolation of the two step samples
// around t_end (taken here from a run that archives every step).
TEST(StiffSpringSimulator, EndSampleInterpolatesTheStepsAroundIt) {
  const Model model = seed_model(1.01, -1);
  StiffSpringOptions options;
  options.kf = 1e5;
  options.output_dt = 0.01;
  const double t_end = 0.123456789;
  const std::vector<StiffSample> short_run = all_samples(model, t_end, options);
  StiffSpringSimulator reference_simulator(model, t_end, options);
  const double dt = reference_simulator.step();

  StiffSpringOptions fine = options;
  fine.dt = dt;
  fine.output_dt = dt;
  ASSERT_EQ(fine.step(model), dt);
  const std::vector<StiffSample> steps = all_samples(model, 0.2, fine);
  const std::uint64_t n = options.steps_per_output(model);
  for (std::size_t k = 0; k + 1 < short_run.size(); ++k) {
    const StiffSample& a = short_run[k];
    const StiffSample& b = steps[k * n];
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.v, b.v);
    EXPECT_EQ(a.f, b.f);
  }
  const double s = (t_end - model.t0) / dt;
  const std::size_t lower = static_cast<std::size_t>(std::floor(s));
  const double fraction = s - std::floor(s);
  ASSERT_GT(fraction, 0.0);
  const StiffSample& lo = steps[lower];
  const StiffSample& hi = steps[lower + 1];
  const StiffSample& end = short_run.back();
  EXPECT_EQ(end.t, t_end);
  EXPECT_NEAR(end.x, lo.x + fraction * (hi.x - lo.x), 1e-15);
  EXPECT_NEAR(end.v, lo.v + fraction * (hi.v - lo.v), 1e-15);
  EXPECT_NEAR(end.z, lo.z + fraction * (hi.z - lo.z), 1e-15);
  EXPECT_LE(reference_simulator.total_steps(), lower + 2);
}

// ---------------------------------------------------------------------------
// (1) The friction force never exceeds R, and is the spring force -kf (x - z).

TEST(StiffSpringPhysics, FrictionForceNeverExceedsR) {
  std::vector<RandomCase> cases = random_cases(40, 20240607);
  for (const double lambda : {0.3, 0.7, 1.01}) {
    RandomCase seed;
    seed.model = seed_model(lambda, lambda > 1 ? -1 : 0);
    seed.kf = 1e7;
    seed.t_end = 30;
    cases.push_back(seed);
  }
  int slipping_cases = 0;
  for (const RandomCase& c : cases) {
    SCOPED_TRACE("lambda " + std::to_string(c.model.lambda()));
    StiffSpringOptions options;
    options.kf = c.kf;
    options.output_dt = (c.t_end - c.model.t0) / 20000;
    StiffSpringSimulator simulator(c.model, c.t_end, options);
    const double R = c.model.friction;
    double largest = 0;
    bool at_r = false;
    StiffSample s;
    while (simulator.next(s)) {
      largest = std::max(largest, std::fabs(s.f));
      at_r = at_r || std::fabs(s.f) == R;
      // f = -kf (x - z): x - z ~ R / kf is a difference of nearby numbers,
      // good to about eps |x| kf.
      const double rounding = 8 * 2.2e-16 * (std::fabs(s.x) + std::fabs(s.z)) * c.kf;
      ASSERT_NEAR(s.f, -c.kf * (s.x - s.z), rounding + 1e-12 * R) << "t = " << s.t;
    }
    EXPECT_LE(largest, R) << "|f| exceeded R";
    slipping_cases += at_r;
  }
  EXPECT_GT(slipping_cases, 30);  // the bound is reached, not just respected
}

// ---------------------------------------------------------------------------
// (2) Energy: work of F = dissipation at the slider + change of kinetic and
// spring energy.
//
// Quantities from samples at every step: W = trapezoid of F v dt; slider
// dissipation D = sum of |f| |dz|, the trapezoid of |f| over each slider move
// (= R |dz| whenever the slider moves at full load; it differs only in the
// start-up step, where the spring loads from 0 to R while the slider already
// moves); E = m v^2 / 2 + f^2 / (2 kf).
//
// The scheme conserves a modified energy, not E. For the mass ringing on the
// spring at w_f = sqrt(kf / m) the central-difference invariant weights the
// spring energy by 1 - (w_f dt / 2)^2, so E differs from it by at most
// (w_f dt)^2 / 4 / (1 - (w_f dt / 2)^2) of the oscillation energy, which is at
// most the energy that went through the system: |W| + D + m v0^2 / 2, plus
// the spring energy (R + B)^2 / kf that a stop can leave ringing. The residual
// W - D - (E - E0) stays within that bound (it does not drift) and is second
// order in dt. Measured over 1000 random models (kf / (m w^2) in [1e4, 1e7]):
// at most 0.0125 of the bound's (w_f dt)^2 (...) for dt <= 0.5 of the limit,
// 0.079 at 0.9 of the limit; for the seed cases at the automatic step, below
// 1.3e-9 of D (10.3's start-up step dominates). All printed below.
struct EnergyBalance {
  double work = 0;         // W
  double dissipation = 0;  // D
  double energy_change = 0;
  double worst_residual = 0;  // max over the run of |W - D - (E - E0)|
  double throughput() const { return std::fabs(work) + dissipation; }
};

EnergyBalance energy_balance(const Model& model, double t_end, const StiffSpringOptions& options) {
  StiffSpringSimulator simulator(model, t_end, options);
  EXPECT_EQ(simulator.steps_per_output(), 1u);
  EnergyBalance balance;
  StiffSample previous, s;
  simulator.next(previous);
  const auto energy = [&](const StiffSample& q) {
    return 0.5 * model.mass * q.v * q.v + q.f * q.f / (2 * options.kf);
  };
  const double e0 = energy(previous);
  while (simulator.next(s)) {
    const double h = s.t - previous.t;
    balance.work += 0.5 * h * (model.force(previous.t) * previous.v + model.force(s.t) * s.v);
    balance.dissipation +=
        0.5 * (std::fabs(previous.f) + std::fabs(s.f)) * std::fabs(s.z - previous.z);
    balance.energy_change = energy(s) - e0;
    balance.worst_residual =
        std::max(balance.worst_residual,
                 std::fabs(balance.work - balance.dissipation - balance.energy_change));
    previous = s;
  }
  return balance;
}

TEST(StiffSpringPhysics, EnergyBalanceOfTheSeedCases) {
  for (const double lambda : {0.3, 0.7, 1.01}) {
    const Model model = seed_model(lambda, lambda > 1 ? -1 : 0);
    const EnergyBalance b = energy_balance(model, 30, every_step(model, 1e7, 0.1));
    const double relative = b.worst_residual / b.dissipation;
    std::printf(
        "measured: energy lambda=%g kf=1e7 dt=0.1 limit: W=%.9g D=%.9g dE=%.9g "
        "worst residual %.3g (%.3g of D)\n",
        lambda, b.work, b.dissipation, b.energy_change, b.worst_residual, relative);
    EXPECT_LT(relative, 5e-9);
    // Without friction work the books do not balance: D is not small.
    EXPECT_GT(b.dissipation, 0.3);
  }
}

TEST(StiffSpringPhysics, EnergyBalanceOfRandomModels) {
  double worst_ratio = 0;  // residual / ((w_f dt)^2 (...)), for the doc
  for (const RandomCase& c : random_cases(40, 77)) {
    const Model& m = c.model;
    for (const double fraction : {0.1, 0.5, 0.9}) {
      const EnergyBalance b = energy_balance(m, c.t_end, every_step(m, c.kf, fraction));
      const double wdt = 2 * fraction;  // w_f dt
      const double energy = b.throughput() + 0.5 * m.mass * m.v0 * m.v0 +
                            (m.friction + m.amplitude) * (m.friction + m.amplitude) / c.kf;
      const double bound = wdt * wdt / 4 / (1 - wdt * wdt / 4) * energy;
      if (fraction <= 0.5)
        worst_ratio = std::max(worst_ratio, b.worst_residual / (wdt * wdt * energy));
      EXPECT_LE(b.worst_residual, bound)
          << "lambda " << m.lambda() << " kf " << c.kf << " fraction " << fraction;
    }
  }
  std::printf(
      "measured: energy residual / ((w_f dt)^2 (|W| + D + m v0^2/2 + (R+B)^2/kf)) <= %.3g "
      "for dt <= 0.5 limit (bound: 1/4 / (1 - (w_f dt)^2/4))\n",
      worst_ratio);
}

// The residual is a discretization defect: second order in dt.
TEST(StiffSpringPhysics, EnergyResidualIsSecondOrderInTheStep) {
  const Model model = seed_model(1.01, -1);
  const double coarse = energy_balance(model, 10, every_step(model, 1e4, 0.3)).worst_residual;
  const double fine = energy_balance(model, 10, every_step(model, 1e4, 0.1)).worst_residual;
  std::printf("measured: energy residual 10.3 kf=1e4: %.3g at 0.3 limit, %.3g at 0.1 limit\n",
              coarse, fine);
  EXPECT_GT(coarse / fine, 9 * 0.8);
  EXPECT_LT(coarse / fine, 9 * 1.25);
}

// ---------------------------------------------------------------------------
// (4) R huge: the slider never moves and the mass is a forced undamped
// oscillator on the spring, y = x - x0, m y'' + kf y = B sin(w t), y(t0) = 0,
// y'(t0) = v0:
//   y = P sin(w t) + C cos(W s) + D sin(W s),  s = t - t0,  W^2 = kf / m,
//   P = (B / m) / (W^2 - w^2),  C = -P sin(w t0),  D = (v0 - P w cos(w t0)) / W.
struct Oscillator {
  double P, C, D, W, w, t0;
  double y(double t) const {
    return P * std::sin(w * t) + C * std::cos(W * (t - t0)) + D * std::sin(W * (t - t0));
  }
  double v(double t) const {
    return P * w * std::cos(w * t) - C * W * std::sin(W * (t - t0)) +
           D * W * std::cos(W * (t - t0));
  }
};

Oscillator oscillator(const Model& m, double kf) {
  Oscillator o;
  o.W = std::sqrt(kf / m.mass);
  o.w = m.omega;
  o.t0 = m.t0;
  o.P = (m.amplitude / m.mass) / (o.W * o.W - o.w * o.w);
  o.C = -o.P * std::sin(o.w * m.t0);
  o.D = (m.v0 - o.P * o.w * std::cos(o.w * m.t0)) / o.W;
  return o;
}

struct SpringErrors {
  double x = 0, v = 0, f = 0;
};

SpringErrors spring_errors(const Model& model, double kf, double fraction, double t_end) {
  StiffSpringOptions options = every_step(model, kf, fraction);
  const Oscillator exact = oscillator(model, kf);
  StiffSpringSimulator simulator(model, t_end, options);
  SpringErrors e;
  StiffSample s;
  while (simulator.next(s)) {
    e.x = std::max(e.x, std::fabs(s.x - model.x0 - exact.y(s.t)));
    e.v = std::max(e.v, std::fabs(s.v - exact.v(s.t)));
    e.f = std::max(e.f, std::fabs(s.f + kf * exact.y(s.t)));
    EXPECT_NEAR(s.z, model.x0, 1e-13) << "the slider moved";
    EXPECT_LT(std::fabs(s.f), 1e3);
  }
  return e;
}

TEST(StiffSpringPhysics, PureSpringIsTheForcedOscillatorToSecondOrder) {
  Model model;
  model.mass = 2;
  model.amplitude = 3;
  model.omega = 1.5;
  model.friction = 1e300;  // never slips
  model.x0 = 0.75;
  model.v0 = -0.5;
  model.t0 = 0.25;
  const double kf = 200;  // W = 10 rad per time unit, limit 0.2
  const double t_end = 10.25;
  std::vector<double> errors;
  for (const double fraction : {0.04, 0.02, 0.01}) {
    const SpringErrors e = spring_errors(model, kf, fraction, t_end);
    std::printf("measured: pure spring dt = %.2f limit: max |dx| %.3g |dv| %.3g |df| %.3g\n",
                fraction, e.x, e.v, e.f);
    errors.push_back(e.v);
    // Phase error of central differences is W t (W dt)^2 / 24 (W dt = 2 fraction):
    // 100 rad * (2 fraction)^2 / 24 times the velocity amplitude (~ |D| W ~ 0.5).
    EXPECT_LT(e.v, 100 * (2 * fraction) * (2 * fraction) / 24 * 0.6 * 1.5);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("measured: pure spring velocity error order in dt %.3f\n", order);
    EXPECT_GT(order, 1.9);
    EXPECT_LT(order, 2.1);
  }
}

// ---------------------------------------------------------------------------
// (3) Convergence to the exact solution (frictionref's event-driven engine)
// as kf grows, with the automatic step (0.1 of the limit, so dt ~ kf^-1/2).
//
// Measured (every step compared, kf = 1e4 ... 1e9): the max velocity error is
// c / sqrt(kf m), order 0.500 +- 0.005 in kf, and c has a closed form:
// - at a stop at ts the spring still carries R while the force is F(ts):
//   the mass rings about -F(ts) with force amplitude R + |F(ts)| for the first
//   half period, so c = R + |F(ts)| (0.778 for 10.2, 1.681 for 10.3);
// - at a reversal (|F| > R) the spring reloads from -R to +R while the mass
//   moves: c = 2 sqrt(R |F|) - (|F| - R) acos((|F| - R) / (|F| + R)),
//   0.4006 at the first reversal of 10.1.
struct VelocityError {
  double max = 0;
  double at = 0;
};

// Max |v_stiff - v_exact| at every time step in [from, to] (and its time).
VelocityError velocity_error(const Model& model, double t_end, double kf, double from = -kInf,
                             double to = kInf) {
  StiffSpringOptions options;
  options.kf = kf;
  options.output_dt = StiffSpringOptions::auto_step_fraction * limit_of(model, kf);
  StiffSpringSimulator simulator(model, t_end, options);
  EXPECT_EQ(simulator.steps_per_output(), 1u);
  GridOptions grid;
  grid.t_end = t_end;
  grid.dt = options.output_dt;
  UniformSampler exact(model, grid);
  VelocityError error;
  StiffSample s;
  State e;
  while (simulator.next(s)) {
    EXPECT_TRUE(exact.next(e));
    EXPECT_EQ(s.t, e.t);
    if (s.t < from || s.t > to) continue;
    const double d = std::fabs(s.v - e.v);
    if (d > error.max) error = {d, s.t};
  }
  return error;
}

// The first phase boundary of the exact solution after `after` of the given kind.
Phase first_phase(const Model& model, double t_end, PhaseKind kind, double after) {
  for (const Phase& phase : solve(model, t_end).phases) {
    if (phase.kind == kind && phase.t_begin > after) return phase;
  }
  ADD_FAILURE() << "no such phase";
  return {};
}

void expect_half_order_in_kf(const Model& model, double t_end, double expected_c,
                             double from = -kInf, double to = kInf) {
  double previous = 0;
  for (const double kf : {1e4, 1e6, 1e8}) {
    const VelocityError e = velocity_error(model, t_end, kf, from, to);
    const double c = e.max * std::sqrt(kf * model.mass);
    std::printf(
        "measured: lambda=%g kf=%g max |dv| %.4g at t=%.4f, times sqrt(kf m) %.4f "
        "(theory %.4f)",
        model.lambda(), kf, e.max, e.at, c, expected_c);
    if (previous > 0) {
      const double order = std::log10(previous / e.max) / 2;
      std::printf(", drop %.2fx per 100x kf, order %.3f", previous / e.max, order);
      EXPECT_GT(previous / e.max, 9.0);   // order >= 0.477
      EXPECT_LT(previous / e.max, 11.1);  // order <= 0.523
    }
    std::printf("\n");
    EXPECT_NEAR(c / expected_c, 1, 0.03);
    previous = e.max;
  }
}

TEST(StiffSpringConvergence, DeadBandsErrorIsTheRingingAfterAStop) {
  const Model model = seed_model(0.7);
  const double ts = first_phase(model, 10, PhaseKind::stick, 1).t_begin;  // 3.2198
  expect_half_order_in_kf(model, 10, model.friction + std::fabs(model.force(ts)));
}

TEST(StiffSpringConvergence, StopsForGoodErrorIsTheRingingAfterTheStop) {
  const Model model = seed_model(1.01, -1);
  const double ts = first_phase(model, 3, PhaseKind::stick, 0).t_begin;  // 0.7347
  expect_half_order_in_kf(model, 3, model.friction + std::fabs(model.force(ts)));
}

TEST(StiffSpringConvergence, ContinuousErrorIsTheSpringReloadAtAReversal) {
  const Model model = seed_model(0.3);
  const Phase phase = first_phase(model, 10, PhaseKind::slip_backward, 0);  // at 4.426
  const double R = model.friction, F = std::fabs(model.force(phase.t_begin));
  const double c = 2 * std::sqrt(R * F) - (F - R) * std::acos((F - R) / (F + R));
  expect_half_order_in_kf(model, 10, c, phase.t_begin, phase.t_begin + 0.2);
}

// In dt at fixed kf: the start-up with an unloaded spring (z0 = x0) misses
// the friction impulse R dt / 2 of the first half step, so with v0 != 0 the
// velocity is off by -sign(v0) R dt / (2 m) until the first stop: first order
// in dt, and the whole dt dependence of the slip in case 10.3.
TEST(StiffSpringConvergence, StartUpCostsHalfAStepOfFriction) {
  const Model model = seed_model(1.01, -1);
  double previous = 0;
  for (const double fraction : {0.8, 0.4, 0.2, 0.1}) {
    StiffSpringOptions options;
    options.kf = 1e7;
    options.output_dt = 0.01;
    options.dt = fraction * limit_of(model, options.kf);
    const std::vector<StiffSample> samples = all_samples(model, 0.6, options);
    std::vector<double> times;
    for (const StiffSample& s : samples) times.push_back(s.t);
    const std::vector<State> exact = sample_at(model, times);
    const double dt = StiffSpringSimulator(model, 0.6, options).step();
    const double expected = -model.friction * dt / (2 * model.mass);  // v0 < 0
    double worst = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (samples[i].t < 0.1) continue;
      const double error = samples[i].v - exact[i].v;
      EXPECT_NEAR(error, expected, 0.02 * std::fabs(expected)) << "t = " << samples[i].t;
      worst = std::max(worst, std::fabs(error));
    }
    if (previous > 0) {
      const double order = std::log2(previous / worst);
      std::printf(
          "measured: 10.3 slip velocity error %.4g at dt=%.4g (-R dt/2m = %.4g), "
          "order in dt %.3f\n",
          worst, dt, expected, order);
      EXPECT_NEAR(order, 1, 0.05);
    }
    previous = worst;
  }
}

// ---------------------------------------------------------------------------
// The seed's figure 10.3 (lambda = 1.01, v0 = -1, kf = 1e7): after the stop
// the velocity is small but not zero, because the mass rings on the finite
// spring at sqrt(kf / m). The ring is clipped whenever the spring force
// reaches R, so its force amplitude is at most min over [ts, t] of
// R - |F|, i.e. |v| <= (R - |F|) / sqrt(kf m); once |F| has peaked at B the
// amplitude is R - B = 0.01 for good: |v| = 0.01 / sqrt(1e7) = 3.16e-6.
TEST(StiffSpringSeed, Case103RingsAfterTheStop) {
  const Model model = seed_model(1.01, -1);
  const double kf = 1e7;
  const double ts = first_phase(model, 30, PhaseKind::stick, 0).t_begin;
  const double scale = 1 / std::sqrt(kf * model.mass);
  StiffSpringOptions options;
  options.kf = kf;
  options.output_dt = 0.1 * limit_of(model, kf);  // every step
  StiffSpringSimulator simulator(model, 30, options);
  StiffSample s;
  double margin = kInf;  // min of R - |F| since the stop
  double worst_ratio = 0, late = 0, early = 0;
  while (simulator.next(s)) {
    if (s.t < ts) continue;
    margin = std::min(margin, model.friction - std::fabs(model.force(s.t)));
    if (s.t < ts + 0.05) continue;  // the first clipped half rings
    worst_ratio = std::max(worst_ratio, std::fabs(s.v) / (margin * scale));
    if (s.t >= 20) late = std::max(late, std::fabs(s.v));
    if (s.t >= 1 && s.t < 1.5) early = std::max(early, std::fabs(s.v));
  }
  std::printf(
      "measured: 10.3 kf=1e7: max |v| on [1, 1.5] %.4g, on [20, 30] %.4g "
      "(0.01/sqrt(kf m) = %.4g); max |v| sqrt(kf m) / (R - |F|) %.4f\n",
      early, late, 0.01 * scale, worst_ratio);
  EXPECT_LE(worst_ratio, 1.05);
  EXPECT_GT(late, 0.9 * 0.01 * scale);  // nonzero: the finite spring rings
  EXPECT_LT(late, 1.1 * 0.01 * scale);
  EXPECT_GT(early, 5 * late);  // larger before |F| has peaked
}

// The seed's own archive step (0.01) sees the same ringing.
TEST(StiffSpringSeed, Case103AtTheSeedArchiveStep) {
  const Model model = seed_model(1.01, -1);
  double late = 0;
  for (const StiffSample& s : all_samples(model, 30, StiffSpringOptions())) {
    if (s.t >= 20) late = std::max(late, std::fabs(s.v));
  }
  std::printf("measured: 10.3 defaults (kf=1e7, output 0.01): max |v| on [20, 30] %.4g\n", late);
  EXPECT_GT(late, 1e-6);
  EXPECT_LT(late, 1e-5);
}

}  // namespace
}  // namespace frictionref
