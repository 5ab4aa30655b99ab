// The seed's dense fast path (double_double_slip.hpp, docs/theory.md 10)
// against an independent 50-digit evaluation of the closed form (Boost's own
// sin and cos on exact arguments), and against the long double path it
// short-cuts: the same rows, except where the long double path is not the
// correctly rounded one and the fast path is.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "comparison/exact_motion.hpp"
#include "dense_row_checks.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/sampling.hpp"
#include "laws/harmonic_coulomb/double_double_slip.hpp"
#include "laws/harmonic_coulomb/phase_formula.hpp"
#include "laws/linear_oscillator/phase_formula.hpp"
#include "random_models.hpp"

namespace frictionref {
namespace {

using testing::Fifty;
using testing::nearest;
using testing::same_row;

// The closed form of phase_law.hpp in 50 digits at exact w t and w t_a (with
// a constant force F0, s r - f0 in place of s r).
struct Exact {
  double x, v, a;
};
class ExactSlip {
 public:
  ExactSlip(const Model& m, const Phase& p)
      : w_(m.omega),
        start_(w_ * Fifty(p.t_begin)),
        cos_start_(cos(start_)),
        sin_start_(sin(start_)),
        b_(Fifty(m.amplitude) / (Fifty(m.mass) * w_)),
        sr_((slip_sign(p.kind) * Fifty(m.friction) - Fifty(m.force_offset)) / (Fifty(m.mass) * w_)),
        x_a_(p.x_begin),
        v_a_(p.v_begin) {}

  Exact at(double t) const {
    const Fifty tau = w_ * Fifty(t);
    const Fifty h = tau - start_;
    const Fifty sin_tau = sin(tau);
    const Fifty v = v_a_ + b_ * (cos_start_ - cos(tau)) - sr_ * h;
    const Fifty x =
        x_a_ + ((v_a_ + b_ * cos_start_) * h - b_ * (sin_tau - sin_start_) - sr_ * h * h / 2) / w_;
    const Fifty a = w_ * (b_ * sin_tau - sr_);
    return {nearest(x), nearest(v), nearest(a)};
  }

