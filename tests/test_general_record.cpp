// A ground record together with a spring, damper or harmonic force: the
// general family's laws on each segment of the record (docs/theory.md 9.6).
// Expected values come from closed forms evaluated here in long double, from
// the rigid block's own laws (quadratic roots, another family) where the
// general family meets a rigid block, and from the general engine's harmonic
// forcing (no record) that a sampled sine approaches. The 50-digit reference
// (tests/reference) checks the same models to 4 ulps.
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "hand_made_record.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

using testing::expect_invalid;
using testing::record;

// Ulps of double between a and b.
double ulps(double a, double b) {
  return std::fabs(a - b) / std::ldexp(1.0, std::ilogb(std::max(std::fabs(a), 1e-300)) - 52);
}

// Two runs of the same motion phase by phase: the same kinds, each x_end
// within x_abs + x_rel |x_end of reference|. Returns the largest difference
// of the phases' end times, in ulps.
double largest_event_difference(const Solution& s, const Solution& reference, double x_abs,
                                double x_rel) {
  double worst = 0;
  for (std::size_t i = 0; i < s.phases.size() && i < reference.phases.size(); ++i) {
    EXPECT_EQ(s.phases[i].kind, reference.phases[i].kind) << "phase " << i;
    worst = std::max(worst, ulps(s.phases[i].t_end, reference.phases[i].t_end));
    EXPECT_NEAR(s.phases[i].x_end, reference.phases[i].x_end,
                x_abs + x_rel * std::fabs(reference.phases[i].x_end))
        << "phase " << i;
  }
  return worst;
}

// m = 1, k = 4 (natural frequency 2), R = Rs = 0 under a_g = 2 t on [0, 1),
// then 0. Relative motion: x'' + 4 x = -2 t, so x = -t/2 + sin(2t)/4 (from
// rest; v = (cos 2t - 1)/2 <= 0, zero only at t = 0 and pi); then the free
// oscillation from (x1, v1) at t = 1. With R = 0 every zero of v is a
// reversal (N = -k x != 0 there), at t_j = 1 + (phi + j pi) / 2 with
// tan(phi) = v1 / (2 x1).
TEST(GeneralRecord, SpringUnderARampMatchesTheClosedForm) {
  Model m;
  m.amplitude = 0;
  m.stiffness = 4;
  m.ground_motion = record({0, 1}, {0, 2});
  const double t_end = 6;
  const Solution s = solve(m, t_end);
  testing::expect_well_formed(s, t_end);
  const long double x1 = -0.5L + sinl(2.0L) / 4, v1 = (cosl(2.0L) - 1) / 2;
  long double phi = atanl(v1 / (2 * x1));
  if (phi < 0) phi += 3.14159265358979323846264338327950288L;
  std::vector<long double> stops;
  for (int j = 0;; ++j) {
    const long double t = 1 + (phi + j * 3.14159265358979323846264338327950288L) / 2;
    if (t >= t_end) break;
    stops.push_back(t);
  }
  // The breakaway at t = 0 (N = -2 m t leaves 0 at once), one slip- to the
  // first stop, then a reversal at each zero of v.
  ASSERT_EQ(s.phases.size(), stops.size() + 1);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_backward);
  for (std::size_t j = 0; j < stops.size(); ++j) {
    const Phase& p = s.phases[j];
    SCOPED_TRACE("stop " + std::to_string(j));
    EXPECT_LE(ulps(p.t_end, static_cast<double>(stops[j])), 4);
    const long double u = stops[j] - 1;
    const long double x = x1 * cosl(2 * u) + v1 / 2 * sinl(2 * u);
    EXPECT_NEAR(p.x_end, static_cast<double>(x), 1e-15);
    EXPECT_EQ(s.phases[j + 1].kind, p.kind == PhaseKind::slip_forward ? PhaseKind::slip_backward
                                                                      : PhaseKind::slip_forward);
  }
  // Inside the ramp, dense output against x = -t/2 + sin(2t)/4.
  for (const double t : {0.25, 0.5, 0.75, 0.999}) {
    const long double x = -0.5L * t + sinl(2.0L * t) / 4;
    EXPECT_NEAR(s.state_at(t).x, static_cast<double>(x), 1e-16) << "t = " << t;
  }
}

