// The general model's dense fast path for an underdamped spring, and for
// harmonics without spring or damper (double_double_oscillator.hpp,
// docs/theory.md 10.6), against an independent 50-digit evaluation of the
// closed form (the textbook split into the steady response and a damped free
// oscillation or a parabola, with Boost's exp, sin and cos at exact
// arguments; the long double path uses divided differences and transition
// functions instead), and against the long double path it short-cuts: the
// same rows, except where the long double row is not the correctly rounded
// one and the fast row is.
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

#include "dense_row_checks.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "laws/linear_oscillator/double_double_oscillator.hpp"
#include "laws/linear_oscillator/phase_formula.hpp"
#include "numeric/double_double_table.hpp"
#include "random_models.hpp"

namespace frictionref {
namespace {

using testing::Fifty;
using testing::nearest;
using testing::same_row;

bool available() { return detail::double_double_lanes_available(); }

// The slip's closed form in 50 digits (docs/theory.md 10.6), from the
// phase's double start at exact w t, w t_a, in the textbook forms (the fast
// path's own split differs for the over-damped spring and the damper alone):
// with a spring, e^{-sigma h} (C1 cos nu h + C2 sin nu h), or (over-damped)
// e^{-sigma h} (C1 cosh mu h + C2 sinh mu h); with a damper alone, C1 +
// (D1 - d)(1 - e^{-2 sigma h}) / (2 sigma) + d h, d = g0 / (2 sigma); with
// neither, C1 + D1 h + g0 h^2 / 2.
struct Exact {
  Fifty x, v, a;
};
class ExactSpringSlip {
 public:
  ExactSpringSlip(const Model& m, const Phase& p)
      : w_(m.omega), a_(w_ * Fifty(p.t_begin)), spring_(m.stiffness > 0) {
    const Fifty mw = Fifty(m.mass) * w_;
    sigma_ = Fifty(m.damping) / (2 * mw);
    const Fifty rho2 = Fifty(m.stiffness) / (mw * w_);
    g0_ = (Fifty(m.force_offset) - slip_sign(p.kind) * Fifty(m.friction)) / mw;
    if (spring_) {
      over_damped_ = sigma_ * sigma_ > rho2;
      nu_ = sqrt(abs(rho2 - sigma_ * sigma_));  // mu if over-damped
      steady_ = g0_ / rho2;
    }
    terms_.push_back({Fifty(m.amplitude) / mw, Fifty(1), Fifty(0)});
    for (const Harmonic& h : m.harmonics)
      terms_.push_back({Fifty(h.amplitude) / mw, Fifty(h.omega) / w_, Fifty(h.phase)});
    for (Term& t : terms_) {
      // b Im(H e^{i theta}), H = 1 / (rho^2 - q^2 + 2 i sigma q).
      const Fifty re = rho2 - t.q * t.q, im = 2 * sigma_ * t.q;
      const Fifty d = re * re + im * im;
      t.s = t.b * re / d;
      t.c = -t.b * im / d;
    }
    const Particular at_start = particular(a_);
    c1_ = w_ * Fifty(p.x_begin) - at_start.y;
    d1_ = Fifty(p.v_begin) - at_start.v;
    if (spring_) c2_ = (d1_ + sigma_ * c1_) / nu_;
  }