 private:
  Fifty w_, start_, cos_start_, sin_start_, b_, sr_, x_a_, v_a_;
};

bool available() { return detail::double_double_lanes_available(); }

// Each slip among the first six phases of `count` random models of the
// stream `seed` (random_models.hpp), with its formula; stops at the first
// fatal failure.
template <class Visit>
void for_each_random_slip(std::uint64_t seed, int count, Visit visit) {
  testing::ModelStream stream(seed);
  for (int i = 0; i < count && !::testing::Test::HasFatalFailure(); ++i) {
    const testing::RandomModel r = stream.next();
    ExactEngine engine(r.model, r.t_end);
    Phase phase;
    for (int k = 0; k < 6 && engine.next(phase); ++k) {
      if (phase.kind == PhaseKind::stick) continue;
      const detail::HarmonicCoulombFormula<double> formula(r.model, phase);
      visit(r, phase, formula);
    }
  }
}

TEST(DoubleDoubleSinCos, WithinItsBoundOfFiftyDigits) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  std::mt19937_64 random(20261127);
  const Fifty pi = boost::math::constants::pi<Fifty>();
  Fifty worst = 0;
  double bound = 0;
  for (int i = 0; i < 60000; ++i) {
    // Half of them next to the table's points j pi/256 (the longest reduced
    // arguments), the others anywhere within +-512.
    const double u = std::ldexp(static_cast<double>(random() >> 11), -53);
    const double hi =
        i % 2 ? (u - 0.5) * 1024
              : static_cast<double>(pi / 256 * Fifty(static_cast<int>(u * 131072) - 65536)) *
                    (1 + (u - 0.5) * 1e-12);
    const double lo = hi * std::ldexp(u - 0.5, -53);
    double out[5];
    detail::double_double_sin_cos(hi, lo, out);
    const Fifty y = Fifty(hi) + Fifty(lo);
    worst = std::max(worst, abs(Fifty(out[0]) + Fifty(out[1]) - sin(y)));
    worst = std::max(worst, abs(Fifty(out[2]) + Fifty(out[3]) - cos(y)));
    bound = std::max(bound, out[4]);
  }
  // 2^-76 plus 2^-94 per table step of the reduction (at most 2^15).
  EXPECT_GE(bound, std::ldexp(1.0, -76));
  EXPECT_LE(bound, std::ldexp(1.0, -76) + std::ldexp(1.0, -79));
  // The analysis gives 1.5e-24 for the reduced argument plus 2^-96 per step.
  EXPECT_LT(worst, Fifty(1.5e-24) + Fifty(std::ldexp(1.0, -81))) << static_cast<double>(worst);
  std::cout << "largest error of sin, cos: " << static_cast<double>(worst) << " (bound " << bound
            << ")\n";
}

// Random slips of random models: every answer the fast path gives is the
// correctly rounded value. Times are spread over the slip, and crowd towards
// its end (where v -> 0 and the bound is tested hardest: the terms cancel).
TEST(DoubleDoubleSlip, DecidedValuesAreCorrectlyRounded) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  std::mt19937_64 random(7);
  const auto unit = [&] { return std::ldexp(static_cast<double>(random() >> 11), -53); };
  std::uint64_t tried = 0, decided = 0;
  for_each_random_slip(11, 3000,
                       [&](const testing::RandomModel& r, const Phase& phase,
                           const detail::HarmonicCoulombFormula<double>& formula) {
                         for (const double t : testing::probe_times(phase, unit)) {
                           ++tried;
                           State fast;
                           if (!formula.fast_at(t, fast)) continue;
                           ++decided;
                           const Exact e = ExactSlip(r.model, phase).at(t);
                           ASSERT_EQ(fast.x, e.x) << testing::describe(r) << " t=" << t;
                           ASSERT_EQ(fast.v, e.v) << testing::describe(r) << " t=" << t;
                           ASSERT_EQ(fast.a, e.a) << testing::describe(r) << " t=" << t;
                         }
                       });
  std::cout << decided << " of " << tried << " states decided by the fast path\n";
  EXPECT_GT(tried, 10000u);
  EXPECT_GT(decided, tried / 2);
}

// A slip's rows at its own ends (a curve's event rows): x and v are the
// stored states, the acceleration the fast path's where it decides it (then
// the correctly rounded 50-digit value), the long double path's elsewhere.
TEST(DenseFastPath, EndRowsDecideTheAcceleration) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  testing::EndRowCounts counts;
  for_each_random_slip(13, 3000,
                       [&](const testing::RandomModel& r, const Phase& phase,
                           const detail::HarmonicCoulombFormula<double>& formula) {
                         testing::check_end_rows(
                             formula, phase,
                             [&](double t) { return ExactSlip(r.model, phase).at(t).a; },
                             [&] { return testing::describe(r); }, counts);
                       });
  testing::expect_end_rows_tested(counts);
}