// The same model in the 50-digit instance of the engine (the same template,
// Work = cpp_bin_float_50): the ramp's closed form G2 and the interval walk in
// 50 digits, against the closed form in 50 digits (Boost.Multiprecision).
TEST(GeneralRecord, SpringUnderARampInFiftyDigits) {
  using Wide = HighPrecision;
  BasicModel<Wide> m;
  m.amplitude = 0;
  m.stiffness = 4;
  m.ground_motion = record({0, 1}, {0, 2});
  const BasicSolution<Wide> s = solve(m, Wide(6));
  ASSERT_EQ(s.summary.termination, Termination::reached_end) << s.summary.message;
  const Wide x1 = Wide(-0.5) + sin(Wide(2)) / 4, v1 = (cos(Wide(2)) - 1) / 2;
  Wide phi = atan(v1 / (2 * x1));
  if (phi < 0) phi += boost::math::constants::pi<Wide>();
  ASSERT_GE(s.phases.size(), 3u);
  for (std::size_t j = 0; j + 1 < s.phases.size(); ++j) {
    const Wide t = 1 + (phi + Wide(j) * boost::math::constants::pi<Wide>()) / 2;
    EXPECT_LT(abs(s.phases[j].t_end - t), Wide("1e-45")) << "stop " << j;
    const Wide u = t - 1;
    const Wide x = x1 * cos(2 * u) + v1 / 2 * sin(2 * u);
    EXPECT_LT(abs(s.phases[j].x_end - x), Wide("1e-45")) << "stop " << j;
  }
}

// A damped spring driven by a record sampling a_g = -sin t at step h: the
// record is the sine's linear interpolant, off by at most h^2 / 8, so the
// motion must approach the general engine's harmonic forcing B sin t (no
// record: one closed form per slip, no segments) as h^2.
TEST(GeneralRecord, SampledSineConvergesToTheHarmonicForcing) {
  const double t_end = 20 * M_PI;
  for (const double lambda : {0.3, 0.6}) {
    Model harmonic;
    harmonic.friction = lambda;
    harmonic.static_friction = 1.25 * lambda;
    harmonic.stiffness = 0.5;
    harmonic.damping = 0.1;
    const Solution exact = solve(harmonic, t_end);
    ASSERT_EQ(exact.summary.termination, Termination::reached_end);
    double previous = 0;
    for (const int per_period : {100, 200, 400}) {
      const int n = 10 * per_period;
      std::vector<double> t(n + 1), a(n + 1);
      for (int i = 0; i <= n; ++i) {
        t[i] = t_end * i / n;
        a[i] = -std::sin(t[i]);
      }
      Model sampled_model = harmonic;
      sampled_model.amplitude = 0;
      sampled_model.ground_motion = record(t, a);
      const Solution sampled = solve(sampled_model, t_end);
      testing::expect_well_formed(sampled, t_end);
      double error = 0;
      for (int j = 1; j <= 40; ++j) {
        const double tj = t_end * j / 40 * (1 - 1e-9);
        error = std::max(error, std::fabs(sampled.state_at(tj).x - exact.state_at(tj).x));
      }
      const double h = 2 * M_PI / per_period;
      SCOPED_TRACE("lambda " + std::to_string(lambda) + " h " + std::to_string(h));
      EXPECT_LT(error, 10 * h * h);
      if (previous > 0) {
        EXPECT_LT(error, previous / 3);
      }
      previous = error;
    }
  }
}