  Exact at(double t) const {
    const Fifty tau = w_ * Fifty(t);
    const Fifty h = tau - a_;
    const Particular p = particular(tau);
    if (!spring_ && sigma_ == 0)
      return {(p.y + c1_ + h * (d1_ + g0_ * h / 2)) / w_, p.v + d1_ + g0_ * h, w_ * (p.dv + g0_)};
    if (!spring_) {
      const Fifty kappa = 2 * sigma_, drift = g0_ / kappa, e = exp(-kappa * h);
      const Fifty y = p.y + c1_ + (d1_ - drift) * (1 - e) / kappa + drift * h;
      return {y / w_, p.v + (d1_ - drift) * e + drift, w_ * (p.dv - kappa * (d1_ - drift) * e)};
    }
    const Fifty e = exp(-sigma_ * h);
    const Fifty c = over_damped_ ? cosh(nu_ * h) : cos(nu_ * h);
    const Fifty s = over_damped_ ? sinh(nu_ * h) : sin(nu_ * h);
    // y_h = e (C1 c + C2 s) and its two derivatives: d/dh of e (P c + Q s) is
    // e ((nu Q - sigma P) c + (-+nu P - sigma Q) s), - for cos, + for cosh.
    const Fifty turn = over_damped_ ? Fifty(1) : Fifty(-1);
    const Fifty d2 = turn * nu_ * c1_ - sigma_ * c2_;
    const Fifty e1 = nu_ * d2 - sigma_ * d1_, e2 = turn * nu_ * d1_ - sigma_ * d2;
    const Fifty y = p.y + e * (c1_ * c + c2_ * s);
    const Fifty v = p.v + e * (d1_ * c + d2 * s);
    const Fifty dv = p.dv + e * (e1 * c + e2 * s);
    return {y / w_, v, w_ * dv};
  }

 private:
  struct Term {
    Fifty b, q, phi, s = 0, c = 0;
  };
  struct Particular {
    Fifty y, v, dv;
  };
  Particular particular(const Fifty& tau) const {
    Particular p{steady_, 0, 0};
    for (const Term& t : terms_) {
      const Fifty theta = t.q * tau + t.phi;
      const Fifty sn = sin(theta), cs = cos(theta);
      p.y += t.s * sn + t.c * cs;
      p.v += t.q * (t.s * cs - t.c * sn);
      p.dv -= t.q * t.q * (t.s * sn + t.c * cs);
    }
    return p;
  }
  Fifty w_, a_;
  bool spring_, over_damped_ = false;
  Fifty sigma_, g0_, nu_, steady_ = 0, c1_, d1_, c2_;
  std::vector<Term> terms_;
};

// Random models from the seed's stream. Springs: natural frequency w 10^u
// (u uniform on [-1, 1]), damping ratio 0 (a tenth) or log-uniform on
// [1e-4, 0.95], and a tenth over-damped (ratio 1 to 4); up to two harmonics.
// Harmonics alone: no spring or damper, one to eight harmonics (with none the
// seed's fast path takes the slip), a fifth driven by the harmonics alone
// (B = 0 once they are drawn). Decays: half over-damped springs (ratio
// 1 + 10^u, u on [-12, 1], so some within rounding of critical damping,
// where the fast path stands aside), half dampers alone (c = m w 10^u, u on
// [-3, 1]); up to two harmonics. All: Rs = R (1 + 10^u), u on [-15, 0];
// F0 = 0 (a half) or +-(B + R) 10^u, u on [-4, 0]; each harmonic B U(0, 1)
// sin(w 10^u t + phi), u on [-1, 1], phi uniform on [-pi, pi].
enum class Family { spring, harmonics_alone, decays };
class SpringModels {
 public:
  explicit SpringModels(std::uint64_t seed, Family family = Family::spring)
      : stream_(seed), random_(seed + 1), family_(family) {}
  testing::RandomModel next() {
    testing::RandomModel r = stream_.next();
    Model& m = r.model;
    if (family_ == Family::spring) {
      const double natural = m.omega * std::pow(10.0, uniform(-1, 1));
      const double pick = unit();
      const double ratio = pick < 0.1   ? 0.0
                           : pick < 0.2 ? uniform(1, 4)
                                        : std::pow(10.0, uniform(-4, std::log10(0.95)));
      m.stiffness = m.mass * natural * natural;
      m.damping = 2 * ratio * m.mass * natural;
    } else if (family_ == Family::decays) {
      if (unit() < 0.5) {
        const double natural = m.omega * std::pow(10.0, uniform(-1, 1));
        m.stiffness = m.mass * natural * natural;
        m.damping = 2 * (1 + std::pow(10.0, uniform(-12, 1))) * m.mass * natural;
      } else {
        m.damping = m.mass * m.omega * std::pow(10.0, uniform(-3, 1));
      }
    }
    m.static_friction = m.friction * (1 + std::pow(10.0, uniform(-15, 0)));
    m.force_offset = unit() < 0.5 ? 0.0
                                  : (unit() < 0.5 ? 1 : -1) * (m.amplitude + m.friction) *
                                        std::pow(10.0, uniform(-4, 0));
    const int harmonics = family_ == Family::harmonics_alone ? 1 + static_cast<int>(unit() * 8)
                                                             : static_cast<int>(unit() * 3);
    for (int j = 0; j < harmonics; ++j)
      m.harmonics.push_back({m.amplitude * unit(), m.omega * std::pow(10.0, uniform(-1, 1)),
                             uniform(-3.141592653589793, 3.141592653589793)});
    if (family_ == Family::harmonics_alone && unit() < 0.2) m.amplitude = 0;
    return r;
  }