// 10^5 random models, every slip sampled: the fast path with its fallback
// gives the long double path's rows, except where the long double row is not
// the correctly rounded one; there the fast row must be (50 digits).
TEST(DenseFastPath, SameRowsAsTheLongDoublePathOnRandomModels) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  std::uint64_t rows = 0, differing = 0, fast_closer = 0;
  // By decade of |w t| (below 1 rad, 1-10, ... up to 1e10): rows, differing.
  std::uint64_t rows_by_decade[11] = {}, differing_by_decade[11] = {};
  for_each_random_slip(
      2026, 100000,
      [&](const testing::RandomModel& r, const Phase& phase,
          const detail::HarmonicCoulombFormula<double>& formula) {
        std::optional<ExactSlip> exact;
        for (const testing::SlipRow& row : testing::slip_rows(formula, phase)) {
          ++rows;
          const double phase_angle = std::fabs(r.model.omega * row.t);
          const int decade =
              phase_angle < 1 ? 0 : std::min(10, static_cast<int>(std::log10(phase_angle)) + 1);
          ++rows_by_decade[decade];
          if (same_row(row.batch, row.long_double)) continue;
          ++differing;
          ++differing_by_decade[decade];
          if (!exact) exact.emplace(r.model, phase);
          const Exact e = exact->at(row.t);
          const State& fast = row.batch;
          ASSERT_TRUE(fast.x == e.x && fast.v == e.v && fast.a == e.a)
              << testing::describe(r) << " t=" << row.t;
          ++fast_closer;
        }
      });
  std::cout << rows << " rows; " << differing
            << " differ from the long double path, and in all of them the fast row is the "
               "correctly rounded one ("
            << fast_closer << ")\n";
  for (int d = 0; d < 11; ++d)
    std::cout << "  |w t| "
              << (d == 0 ? "below 1" : "1e" + std::to_string(d - 1) + "..1e" + std::to_string(d))
              << " rad: " << differing_by_decade[d] << " of " << rows_by_decade[d]
              << " rows differ\n";
  EXPECT_GT(rows, 300000u);
  RecordProperty("rows", std::to_string(rows));
  RecordProperty("differing_fast_correctly_rounded", std::to_string(fast_closer));
}

// The general model without spring, damper, harmonics or record slips by the
// seed's law with a constant force F0 - s R (static friction Rs > R only
// decides when it starts): its dense rows take the same fast path. 10^5
// random models of the seed's stream with Rs = R (1 + 10^u), u uniform on
// [-15, 1], and F0 = 0 (a third), or +-(B + R) 10^u, u uniform on [-8, 1]:
// the rows are those of the general long double path, except where that
// one is not the correctly rounded value; there the fast row must be.
TEST(DenseFastPath, GeneralModelWithoutSpringSameRowsAsItsLongDoublePath) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  testing::ModelStream stream(2027);
  std::mt19937_64 random(31);
  const auto unit = [&] { return std::ldexp(static_cast<double>(random() >> 11), -53); };
  std::uint64_t models = 0, refused = 0, slips = 0, rows = 0, decided = 0, differing = 0;
  // Rows whose start is within the fast path's reach, |w t_a| <= 2^24.
  std::uint64_t near_rows = 0, near_decided = 0;
  for (int i = 0; i < 100000 && !HasFatalFailure(); ++i) {
    testing::RandomModel r = stream.next();
    Model& m = r.model;
    m.static_friction = m.friction * (1 + std::pow(10.0, -15 + 16 * unit()));
    const double pick = unit();
    m.force_offset = pick < 1.0 / 3 ? 0.0
                                    : (pick < 2.0 / 3 ? 1 : -1) * (m.amplitude + m.friction) *
                                          std::pow(10.0, -8 + 9 * unit());
    if (m.is_harmonic_coulomb()) continue;  // R = 0 and F0 = 0: the seed's engine
    Phase phase;
    try {
      ExactEngine engine(m, r.t_end);
      ++models;
      for (int k = 0; k < 6 && engine.next(phase); ++k) {
        if (phase.kind == PhaseKind::stick) continue;
        ++slips;
        const detail::LinearOscillatorFormula<double> formula(m, phase);
        std::optional<ExactSlip> exact;
        for (const testing::SlipRow& row : testing::slip_rows(formula, phase)) {
          if (!row.inside) continue;
          ++rows;
          State only_fast;
          const bool near = std::fabs(m.omega * phase.t_begin) <= 0x1p24;
          near_rows += near;
          if (formula.fast_at(row.t, only_fast)) {
            ++decided;
            near_decided += near;
          }
          if (same_row(row.batch, row.long_double)) continue;
          ++differing;
          if (!exact) exact.emplace(m, phase);
          const Exact e = exact->at(row.t);
          const State& fast = row.batch;
          ASSERT_TRUE(fast.x == e.x && fast.v == e.v && fast.a == e.a)
              << testing::describe(r) << " Rs=" << m.static_limit() << " F0=" << m.force_offset
              << " t=" << row.t;
        }
      }
    } catch (const InvalidInput&) {
      ++refused;
    }
  }
  std::cout << models << " general models (" << refused << " refused), " << slips << " slips, "
            << rows << " rows, " << decided << " decided by the fast path (" << near_decided
            << " of the " << near_rows << " that start within |w t| <= 2^24); " << differing
            << " differ from the long double path, and in all of them the fast row is the "
               "correctly rounded one\n";
  EXPECT_GT(models, 90000u);
  EXPECT_GT(rows, 200000u);
  // (90 % when written: the rest are rows of slips a few ulps long, or whose
  // v or x is far below the forcing's velocity or length scale, whose
  // absolute bound then exceeds their half-ulp; the seed's rows alike.)
  EXPECT_GT(near_decided, near_rows * 85 / 100);
  RecordProperty("rows", std::to_string(rows));
  RecordProperty("differing_fast_correctly_rounded", std::to_string(differing));
}