// The general family on a rigid block (a damper of 1e-200, or a harmonic of
// 1e-200: the same motion to far below rounding) against the rigid block's
// own laws, whose stops are roots of quadratics: two methods, one answer, on
// a record of noise.
TEST(GeneralRecord, MeetsTheRigidBlockLawsOnARigidBlock) {
  std::vector<double> t, a;
  unsigned state = 12345;
  for (int i = 0; i <= 400; ++i) {
    state = state * 1103515245u + 12345u;
    t.push_back(0.01 * i);
    a.push_back(4.0 * ((state >> 8) % 2001 / 1000.0 - 1.0));
  }
  Model rigid;
  rigid.amplitude = 0;
  rigid.friction = 1;
  rigid.static_friction = 1.2;
  rigid.ground_motion = record(t, a);
  const double t_end = 6;
  const Solution reference = solve(rigid, t_end);
  testing::expect_well_formed(reference, t_end);
  ASSERT_GT(reference.phases.size(), 20u);
  for (int variant = 0; variant < 2; ++variant) {
    Model general = rigid;
    if (variant == 0)
      general.damping = 1e-200;
    else
      general.harmonics.push_back({1e-200, 3.0, 0.0});
    const Solution s = solve(general, t_end);
    SCOPED_TRACE(variant == 0 ? "damper" : "harmonic");
    testing::expect_well_formed(s, t_end);
    ASSERT_EQ(s.phases.size(), reference.phases.size());
    EXPECT_LE(largest_event_difference(s, reference, 1e-14, 1e-14), 4)
        << "largest event-time difference, ulps";
  }
}

// Resampling the record linearly at dt/10 gives the same ground motion (the
// record is linear between its samples), so the same motion: the general laws
// then carry the state across ten times as many interval ends, each a
// rounding of the work type (long double), far below double's. Every event
// the same, to a few ulps.
TEST(GeneralRecord, InvariantUnderLinearResampling) {
  std::vector<double> t, a;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(0.02 * i);
    a.push_back(3 * std::sin(2.3 * t.back()) * std::sin(0.7 * t.back()) +
                1.5 * std::sin(9.1 * t.back() + 0.4));
  }
  std::vector<double> fine_t, fine_a;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    for (int j = 0; j < 10; ++j) {
      // Points on the segment's line, in long double, rounded once.
      const long double f = j / 10.0L;
      fine_t.push_back(static_cast<double>(t[i] + f * (static_cast<long double>(t[i + 1]) - t[i])));
      fine_a.push_back(static_cast<double>(a[i] + f * (static_cast<long double>(a[i + 1]) - a[i])));
    }
  fine_t.push_back(t.back());
  fine_a.push_back(a.back());
  Model m;
  m.amplitude = 0;
  m.friction = 0.8;
  m.static_friction = 1.1;
  m.stiffness = 9;
  m.damping = 0.3;
  m.harmonics.push_back({0.2, 1.3, 0.5});
  m.ground_motion = record(t, a);
  Model fine = m;
  fine.ground_motion = record(fine_t, fine_a);
  const double t_end = 22;
  const Solution coarse_run = solve(m, t_end), fine_run = solve(fine, t_end);
  testing::expect_well_formed(coarse_run, t_end);
  testing::expect_well_formed(fine_run, t_end);
  ASSERT_GT(coarse_run.phases.size(), 20u);
  ASSERT_EQ(fine_run.phases.size(), coarse_run.phases.size());
  const double worst = largest_event_difference(fine_run, coarse_run, 1e-13, 0);
  EXPECT_LE(worst, 16) << "largest event-time difference, ulps";
  std::printf("resampled x10: %zu phases, largest event-time difference %.3g ulps\n",
              coarse_run.phases.size(), worst);
}

// At the record's first sample a_g jumps from 0 to -3: N = 3 > Rs = 2 breaks
// the mass away at exactly t = 1 (the segment's start), with a spring.
TEST(GeneralRecord, JumpAtTheFirstSampleBreaksAwayAtIt) {
  Model m;
  m.amplitude = 0;
  m.friction = 1;
  m.static_friction = 2;
  m.stiffness = 1;
  m.ground_motion = record({1, 2}, {-3, -3});
  const Solution s = solve(m, 5.0);
  testing::expect_well_formed(s, 5.0);
  ASSERT_GE(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
  EXPECT_EQ(s.phases[0].t_end, 1.0);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::slip_forward);
  // x'' + x = 3 - 1 from rest at t = 1: x = 2 (1 - cos(t - 1)), v = 2 sin(t - 1),
  // until a_g jumps back to 0 at t = 2 (v > 0 there).
  const double x2 = 2 * (1 - std::cos(1.0));
  EXPECT_NEAR(s.state_at(1.5).x, 2 * (1 - std::cos(0.5)), 1e-15);
  EXPECT_NEAR(s.state_at(2.0).x, x2, 1e-15);
}