 private:
  double unit() { return std::ldexp(static_cast<double>(random_() >> 11), -53); }
  double uniform(double a, double b) { return a + (b - a) * unit(); }
  testing::ModelStream stream_;
  std::mt19937_64 random_;
  Family family_;
};

// Each slip among the first six phases of `count` random spring models, with
// its formula; models the engine refuses are counted.
template <class Visit>
std::uint64_t for_each_spring_slip(std::uint64_t seed, int count, Visit visit,
                                   Family family = Family::spring) {
  SpringModels models(seed, family);
  std::uint64_t refused = 0;
  for (int i = 0; i < count && !::testing::Test::HasFatalFailure(); ++i) {
    const testing::RandomModel r = models.next();
    try {
      ExactEngine engine(r.model, r.t_end);
      Phase phase;
      for (int k = 0; k < 6 && engine.next(phase); ++k) {
        if (phase.kind == PhaseKind::stick) continue;
        const detail::LinearOscillatorFormula<double> formula(r.model, phase);
        visit(r, phase, formula);
      }
    } catch (const InvalidInput&) {
      ++refused;
    }
  }
  return refused;
}

std::string describe_spring(const testing::RandomModel& r) {
  const Model& m = r.model;
  std::string text = testing::describe(r);
  char more[256];
  std::snprintf(more, sizeof more, " k=%.17g c=%.17g Rs=%.17g F0=%.17g", m.stiffness, m.damping,
                m.static_limit(), m.force_offset);
  text += more;
  for (const Harmonic& h : m.harmonics) {
    std::snprintf(more, sizeof more, " harmonic=%.17g,%.17g,%.17g", h.amplitude, h.omega, h.phase);
    text += more;
  }
  return text;
}

TEST(DoubleDoubleExp, WithinItsBoundOfFiftyDigits) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  std::mt19937_64 random(20261127);
  const auto unit = [&] { return std::ldexp(static_cast<double>(random() >> 11), -53); };
  const Fifty ln2 = boost::math::constants::ln_two<Fifty>();
  Fifty worst = 0;
  double bound = 0;
  for (int i = 0; i < 60000; ++i) {
    // A third near the reduction's boundaries (k ln 2 + m / 2048 + 1/4096), a
    // third small, the rest anywhere in [-708, 0].
    double hi;
    if (i % 3 == 0)
      hi = -static_cast<double>(ln2 * Fifty(std::floor(unit() * 1000)) +
                                Fifty(std::floor(unit() * 1421) - 710) / 2048 + Fifty(1) / 4096) *
           (1 + (unit() - 0.5) * 1e-12);
    else if (i % 3 == 1)
      hi = -std::ldexp(unit(), -static_cast<int>(unit() * 60));
    else
      hi = -708 * unit();
    if (hi > 0) hi = -hi;
    if (hi < -708) hi = -708;
    const double lo = hi * std::ldexp(unit() - 0.5, -53);
    double out[3];
    detail::double_double_exp(hi, lo, out);
    const Fifty exact = exp(Fifty(hi) + Fifty(lo));
    const Fifty error = abs(Fifty(out[0]) + Fifty(out[1]) - exact);
    // Within the bound relative, plus 2^-1000 absolute (the low part's
    // underflow near e^-708); the largest relative error where that is
    // below the bound's 2^-40.
    bound = out[2];
    ASSERT_LE(error, Fifty(bound) * exact + Fifty(std::ldexp(1.0, -1000))) << hi;
    if (exact > Fifty(std::ldexp(1.0, -900))) worst = std::max(worst, error / exact);
  }
  EXPECT_LT(worst, Fifty(bound) / 8) << static_cast<double>(worst);
  std::cout << "largest relative error of exp: " << static_cast<double>(worst) << " (bound "
            << bound << ")\n";
}

// The sum of products of the rows' x, v and a (numeric/double_double_sum.hpp),
// on exact operands: within its bound of the 50-digit sum, with the sums
// cancelling to a millionth of their terms or less in a third of the cases.
TEST(DoubleDoubleSum, WithinItsBoundOfFiftyDigits) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  std::mt19937_64 random(20261128);
  const auto unit = [&] { return std::ldexp(static_cast<double>(random() >> 11), -53); };
  // A normalized pair of magnitude about 2^[-20, 20] and either sign.
  const auto pair = [&](double* p) {
    p[0] = std::ldexp(unit() + 0.5, static_cast<int>(unit() * 40) - 20) * (unit() < 0.5 ? -1 : 1);
    p[1] = p[0] * std::ldexp(unit() - 0.5, -53);
  };
  Fifty worst = 0;  // the largest error relative to the bound
  int exact_sums = 0;
  for (int i = 0; i < 20000; ++i) {
    const int n = 1 + static_cast<int>(unit() * 12);
    double start[2], c[24], f[24];
    pair(start);
    for (int j = 0; j < n; ++j) {
      pair(c + 2 * j);
      pair(f + 2 * j);
    }
    Fifty exact = Fifty(start[0]) + Fifty(start[1]);
    for (int j = 0; j < n - 1; ++j)
      exact += (Fifty(c[2 * j]) + Fifty(c[2 * j + 1])) * (Fifty(f[2 * j]) + Fifty(f[2 * j + 1]));
    if (i % 3 == 0) {
      // The last product cancels the rest to about 2^-20 of it: c = -rest / f.
      const Fifty last_f = Fifty(f[2 * n - 2]) + Fifty(f[2 * n - 1]);
      const Fifty want = -exact / last_f * (1 + Fifty(std::ldexp(unit(), -20)));
      c[2 * n - 2] = static_cast<double>(want);
      c[2 * n - 1] = static_cast<double>(want - Fifty(c[2 * n - 2]));
    }
    exact +=
        (Fifty(c[2 * n - 2]) + Fifty(c[2 * n - 1])) * (Fifty(f[2 * n - 2]) + Fifty(f[2 * n - 1]));
    double out[3];
    detail::double_double_sum(start, c, f, n, out);
    const Fifty error = abs(Fifty(out[0]) + Fifty(out[1]) - exact);
    ASSERT_LE(error, Fifty(out[2])) << "case " << i << ", " << n << " terms";
    ASSERT_EQ(std::fabs(out[1]) <= std::ldexp(std::fabs(out[0]), -53), true) << "not normalized";
    if (error == 0) ++exact_sums;
    worst = std::max(worst, error / Fifty(out[2]));
  }
  std::cout << "largest error of the sum: " << static_cast<double>(worst) << " of its bound; "
            << exact_sums << " of 20000 sums exact\n";
  EXPECT_LT(exact_sums, 20000);  // the bound is tested by inexact sums
}

