// Newmark's sliding-block analysis (newmark.hpp): SLAMMER's sign convention
// on records solved by hand, the permanent displacement after the record,
// the peak relative velocity inside a slide, invariance under linear
// resampling, SLAMMER's algorithm converging to the exact answer as the
// record is resampled, the batch's order and determinism, and the refusals.
#include <gtest/gtest.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/newmark.hpp"

namespace frictionref {
namespace {

// The call must throw InvalidInput naming `parameter`, its rule containing `rule`.
template <class F>
void expect_refused(F&& call, const std::string& parameter, const std::string& rule) {
  const InvalidInput error = testing::expect_invalid(std::forward<F>(call));
  EXPECT_EQ(error.parameter(), parameter);
  EXPECT_NE(error.rule().find(rule), std::string::npos) << error.rule();
}

const std::string kSource = FRICTIONREF_SOURCE_DIR;

// A record in units where g = 1, so that KY is an acceleration in those units.
GroundMotion unit_record(std::vector<double> t, std::vector<double> a) {
  GroundMotion r;
  r.t = std::move(t);
  r.a = std::move(a);
  r.file = "hand-made";
  r.npts = r.t.size();
  r.gravity = 1;
  return r;
}

GroundMotion synthetic(const std::string& name) {
  return read_ground_motion(kSource + "/data/records/synthetic/" + name);
}

// The record linear between its samples, sampled `factor` times as finely
// (the same piecewise-linear function, up to the rounding of the new values).
GroundMotion resampled(const GroundMotion& r, int factor) {
  GroundMotion fine = r;
  fine.t.clear();
  fine.a.clear();
  for (std::size_t i = 0; i + 1 < r.t.size(); ++i) {
    for (int j = 0; j < factor; ++j) {
      const double s = static_cast<double>(j) / factor;
      fine.t.push_back(r.dt ? (static_cast<double>(i * factor + j) * *r.dt / factor) + r.t.front()
                            : r.t[i] + s * (r.t[i + 1] - r.t[i]));
      fine.a.push_back(r.a[i] + s * (r.a[i + 1] - r.a[i]));
    }
  }
  fine.t.push_back(r.t.back());
  fine.a.push_back(r.a.back());
  if (r.dt) fine.dt = *r.dt / factor;
  fine.npts = fine.t.size();
  return fine;
}

// a = 3 (in g = 1 units) for 0 <= t <= 2, then 0; KY = 1. Normal polarity,
// downslope: x'' = 3 - 1 = 2 until t = 2 (v = 4, x = 4), then x'' = -1: at
// rest at t = 6, x = 4 + 16 - 8 = 12 = (A - K) A T^2 / (2 K).
TEST(Newmark, ConstantPulseSlidesDownslopeInTheNormalPolarity) {
  const GroundMotion r = unit_record({0, 2}, {3, 3});
  const NewmarkResult n = newmark_analysis(r, 1, true, Polarity::normal, NewmarkMethod::exact);
  EXPECT_EQ(n.displacement_at_record_end, 4.0);
  ASSERT_TRUE(n.permanent_displacement);
  EXPECT_EQ(*n.permanent_displacement, 12.0);
  EXPECT_EQ(n.slip_episodes, 1u);
  EXPECT_EQ(n.max_relative_velocity, 4.0);
  EXPECT_EQ(n.record, "hand-made");
  EXPECT_EQ(n.yield_accel_g, 1.0);
  EXPECT_EQ(n.polarity, Polarity::normal);
  EXPECT_EQ(n.method, NewmarkMethod::exact);

  // Inverse: the ground pushes the block upslope, which one-way forbids...
  const NewmarkResult up = newmark_analysis(r, 1, true, Polarity::inverse, NewmarkMethod::exact);
  EXPECT_EQ(up.displacement_at_record_end, 0.0);
  ASSERT_TRUE(up.permanent_displacement);
  EXPECT_EQ(*up.permanent_displacement, 0.0);
  EXPECT_EQ(up.slip_episodes, 0u);
  EXPECT_EQ(up.max_relative_velocity, 0.0);
  // ... and two-way allows: the mirror image.
  const NewmarkResult both = newmark_analysis(r, 1, false, Polarity::inverse, NewmarkMethod::exact);
  EXPECT_EQ(both.displacement_at_record_end, -4.0);
  ASSERT_TRUE(both.permanent_displacement);
  EXPECT_EQ(*both.permanent_displacement, -12.0);
  EXPECT_EQ(both.max_relative_velocity, 4.0);
}

// a rises from 0 to 4 over [0, 1] and falls back to 0 over [1, 2]; KY = 1.
// The slide starts at t = 1/4 (v = 2 (t - 1/4)^2 up to t = 1: v = 9/8,
// x = 9/32); then v = 9/8 + 7 (t - 1) - 2 (t^2 - 1), largest where a = KY,
// t = 7/4: v = 9/4 = (A - K)^2 / A; at t = 2, v = 17/8 and x = 9/32 + 47/24 =
// 215/96; then x'' = -1 and the block stops 289/128 further on:
// 215/96 + 289/128 = 1727/384.
TEST(Newmark, PeakVelocityInsideASlideAndThePermanentDisplacement) {
  const GroundMotion r = unit_record({0, 1, 2}, {0, 4, 0});
  const NewmarkResult n = newmark_analysis(r, 1, true, Polarity::normal, NewmarkMethod::exact);
  EXPECT_NEAR(n.max_relative_velocity, 9.0 / 4, 4 * 0x1p-52 * 2.25);
  EXPECT_NEAR(n.displacement_at_record_end, 215.0 / 96, 4 * 0x1p-52 * 2.24);
  ASSERT_TRUE(n.permanent_displacement);
  EXPECT_NEAR(*n.permanent_displacement, 1727.0 / 384, 4 * 0x1p-52 * 4.5);
  EXPECT_EQ(n.slip_episodes, 1u);
}

// KY = 0 two-way: the block keeps the speed it has when the ground stops,
// so it never comes to rest: no permanent displacement.
TEST(Newmark, NoPermanentDisplacementWithoutFriction) {
  const GroundMotion r = unit_record({0, 2}, {3, 3});
  const NewmarkResult n = newmark_analysis(r, 0, false, Polarity::normal, NewmarkMethod::exact);
  EXPECT_EQ(n.displacement_at_record_end, 6.0);
  EXPECT_FALSE(n.permanent_displacement);
}

// The record is linear between its samples: resampling it linearly ten
// times as finely describes the same ground motion, and the exact answer
// must not move beyond the rounding of the new samples. (SLAMMER's answer
// moves: see SlammerConvergesToTheExactAnswer.)
TEST(Newmark, PermanentDisplacementInvariantUnderLinearResampling) {
  for (const char* name : {"pulse-train.AT2", "noise-burst.AT2", "nonuniform.csv"}) {
    const GroundMotion coarse = synthetic(name);
    const GroundMotion fine = resampled(coarse, 10);
    for (const bool one_way : {true, false}) {
      for (const Polarity polarity : {Polarity::normal, Polarity::inverse}) {
        for (const double ky : {0.05, 0.1, 0.2}) {
          SCOPED_TRACE(std::string(name) + " ky " + std::to_string(ky) +
                       (one_way ? " one-way " : " two-way ") + std::string(to_string(polarity)));
          const NewmarkResult a =
              newmark_analysis(coarse, ky, one_way, polarity, NewmarkMethod::exact);
          const NewmarkResult b =
              newmark_analysis(fine, ky, one_way, polarity, NewmarkMethod::exact);
          ASSERT_TRUE(a.permanent_displacement && b.permanent_displacement);
          const double scale = std::max(std::fabs(*a.permanent_displacement), 1e-3);
          EXPECT_NEAR(*b.permanent_displacement, *a.permanent_displacement, 1e-12 * scale);
          EXPECT_NEAR(b.max_relative_velocity, a.max_relative_velocity,
                      1e-12 * std::max(a.max_relative_velocity, 1e-3));
        }
      }
    }
  }
}

// SLAMMER integrates at the record's step with the trapezoidal rule: its
// error against the exact answer of the same (linear) record shrinks as the
// record is resampled more finely. One-way, about as dt^2 (at least 3 times
// smaller per 4 times finer); two-way only about as dt, and irregularly: at
// a reversal SLAMMER holds the block for a step (v = 0) before it slides
// back (at least 4 times smaller per 16 times finer). Measured on
// noise-burst.AT2, KY = 0.1: docs/validation.md.
TEST(Newmark, SlammerConvergesToTheExactAnswer) {
  const GroundMotion coarse = synthetic("noise-burst.AT2");
  for (const bool one_way : {true, false}) {
    const std::vector<int> factors =
        one_way ? std::vector<int>{1, 4, 16, 64} : std::vector<int>{1, 16, 256};
    const double reduction = one_way ? 3 : 4;
    for (const Polarity polarity : {Polarity::normal, Polarity::inverse}) {
      SCOPED_TRACE(std::string(one_way ? "one-way " : "two-way ") +
                   std::string(to_string(polarity)));
      const NewmarkResult exact =
          newmark_analysis(coarse, 0.1, one_way, polarity, NewmarkMethod::exact);
      double previous = 0;
      for (const int factor : factors) {
        const GroundMotion r = resampled(coarse, factor);
        const double slammer = newmark_analysis(r, 0.1, one_way, polarity, NewmarkMethod::slammer)
                                   .displacement_at_record_end;
        const double error = std::fabs(slammer - exact.displacement_at_record_end);
        if (factor > 1) {
          EXPECT_LT(error, previous / reduction) << "factor " << factor;
        }
        previous = error;
      }
      EXPECT_LT(previous, 1e-3 * std::fabs(exact.displacement_at_record_end));
    }
  }
}

// One cycle of a_g = A sin(w t) (then still), one-way, normal polarity: the
// closed form of the harmonic base motion (Conte & Dente 1989 give it for a
// harmonic excitation; derived here, theory.md 9). With K = KY g <= A the
// block slides from theta1 = asin(K / A), where a_g reaches K, with
// v(theta) = [A (cos theta1 - cos theta) - K (theta - theta1)] / w until v = 0
// at theta2 in (pi - theta1, 2 pi) (v > 0 at pi - theta1, v < 0 at 2 pi), and
//   D = [A cos theta1 (theta2 - theta1) - A (sin theta2 - sin theta1)
//        - K (theta2 - theta1)^2 / 2] / w^2.
// The exact engine solves the record linear between samples: sampled N times
// per period it converges to D as N^-2 (the interpolant differs from the
// sine by O(h^2)); so does SLAMMER, from further away.
TEST(Newmark, OneSineCycleConvergesToTheClosedForm) {
  const double a = 1, w = 2 * M_PI;  // g = 1 units, period 1 s
  for (const double k : {0.1, 0.3, 0.6}) {
    const double theta1 = std::asin(k / a);
    const auto v = [&](double theta) {
      return a * (std::cos(theta1) - std::cos(theta)) - k * (theta - theta1);
    };
    boost::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve(
        v, M_PI - theta1, 2 * M_PI, boost::math::tools::eps_tolerance<double>(52), iterations);
    const double theta2 = 0.5 * (bracket.first + bracket.second);
    const double d = (a * std::cos(theta1) * (theta2 - theta1) -
                      a * (std::sin(theta2) - std::sin(theta1)) -
                      k * (theta2 - theta1) * (theta2 - theta1) / 2) /
                     (w * w);
    double previous = 0;
    for (const int n : {100, 200, 400, 800}) {
      std::vector<double> t, acc;
      for (int i = 0; i <= n; ++i) {
        t.push_back(static_cast<double>(i) / n);
        acc.push_back(a * std::sin(w * t.back()));
      }
      acc.back() = 0;  // sin(2 pi) to rounding
      GroundMotion r = unit_record(t, acc);
      r.dt = 1.0 / n;  // uniform, as SLAMMER needs
      const NewmarkResult exact =
          newmark_analysis(r, k, true, Polarity::normal, NewmarkMethod::exact);
      const NewmarkResult slammer =
          newmark_analysis(r, k, true, Polarity::normal, NewmarkMethod::slammer);
      ASSERT_TRUE(exact.permanent_displacement);
      EXPECT_EQ(exact.slip_episodes, 1u);
      const double error = std::fabs(*exact.permanent_displacement - d);
      std::printf(
          "measured: sine cycle K/A = %.1f, %d samples per period: closed form D = %.10g, "
          "exact %.10g (error %.2e), slammer %.10g (error %.2e)\n",
          k, n, d, *exact.permanent_displacement, error,
          slammer.displacement_at_record_end,
          std::fabs(slammer.displacement_at_record_end - d));
      EXPECT_LT(error, 15.0 / (n * n) * d) << n;  // measured: 4.2 to 13.7 / N^2
      if (previous > 0) {
        EXPECT_GT(previous / error, 3.5) << n;  // second order: 4 per halving
        EXPECT_LT(previous / error, 4.5) << n;
      }
      previous = error;
    }
  }
}

// Rows: records, then KY, then polarity; the same numbers on any number of
// threads, and those of the single analysis.
TEST(Newmark, BatchOrderAndDeterminism) {
  const std::vector<std::shared_ptr<const GroundMotion>> records{
      std::make_shared<const GroundMotion>(synthetic("pulse-train.AT2")),
      std::make_shared<const GroundMotion>(synthetic("noise-burst.AT2"))};
  NewmarkOptions options;
  options.yield_accels_g = {0.05, 0.1, 0.3};
  options.polarities = {Polarity::normal, Polarity::inverse};
  options.threads = 1;
  const std::vector<NewmarkResult> one = newmark_batch(records, options);
  options.threads = 2;
  std::size_t calls = 0;
  options.progress = [&calls](std::size_t, std::size_t) { ++calls; };
  const std::vector<NewmarkResult> two = newmark_batch(records, options);
  EXPECT_GE(calls, 1u);
  ASSERT_EQ(one.size(), 12u);
  ASSERT_EQ(two.size(), 12u);
  for (std::size_t i = 0; i < one.size(); ++i) {
    const std::size_t r = i / 6, k = i / 2 % 3, p = i % 2;
    const NewmarkResult single = newmark_analysis(*records[r], options.yield_accels_g[k], true,
                                                  options.polarities[p], NewmarkMethod::exact);
    for (const NewmarkResult* n : {&one[i], &two[i]}) {
      EXPECT_EQ(n->record, records[r]->file);
      EXPECT_EQ(n->yield_accel_g, options.yield_accels_g[k]);
      EXPECT_EQ(n->polarity, options.polarities[p]);
      EXPECT_EQ(n->displacement_at_record_end, single.displacement_at_record_end);
      EXPECT_EQ(n->permanent_displacement, single.permanent_displacement);
      EXPECT_EQ(n->slip_episodes, single.slip_episodes);
      EXPECT_EQ(n->max_relative_velocity, single.max_relative_velocity);
    }
  }
  // A larger KY never slides further (the same record, one-way).
  for (std::size_t i = 0; i + 2 < 6; ++i)
    EXPECT_GE(*one[i].permanent_displacement, *one[i + 2].permanent_displacement);
}

TEST(Newmark, Refusals) {
  const auto record = std::make_shared<const GroundMotion>(synthetic("pulse-train.AT2"));
  const auto table = std::make_shared<const GroundMotion>(synthetic("nonuniform.csv"));
  NewmarkOptions options;
  expect_refused([&] { newmark_batch({record}, options); }, "yield_accels_g", "at least one");
  options.yield_accels_g = {0.1, -0.1};
  expect_refused([&] { newmark_batch({record}, options); }, "yield_accel", ">= 0");
  options.yield_accels_g = {std::nan("")};
  expect_refused([&] { newmark_batch({record}, options); }, "yield_accel", "finite");
  options.yield_accels_g = {0};
  options.method = NewmarkMethod::slammer;
  expect_refused([&] { newmark_batch({record}, options); }, "yield_accel", "slammer");
  options.yield_accels_g = {0.1};
  expect_refused([&] { newmark_batch({table}, options); }, "record", "uniform step");
  options.polarities.clear();
  expect_refused([&] { newmark_batch({record}, options); }, "polarities", "at least one");
  EXPECT_EQ(newmark_method_from_string("slammer"), NewmarkMethod::slammer);
  EXPECT_EQ(newmark_method_from_string("exact"), NewmarkMethod::exact);
  EXPECT_FALSE(newmark_method_from_string("Exact"));
}

}  // namespace
}  // namespace frictionref