// The seed's fast path on eight lanes gives the rows of its four, on random
// models (dense_row_checks.hpp, check_lane_widths).
TEST(DenseFastPath, EightLanesGiveTheRowsOfFour) {
  if (!detail::double_double_wide_lanes_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  std::uint64_t rows = 0;
  for_each_random_slip(17, 3000,
                       [&](const testing::RandomModel& r, const Phase& phase,
                           const detail::HarmonicCoulombFormula<double>& formula) {
                         testing::check_lane_widths(
                             formula, phase, [&] { return testing::describe(r); }, rows);
                       });
  std::cout << rows << " rows the same on eight lanes and on four\n";
  EXPECT_GT(rows, 100000u);
}

// The sampler's, sample_at's and compare's batches give the rows of one
// evaluation per time.
TEST(DenseFastPath, SamplerRowsAreThoseOfSingleEvaluations) {
  testing::ModelStream stream(5);
  for (int i = 0; i < 300; ++i) {
    const testing::RandomModel r = stream.next();
    GridOptions grid;
    grid.t_end = r.t_end;
    grid.dt = (r.t_end - r.model.t0) / 333;
    grid.include_events = i % 2 == 0;
    if (!(r.model.t0 + grid.dt > r.model.t0)) continue;
    UniformSampler sampler(r.model, grid);
    ExactEngine engine(r.model, grid.t_end);
    Phase phase;
    ASSERT_TRUE(engine.next(phase));
    State row;
    std::uint64_t count = 0;
    std::vector<State> rows;
    while (sampler.next(row)) {
      ++count;
      rows.push_back(row);
      // The sampler's rule: a time at a boundary belongs to the next phase.
      while (row.t >= phase.t_end && phase.t_end < grid.t_end && engine.next(phase)) {
      }
      const State single = evaluate(r.model, phase, row.t);
      ASSERT_TRUE(same_row(row, single)) << testing::describe(r) << " row " << count;
    }
    EXPECT_GE(count, 333u);
    // sample_at evaluates its times in batches too: the grid's times (no
    // event rows, which carry the next phase) give the same rows.
    std::vector<double> times;
    std::vector<State> expected;
    for (const State& s : rows)
      if (!grid.include_events) {
        times.push_back(s.t);
        expected.push_back(s);
      }
    const std::vector<State> again = sample_at(r.model, times);
    ASSERT_EQ(again.size(), expected.size());
    for (std::size_t k = 0; k < again.size(); ++k)
      ASSERT_TRUE(same_row(again[k], expected[k])) << testing::describe(r) << " time " << k;
    // So does compare's exact side.
    if (times.empty()) continue;
    const std::vector<State> exact = comparison::exact_motion(r.model, times).states;
    ASSERT_EQ(exact.size(), expected.size());
    for (std::size_t k = 0; k < exact.size(); ++k)
      ASSERT_TRUE(same_row(exact[k], expected[k])) << testing::describe(r) << " time " << k;
  }
}

}  // namespace
}  // namespace frictionref