// Every value the fast path decides, at times spread over each slip and
// crowded towards its stop, is the correctly rounded 50-digit value.
void decided_values_are_correctly_rounded(Family family) {
  std::mt19937_64 random(7);
  const auto unit = [&] { return std::ldexp(static_cast<double>(random() >> 11), -53); };
  std::uint64_t tried = 0, decided = 0;
  const auto visit = [&](const testing::RandomModel& r, const Phase& phase,
                         const detail::LinearOscillatorFormula<double>& formula) {
    std::optional<ExactSpringSlip> exact;
    for (const double t : testing::probe_times(phase, unit)) {
      ++tried;
      State fast;
      if (!formula.fast_at(t, fast)) continue;
      ++decided;
      if (!exact) exact.emplace(r.model, phase);
      const Exact e = exact->at(t);
      ASSERT_EQ(fast.x, nearest(e.x)) << describe_spring(r) << " t=" << t;
      ASSERT_EQ(fast.v, nearest(e.v)) << describe_spring(r) << " t=" << t;
      ASSERT_EQ(fast.a, nearest(e.a)) << describe_spring(r) << " t=" << t;
    }
  };
  for_each_spring_slip(11, 3000, visit, family);
  std::cout << decided << " of " << tried << " states decided by the fast path\n";
  EXPECT_GT(tried, 10000u);
  EXPECT_GT(decided, tried / 2);
}