// Samples closer than the time resolution can hold a whole impulse the laws
// cannot resolve (a_g = 6e247 for 2e-70 s: found by fuzzing); with a spring,
// damper or harmonic the record is refused, naming it. The rigid block
// takes it (its quadratic roots need no resolution).
TEST(GeneralRecord, RefusesSamplesCloserThanTheTimeResolution) {
  Model m;
  m.mass = 257;
  m.amplitude = 4;
  m.friction = 0.2;
  m.force_offset = 256;
  m.ground_motion = record({5.4110892682262525e-312, 2.0295277722943321e-70},
                           {2.5522833063287139e+151, 6.0911478208424353e+247});
  const InvalidInput error = expect_invalid([&] { solve(m, 6.0); });
  EXPECT_EQ(error.parameter(), "ground_motion");
  EXPECT_NE(std::string(error.what()).find("closer than the engine's time resolution"),
            std::string::npos);
  m.ground_motion = record({0, 1e-16, 1}, {0.5, 0.5, 0.5});
  EXPECT_EQ(expect_invalid([&] { solve(m, 2.0); }).parameter(), "ground_motion");
  m.amplitude = 0;  // the rigid block
  EXPECT_EQ(solve(m, 2.0).summary.termination, Termination::reached_end);
}

// A ramp of 3e222 per second after a slip of 4.6e-4: the stop is 1e-112 s
// after the ramp starts, far inside one ulp of t, where the search's maximum
// of v rounds past the zero (found by fuzzing: the bracket then began where v
// was -5e183 and the slip "stopped" at the ramp's end, touch after touch until
// the cap). Now: the stop at the ramp's start, then the ramp throws the mass
// back; with the other forces 1e-220 of it, v at the ramp's end is the
// spring's response to the ramp, -(S/w^2)(1 - cos w u), to 1e-4 (damping
// c/m u = 7e-6).
TEST(GeneralRecord, SteepRampStopsAtItsStart) {
  Model m;
  m.mass = 10113;
  m.amplitude = 0.2;
  m.omega = 11;
  m.friction = 0.2;
  m.static_friction = 0.30000000000000004;
  m.stiffness = 5124;
  m.damping = 0.3;
  m.force_offset = 16;
  m.harmonics.push_back({7, 256, 1279});
  m.ground_motion = record({0.3, 0.55}, {8.3494804985847859e-309, 7.6813179677913809e+221});
  const double t_end = 1.1423973285781066;
  const Solution s = solve(m, t_end);
  testing::expect_well_formed(s, t_end);
  ASSERT_EQ(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::slip_forward);
  EXPECT_EQ(s.phases[0].t_end, 0.3);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::slip_backward);
  const long double w = sqrtl(5124.0L / 10113), slope = 7.6813179677913809e+221L / 0.25L;
  const long double v = -(slope / (w * w)) * (1 - cosl(w * 0.25L));
  EXPECT_NEAR(s.state_at(0.55 * (1 - 1e-15)).v / static_cast<double>(v), 1.0, 1e-4);
}

// A stick early in a long record interval (a ramp of a_g over 1284 s, the
// horizon at 2e-14 s): the stick's rounding margin came from the record's
// value at the interval's far end, 1e20 times rs^2, and every stick "broke
// away" one resolution after it began, a slip+ at a time (found by
// fuzzing). The breakaway is where N = m a_g' t + B sin(w t) reaches Rs.
TEST(GeneralRecord, StickEarlyInALongIntervalBreaksAwayWhereNReachesRs) {
  Model m;
  m.mass = 631612800000000;
  m.amplitude = 0.00063161279999999998;
  m.omega = 631612800000000;
  m.friction = 0.2;
  m.static_friction = 6.9;
  m.stiffness = 4;
  m.ground_motion = record({0, 1284}, {0, -6323300000000});
  const double t_end = 1.9895687063908729e-14;
  const Solution s = solve(m, t_end);
  testing::expect_well_formed(s, t_end);
  ASSERT_EQ(s.phases.size(), 2u);
  EXPECT_EQ(s.phases[0].kind, PhaseKind::stick);
  EXPECT_EQ(s.phases[1].kind, PhaseKind::slip_forward);
  // N(t) = (m 6.3233e12 / 1284 + B w) t to 1e-20 (sin(w t) = w t there).
  const long double rate =
      631612800000000.0L * 6323300000000.0L / 1284 + 0.00063161279999999998L * 631612800000000.0L;
  EXPECT_NEAR(s.phases[0].t_end / static_cast<double>(6.9L / rate), 1.0, 1e-12);
}