TEST(DoubleDoubleOscillator, DecidedValuesAreCorrectlyRounded) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  decided_values_are_correctly_rounded(Family::spring);
}

TEST(DoubleDoubleOscillator, HarmonicsAloneDecidedValuesAreCorrectlyRounded) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  decided_values_are_correctly_rounded(Family::harmonics_alone);
}

TEST(DoubleDoubleOscillator, DecaysDecidedValuesAreCorrectlyRounded) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  decided_values_are_correctly_rounded(Family::decays);
}

// A slip's rows at its own ends (a curve's event rows): x and v are the
// stored states there, so the fast path need decide the acceleration alone
// (a start from rest has v = 0, which no bound decides). Where it does, the
// acceleration is the correctly rounded 50-digit value; elsewhere the row is
// the long double path's.
void end_rows_decide_the_acceleration(Family family) {
  testing::EndRowCounts counts;
  const auto visit = [&](const testing::RandomModel& r, const Phase& phase,
                         const detail::LinearOscillatorFormula<double>& formula) {
    std::optional<ExactSpringSlip> exact;
    const auto exact_a = [&](double t) {
      if (!exact) exact.emplace(r.model, phase);
      return nearest(exact->at(t).a);
    };
    testing::check_end_rows(
        formula, phase, exact_a, [&] { return describe_spring(r); }, counts);
  };
  for_each_spring_slip(13, 3000, visit, family);
  testing::expect_end_rows_tested(counts);
}

TEST(DenseFastPath, SpringEndRowsDecideTheAcceleration) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  end_rows_decide_the_acceleration(Family::spring);
}

TEST(DenseFastPath, HarmonicsAloneEndRowsDecideTheAcceleration) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  end_rows_decide_the_acceleration(Family::harmonics_alone);
}

TEST(DenseFastPath, DecaysEndRowsDecideTheAcceleration) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  end_rows_decide_the_acceleration(Family::decays);
}

// The oscillator's fast path on eight lanes gives the rows of its four, on
// random models of each family (dense_row_checks.hpp, check_lane_widths).
void eight_lanes_give_the_rows_of_four(Family family) {
  std::uint64_t rows = 0;
  const auto visit = [&](const testing::RandomModel& r, const Phase& phase,
                         const detail::LinearOscillatorFormula<double>& formula) {
    testing::check_lane_widths(
        formula, phase, [&] { return describe_spring(r); }, rows);
  };
  for_each_spring_slip(17, 2000, visit, family);
  std::cout << rows << " rows the same on eight lanes and on four\n";
  EXPECT_GT(rows, 50000u);
}

TEST(DenseFastPath, SpringEightLanesGiveTheRowsOfFour) {
  if (!detail::double_double_wide_lanes_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  eight_lanes_give_the_rows_of_four(Family::spring);
}

TEST(DenseFastPath, HarmonicsAloneEightLanesGiveTheRowsOfFour) {
  if (!detail::double_double_wide_lanes_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  eight_lanes_give_the_rows_of_four(Family::harmonics_alone);
}

TEST(DenseFastPath, DecaysEightLanesGiveTheRowsOfFour) {
  if (!detail::double_double_wide_lanes_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  eight_lanes_give_the_rows_of_four(Family::decays);
}

// `count` random models, three rows in each slip among the first six phases:
// the rows of the long double path, except where they differ; there the fast
// row is the correctly rounded 50-digit value, and the long double row is
// within 1e-6 of the motion's scale of it (rounding, not a different
// formula).
void same_rows_as_the_long_double_path(Family family, std::uint64_t seed, int count,
                                       std::uint64_t least_rows) {
  std::uint64_t rows = 0, decided = 0, differing = 0;
  const auto visit = [&](const testing::RandomModel& r, const Phase& phase,
                         const detail::LinearOscillatorFormula<double>& formula) {
    std::optional<ExactSpringSlip> exact;
    for (const testing::SlipRow& row : testing::slip_rows(formula, phase)) {
      if (!row.inside) continue;
      ++rows;
      State only_fast;
      decided += formula.fast_at(row.t, only_fast);
      if (same_row(row.batch, row.long_double)) continue;
      ++differing;
      if (!exact) exact.emplace(r.model, phase);
      const Exact e = exact->at(row.t);
      const State& fast = row.batch;
      const State& slow = row.long_double;
      ASSERT_TRUE(fast.x == nearest(e.x) && fast.v == nearest(e.v) && fast.a == nearest(e.a))
          << describe_spring(r) << " t=" << row.t;
      // The motion's scales: velocity (forces) / (m w), and its x and a; the
      // forces include the spring's and the damper's at the start (with a
      // spring's force far above the others, the long double path's 64-bit
      // w t costs its ulps times that).
      const Model& m = r.model;
      double forces = m.amplitude + m.friction + std::fabs(m.force_offset) +
                      m.stiffness * std::fabs(phase.x_begin) + m.damping * std::fabs(phase.v_begin);
      for (const Harmonic& h : m.harmonics) forces += std::fabs(h.amplitude);
      const double speed = forces / (m.mass * m.omega) + std::fabs(phase.v_begin);
      const auto near = [](double value, const Fifty& reference, double scale) {
        return std::fabs(static_cast<double>(Fifty(value) - reference)) <=
               1e-6 * (std::fabs(static_cast<double>(reference)) + scale);
      };
      ASSERT_TRUE(near(slow.x, e.x, speed / m.omega + std::fabs(phase.x_begin)) &&
                  near(slow.v, e.v, speed) && near(slow.a, e.a, speed * m.omega))
          << describe_spring(r) << " t=" << row.t;
    }
  };
  const std::uint64_t refused = for_each_spring_slip(seed, count, visit, family);
  std::cout << rows << " rows (" << refused << " models refused), " << decided
            << " decided by the fast path; " << differing
            << " differ from the long double path, and in all of them the fast row is the "
               "correctly rounded one\n";
  EXPECT_GT(rows, least_rows);
  ::testing::Test::RecordProperty("rows", std::to_string(rows));
  ::testing::Test::RecordProperty("differing_fast_correctly_rounded", std::to_string(differing));
}

TEST(DenseFastPath, SpringSameRowsAsItsLongDoublePath) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  same_rows_as_the_long_double_path(Family::spring, 2028, 100000, 200000);
}

TEST(DenseFastPath, HarmonicsAloneSameRowsAsTheirLongDoublePath) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  same_rows_as_the_long_double_path(Family::harmonics_alone, 2029, 100000, 200000);
}

TEST(DenseFastPath, DecaysSameRowsAsTheirLongDoublePath) {
  if (!available()) GTEST_SKIP() << "no AVX2 and FMA on this CPU";
  same_rows_as_the_long_double_path(Family::decays, 2030, 100000, 200000);
}

}  // namespace
}  // namespace frictionref