// One-way (Newmark's downslope block, never towards negative x) through the
// general laws: on a rigid block (a damper of 1e-200) they must agree with the
// rigid block's own one-way laws, within 4 ulps, on a noise record.
TEST(GeneralRecord, OneWayMeetsTheRigidBlockLaws) {
  std::vector<double> t, a;
  unsigned state = 777;
  for (int i = 0; i <= 600; ++i) {
    state = state * 1103515245u + 12345u;
    t.push_back(0.01 * i);
    a.push_back(3.0 * ((state >> 8) % 2001 / 1000.0 - 1.0) - 0.5);
  }
  Model rigid;
  rigid.amplitude = 0;
  rigid.friction = 0.8;
  rigid.static_friction = 1.0;
  rigid.one_way = true;
  rigid.ground_motion = record(t, a);
  const double t_end = 7;
  const Solution reference = solve(rigid, t_end);
  testing::expect_well_formed(reference, t_end);
  ASSERT_GT(reference.phases.size(), 20u);
  Model general = rigid;
  general.damping = 1e-200;
  const Solution s = solve(general, t_end);
  testing::expect_well_formed(s, t_end);
  ASSERT_EQ(s.phases.size(), reference.phases.size());
  for (std::size_t i = 0; i < s.phases.size(); ++i)
    EXPECT_NE(s.phases[i].kind, PhaseKind::slip_backward) << "phase " << i;
  EXPECT_LE(largest_event_difference(s, reference, 1e-14, 1e-14), 4)
      << "largest event-time difference, ulps";
}

// One-way with a spring: m = 1, k = 1, R = Rs = 1 under a_g = -3 on [0, 4),
// then 0. From rest N = 3 > 1: x'' + x = 2, x = 2 (1 - cos t) until v = 2 sin t
// = 0 at t = pi (x = 4); there N = 3 - 4 = -1, on the lower edge: two-way it
// would stay (|N| <= Rs); then at t = 4 a_g jumps to 0, N = -4: two-way the
// mass slides back, one-way it stays at x = 4 to the end.
TEST(GeneralRecord, OneWaySpringStaysWhereTwoWaySlidesBack) {
  Model m;
  m.amplitude = 0;
  m.friction = 1;
  m.stiffness = 1;
  m.ground_motion = record({0, 4}, {-3, -3});
  Model one_way = m;
  one_way.one_way = true;
  const Solution two = solve(m, 8.0), one = solve(one_way, 8.0);
  testing::expect_well_formed(two, 8.0);
  testing::expect_well_formed(one, 8.0);
  ASSERT_EQ(one.phases.size(), 2u);
  EXPECT_EQ(one.phases[0].kind, PhaseKind::slip_forward);
  EXPECT_LE(ulps(one.phases[0].t_end, M_PI), 4);
  EXPECT_NEAR(one.phases[0].x_end, 4.0, 4e-15);
  EXPECT_EQ(one.phases[1].kind, PhaseKind::stick);
  // Two-way: the same first slip and stick, then backwards from t = 4.
  ASSERT_GE(two.phases.size(), 3u);
  EXPECT_EQ(two.phases[0].t_end, one.phases[0].t_end);
  EXPECT_EQ(two.phases[1].kind, PhaseKind::stick);
  EXPECT_EQ(two.phases[1].t_end, 4.0);
  EXPECT_EQ(two.phases[2].kind, PhaseKind::slip_backward);
}

}  // namespace
}  // namespace frictionref
