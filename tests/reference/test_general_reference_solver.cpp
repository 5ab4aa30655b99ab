// Checks of the general 50-digit reference (general_reference_solver.hpp)
// against closed forms it does not use: free undamped, under-, critically and
// overdamped oscillators, the Coulomb free oscillator losing 2R/k per half
// cycle, a damper without spring, the secular growth at resonance, a forced
// frictionless spring across its reversals, the static-friction breakaway,
// a grazing dip inside a step, and independence of the Taylor step; with a
// ground record: the rigid block against the separate record reference
// (record_reference_solver.hpp), the spring under a ramp, the damped spring
// under a step of acceleration (frictionless, and with a stick broken by the
// record's jumps at t_0 and t_{n-1}), and independence of the Taylor step.
// No frictionref library code is involved (the engine is not linked).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>

#include "general_reference_solver.hpp"
#include "record_reference_solver.hpp"

namespace gref = frictionref_general_reference;
using gref::Kind;
using gref::Real;

namespace {

const Real kPi = boost::math::constants::pi<Real>();
const Real kTight("1e-44");

Real abs_r(const Real& v) { return boost::multiprecision::abs(v); }
Real exp_r(const Real& v) { return boost::multiprecision::exp(v); }
Real sin_r(const Real& v) { return boost::multiprecision::sin(v); }
Real cos_r(const Real& v) { return boost::multiprecision::cos(v); }
Real sqrt_r(const Real& v) { return boost::multiprecision::sqrt(v); }

// The rules of the model, phase by phase: continuity, v = 0 at every
// boundary, |N| <= Rs inside a stick and where a slip stops into one, |N| > Rs
// in the new direction where it goes on, a slip's speed slope <= 0 at its stop.
void expect_consistent(const gref::Result& r) {
  const auto& ph = r.phases;
  const gref::RealInput& in = r.model;
  ASSERT_FALSE(ph.empty());
  EXPECT_EQ(ph.front().t_begin, in.t0);
  EXPECT_EQ(ph.back().t_end, r.t_end);
  EXPECT_TRUE(ph.back().at_horizon);
  auto N = [&](const Real& t, const Real& x) { return in.force(t) - in.stiffness * x; };
  Real force_scale =
      1 + abs_r(in.force_offset) + in.static_friction + in.stiffness * (1 + abs_r(in.x0));
  for (const Real& a : in.record_a) force_scale += in.mass * abs_r(a);
  for (std::size_t i = 0; i < ph.size(); ++i) {
    const gref::Phase& p = ph[i];
    EXPECT_GT(p.t_end, p.t_begin) << "phase " << i;
    if (p.kind == Kind::stick) {
      EXPECT_EQ(p.x_begin, p.x_end);
      const Real mid = (p.t_begin + p.t_end) / 2;
      EXPECT_LE(abs_r(N(mid, p.x_begin)), in.static_friction * (1 + kTight)) << "phase " << i;
    }
    if (i + 1 == ph.size()) break;
    const gref::Phase& q = ph[i + 1];
    EXPECT_FALSE(p.at_horizon);
    EXPECT_EQ(p.t_end, q.t_begin) << "phase " << i;
    EXPECT_EQ(p.x_end, q.x_begin) << "phase " << i;
    EXPECT_EQ(p.v_end, 0) << "phase " << i;
    EXPECT_EQ(q.v_begin, 0) << "phase " << i;
    const Real n_end = N(p.t_end, p.x_end);
    if (p.kind == Kind::stick && p.at_record_jump) {
      // The record's jump at t_0 or t_{n-1} took |N| (right limit) past Rs.
      EXPECT_NE(q.kind, Kind::stick);
      EXPECT_TRUE(p.t_end == in.record_t.front() || p.t_end == in.record_t.back())
          << "breakaway " << i;
      EXPECT_GT(abs_r(n_end), in.static_friction) << "breakaway " << i;
      EXPECT_EQ(gref::sign_of(q.kind), n_end > 0 ? 1 : -1) << "breakaway " << i;
    } else if (p.kind == Kind::stick) {
      EXPECT_NE(q.kind, Kind::stick);
      EXPECT_NEAR(static_cast<double>(abs_r(n_end) - in.static_friction), 0,
                  1e-40 * static_cast<double>(force_scale))
          << "breakaway " << i;
      EXPECT_EQ(gref::sign_of(q.kind), n_end > 0 ? 1 : -1) << "breakaway " << i;
    } else {
      EXPECT_LE(p.slope_end, Real("1e-40") * force_scale / in.mass) << "stop " << i;
      if (q.kind == Kind::stick) {
        EXPECT_LE(abs_r(n_end), in.static_friction * (1 + kTight)) << "stop " << i;
      } else {
        EXPECT_GT(abs_r(n_end), in.static_friction) << "stop " << i;
        EXPECT_EQ(gref::sign_of(q.kind), n_end > 0 ? 1 : -1) << "stop " << i;
      }
    }
  }
}

std::vector<Real> event_times(const gref::Result& r) {
  std::vector<Real> t;
  for (std::size_t i = 0; i + 1 < r.phases.size(); ++i) t.push_back(r.phases[i].t_end);
  return t;
}

gref::RealInput unforced(const Real& m, const Real& k, const Real& c) {
  gref::RealInput in;
  in.mass = m;
  in.stiffness = k;
  in.damping = c;
  in.terms.push_back({Real(0), Real(1), Real(0)});
  return in;
}

}  // namespace

// m x'' + k x = 0 from x0 = 1 at rest, R = Rs = 0: reversals at n pi / wn,
// x = (-1)^n there, and the state at the horizon is cos, -wn sin.
TEST(GeneralReferenceSolver, FreeUndampedOscillator) {
  gref::RealInput in = unforced(2, 3, 0);
  in.x0 = 1;
  const Real wn = sqrt_r(Real(3) / 2);
  const Real t_end = 40;
  const gref::Result r = gref::solve(in, t_end);
  expect_consistent(r);
  const auto t = event_times(r);
  ASSERT_EQ(t.size(), static_cast<std::size_t>(boost::multiprecision::floor(t_end * wn / kPi)));
  for (std::size_t n = 0; n < t.size(); ++n) {
    EXPECT_LT(abs_r(t[n] - Real(n + 1) * kPi / wn), kTight) << n;
    EXPECT_LT(abs_r(r.phases[n].x_end - (n % 2 == 0 ? -1 : 1)), kTight) << n;
  }
  EXPECT_LT(abs_r(r.phases.back().x_end - cos_r(wn * t_end)), kTight);
  EXPECT_LT(abs_r(r.phases.back().v_end + wn * sin_r(wn * t_end)), kTight);
}

// Underdamped (zeta = 0.1): from rest at x0 = 1, v = 0 at n pi / wd, where
// x = (-1)^n exp(-sigma n pi / wd).
TEST(GeneralReferenceSolver, UnderdampedFreeOscillator) {
  gref::RealInput in = unforced(1, 4, Real(2) / 5);
  in.x0 = 1;
  const Real sigma = Real(1) / 5, wd = sqrt_r(4 - sigma * sigma);
  const gref::Result r = gref::solve(in, Real(30));
  expect_consistent(r);
  const auto t = event_times(r);
  ASSERT_GE(t.size(), 15u);
  for (std::size_t n = 0; n < t.size(); ++n) {
    const Real tn = Real(n + 1) * kPi / wd;
    EXPECT_LT(abs_r(t[n] - tn), kTight) << n;
    const Real xn = (n % 2 == 0 ? -1 : 1) * exp_r(-sigma * tn);
    EXPECT_LT(abs_r(r.phases[n].x_end - xn), kTight) << n;
  }
}

// Critically (c = 4) and overdamped (c = 5) with k = 4, m = 1 from x0 = 1 at
// rest: one slip backward that never stops; the state at the horizon is
// (1 + 2t) e^(-2t), -4t e^(-2t), resp. (4 e^(-t) - e^(-4t)) / 3, -(4/3)(e^(-t) - e^(-4t)).
TEST(GeneralReferenceSolver, CriticallyAndOverdampedApproachWithoutStop) {
  for (const int c : {4, 5}) {
    gref::RealInput in = unforced(1, 4, c);
    in.x0 = 1;
    const Real T = 7;
    const gref::Result r = gref::solve(in, T);
    expect_consistent(r);
    ASSERT_EQ(r.phases.size(), 1u) << "c = " << c;
    EXPECT_EQ(r.phases[0].kind, Kind::slip_backward);
    Real x = 0, v = 0;
    if (c == 4) {
      x = (1 + 2 * T) * exp_r(-2 * T);
      v = -4 * T * exp_r(-2 * T);
    } else {
      x = (4 * exp_r(-T) - exp_r(-4 * T)) / 3;
      v = -Real(4) / 3 * (exp_r(-T) - exp_r(-4 * T));
    }
    EXPECT_LT(abs_r(r.phases[0].x_end - x), kTight) << "c = " << c;
    EXPECT_LT(abs_r(r.phases[0].v_end - v), kTight) << "c = " << c;
  }
}

// Nearly critical damping, c = 2 sqrt(k m) (1 - 1e-30): still one slip, the
// state at the horizon within 1e-28 of the critical closed form.
TEST(GeneralReferenceSolver, NearlyCriticalDampingIsContinuous) {
  gref::RealInput in = unforced(1, 4, 4 * (1 - Real("1e-30")));
  in.x0 = 1;
  const Real T = 5;
  const gref::Result r = gref::solve(in, T);
  ASSERT_EQ(r.phases.size(), 1u);
  EXPECT_LT(abs_r(r.phases[0].x_end - (1 + 2 * T) * exp_r(-2 * T)), Real("1e-28"));
}

// Coulomb free oscillator (m = k = 1, R = 0.1, Rs = 0.25, x0 = 1.02): half
// cycles of pi, each losing 2R/k of amplitude, until |k x| <= Rs at a stop:
// 1.02 -> -0.82 -> 0.62 -> -0.42 -> 0.22, then stuck for good.
TEST(GeneralReferenceSolver, CoulombFreeOscillatorLoses2RPerHalfCycle) {
  gref::RealInput in = unforced(1, 1, 0);
  in.friction = Real(0.1);
  in.static_friction = Real(0.25);
  in.x0 = Real(1.02);
  const gref::Result r = gref::solve(in, Real(20));
  expect_consistent(r);
  ASSERT_EQ(r.phases.size(), 5u);
  Real amplitude = in.x0;
  for (std::size_t n = 0; n < 4; ++n) {
    EXPECT_EQ(r.phases[n].kind, n % 2 == 0 ? Kind::slip_backward : Kind::slip_forward);
    EXPECT_LT(abs_r(r.phases[n].t_end - Real(n + 1) * kPi), kTight) << n;
    amplitude -= 2 * in.friction / in.stiffness;
    EXPECT_LT(abs_r(abs_r(r.phases[n].x_end) - amplitude), kTight) << n;
  }
  EXPECT_EQ(r.phases[4].kind, Kind::stick);
  EXPECT_LT(abs_r(r.phases[4].x_end - (in.x0 - 8 * in.friction / in.stiffness)), kTight);
}

// k = 0, c > 0, constant force F0 < R: v relaxes towards (F0 - R)/c < 0, so
// the slip stops at t = (m/c) ln((v0 - vt)/(-vt)), x there from the integral,
// and sticks for good since |F0| <= Rs.
TEST(GeneralReferenceSolver, DamperWithoutSpringStopsAtTheLogarithmicTime) {
  gref::RealInput in = unforced(Real(1.5), 0, Real(0.8));
  in.friction = Real(0.5);
  in.static_friction = Real(0.6);
  in.force_offset = Real(0.3);
  in.v0 = 2;
  in.t0 = Real(0.25);
  const gref::Result r = gref::solve(in, Real(10));
  expect_consistent(r);
  ASSERT_EQ(r.phases.size(), 2u);
  const Real vt = (in.force_offset - in.friction) / in.damping;
  const Real tau = in.mass / in.damping;
  const Real ts = in.t0 + tau * boost::multiprecision::log((in.v0 - vt) / (-vt));
  EXPECT_LT(abs_r(r.phases[0].t_end - ts), kTight);
  const Real xs = vt * (ts - in.t0) + (in.v0 - vt) * tau * (1 - exp_r(-(ts - in.t0) / tau));
  EXPECT_LT(abs_r(r.phases[0].x_end - xs), kTight);
  EXPECT_EQ(r.phases[1].kind, Kind::stick);
}

// Resonance without damping or friction: m = k = B = w = 1 from rest at 0,
// x = (sin t - t cos t) / 2, v = t sin t / 2: reversals at n pi with
// x = (-1)^(n+1) n pi / 2, the secular growth.
TEST(GeneralReferenceSolver, ResonanceGrowsSecularly) {
  gref::RealInput in;
  in.stiffness = 1;
  in.terms.push_back({Real(1), Real(1), Real(0)});
  const gref::Result r = gref::solve(in, Real(64));
  expect_consistent(r);
  const auto t = event_times(r);
  ASSERT_EQ(t.size(), 20u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Real n = Real(i + 1);
    EXPECT_LT(abs_r(t[i] - n * kPi), kTight * n) << i;
    EXPECT_LT(abs_r(r.phases[i].x_end - (i % 2 == 0 ? 1 : -1) * n * kPi / 2), kTight * n) << i;
  }
}

// A forced frictionless spring (k = 4, B = 1, w = 1, a second harmonic
// 0.5 sin(3t + 1), F0 = 0.2) from x0 = 0.1, v0 = 1, t0 = 0.5: reversals do not
// change the motion (R = 0), so the state at every event and at the horizon is
// the linear closed form, and v = 0 at every event.
TEST(GeneralReferenceSolver, ForcedFrictionlessSpringIsTheLinearSolution) {
  gref::RealInput in;
  in.stiffness = 4;
  in.force_offset = Real(0.2);
  in.terms.push_back({Real(1), Real(1), Real(0)});
  in.terms.push_back({Real(0.5), Real(3), Real(1)});
  in.x0 = Real(0.1);
  in.v0 = 1;
  in.t0 = Real(0.5);
  const Real wn = 2;
  // Particular: F0/k + sum a_j sin(q t + p) / (k - q^2); homogeneous fits (x0, v0) at t0.
  auto particular = [&](const Real& t, Real& x, Real& v) {
    x = in.force_offset / in.stiffness;
    v = 0;
    for (const auto& term : in.terms) {
      const Real gain = term.amplitude / (in.stiffness - term.omega * term.omega);
      x += gain * sin_r(term.omega * t + term.phase);
      v += gain * term.omega * cos_r(term.omega * t + term.phase);
    }
  };
  Real xp0, vp0;
  particular(in.t0, xp0, vp0);
  const Real A = in.x0 - xp0, Bh = (in.v0 - vp0) / wn;
  auto exact = [&](const Real& t, Real& x, Real& v) {
    particular(t, x, v);
    x += A * cos_r(wn * (t - in.t0)) + Bh * sin_r(wn * (t - in.t0));
    v += wn * (-A * sin_r(wn * (t - in.t0)) + Bh * cos_r(wn * (t - in.t0)));
  };
  const gref::Result r = gref::solve(in, Real(30));
  expect_consistent(r);
  ASSERT_GE(r.phases.size(), 15u);
  for (const gref::Phase& p : r.phases) {
    EXPECT_NE(p.kind, Kind::stick);
    Real x, v;
    exact(p.t_end, x, v);
    EXPECT_LT(abs_r(p.x_end - x), kTight);
    EXPECT_LT(abs_r(p.v_end - v), kTight);
  }
}

// The seed's model with static friction (B = 1, R = 0.3, Rs = 0.6) from rest
// at 0: stuck until sin t = Rs, then the slip v = cos tb - cos t - R (t - tb),
// which ends where that closed form is 0.
TEST(GeneralReferenceSolver, StaticFrictionBreakawayAndSeedClosedForm) {
  gref::RealInput in;
  in.friction = Real(0.3);
  in.static_friction = Real(0.6);
  in.terms.push_back({Real(1), Real(1), Real(0)});
  const gref::Result r = gref::solve(in, Real(30));
  expect_consistent(r);
  ASSERT_GE(r.phases.size(), 3u);
  EXPECT_EQ(r.phases[0].kind, Kind::stick);
  const Real tb = boost::multiprecision::asin(in.static_friction);
  EXPECT_LT(abs_r(r.phases[0].t_end - tb), kTight);
  ASSERT_EQ(r.phases[1].kind, Kind::slip_forward);
  const Real ts = r.phases[1].t_end;
  const Real v_closed = cos_r(tb) - cos_r(ts) - in.friction * (ts - tb);
  EXPECT_LT(abs_r(v_closed), kTight);
  const Real x_closed = (ts - tb) * cos_r(tb) - (sin_r(ts) - sin_r(tb)) -
                        in.friction * (ts - tb) * (ts - tb) / 2;
  EXPECT_LT(abs_r(r.phases[1].x_end - x_closed), kTight);
}

// The seed's model (R = Rs = 0.5) with v0 chosen in 50 digits so that v dips
// to -1e-30 at its minimum t* = pi/6 (inside a Taylor step): a stop, a stick
// of ~1e-15, the breakaway at pi/6. With +1e-30 there is no stop at all.
TEST(GeneralReferenceSolver, FindsAGrazingDipInsideAStep) {
  for (const int sign : {-1, 1}) {
    gref::RealInput in;
    in.friction = in.static_friction = Real(0.5);
    in.terms.push_back({Real(1), Real(1), Real(0)});
    const Real t_star = kPi / 6;
    in.v0 = cos_r(t_star) + in.friction * t_star - 1 + sign * Real("1e-30");
    const gref::Result r = gref::solve(in, Real(2));
    expect_consistent(r);
    if (sign > 0) {
      ASSERT_EQ(r.phases.size(), 1u);
      continue;
    }
    ASSERT_EQ(r.phases.size(), 3u);
    EXPECT_EQ(r.phases[1].kind, Kind::stick);
    EXPECT_LT(r.phases[1].duration(), Real("1e-14"));
    EXPECT_GT(r.phases[1].duration(), Real("1e-16"));
    EXPECT_LT(abs_r(r.phases[1].t_end - t_star), kTight);
  }
}

// Every feature at once; Taylor steps of 1/2, 1/7 and 1/20 of 1/Omega give
// the same events to 1e-42 (the truncation bound and the scan do not depend
// on where the steps fall).
TEST(GeneralReferenceSolver, IndependentOfTheTaylorStep) {
  gref::Input in;
  in.mass = 1.5;
  in.amplitude = 1;
  in.omega = 1.3;
  in.friction = 0.25;
  in.static_friction = 0.4;
  in.stiffness = 2;
  in.damping = 0.3;
  in.force_offset = 0.1;
  in.harmonics = {{0.4, 2.9, 0.7}, {-0.3, 0.45, -2}};
  in.v0 = -0.5;
  in.t0 = 3.25;
  std::vector<std::vector<Real>> runs;
  for (const Real& fraction : {Real(1) / 2, Real(1) / 7, Real(1) / 20}) {
    gref::Options options;
    options.step_fraction = fraction;
    const gref::Result r = gref::solve(gref::RealInput::from_double(in), Real(43.25), options);
    expect_consistent(r);
    runs.push_back(event_times(r));
  }
  ASSERT_GE(runs[0].size(), 10u);
  for (std::size_t j = 1; j < runs.size(); ++j) {
    ASSERT_EQ(runs[j].size(), runs[0].size());
    for (std::size_t i = 0; i < runs[0].size(); ++i)
      EXPECT_LT(abs_r(runs[j][i] - runs[0][i]), Real("1e-42")) << j << " " << i;
  }
}

// The truncation bound is what makes the scan rigorous: it must be far below
// the 50-digit rounding on every step.
TEST(GeneralReferenceSolver, TruncationBoundBelowRounding) {
  gref::Input in;
  in.stiffness = 9;
  in.damping = 6.5;
  in.friction = 0.2;
  in.harmonics = {{2, 5, 0.3}};
  in.v0 = 3;
  const gref::Result r = gref::solve(in, 30);
  EXPECT_LT(r.max_truncation, Real("1e-55"));
  EXPECT_LE(r.max_degree, 80u);
}

// ---------------------------------------------------------------------------
// Ground records: m x'' + c x' + k x = F(t) - m a_g(t) - f, a_g linear between
// the samples, 0 before t_0 and from t_{n-1} on.

namespace {

struct BlockCase {
  const char* name;
  std::vector<double> t, a;
  double mass, offset, friction, static_friction, x0, v0, t0, t_end;
};

// The rigid block (k = c = 0, no harmonic): the general reference against
// the separate record reference (exact segment integrals and quadratic
// roots): the same phases, event times and positions to 1e-40.
void expect_matches_record_reference(const BlockCase& c, std::size_t min_events) {
  SCOPED_TRACE(c.name);
  gref::Input in;
  in.mass = c.mass;
  in.amplitude = 0;
  in.friction = c.friction;
  in.static_friction = c.static_friction;
  in.force_offset = c.offset;
  in.record_t = c.t;
  in.record_a = c.a;
  in.x0 = c.x0;
  in.v0 = c.v0;
  in.t0 = c.t0;
  const gref::Result r = gref::solve(in, c.t_end);
  expect_consistent(r);

  frictionref_reference::RecordBlock block;
  block.t = c.t;
  block.a = c.a;
  block.offset = c.offset / c.mass;
  block.mu = c.friction / c.mass;
  block.mu_static = c.static_friction / c.mass;
  // The per-mass fields must be the same numbers (mass a power of 2).
  ASSERT_EQ(block.offset * c.mass, c.offset);
  ASSERT_EQ(block.mu * c.mass, c.friction);
  ASSERT_EQ(block.mu_static * c.mass, c.static_friction);
  block.t0 = c.t0;
  block.x0 = c.x0;
  block.v0 = c.v0;
  const auto events = frictionref_reference::solve_record_block(block, c.t_end);

  ASSERT_GE(events.size(), min_events);
  ASSERT_EQ(r.phases.size(), events.size() + 1);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const gref::Phase& p = r.phases[i];
    const Real scale = abs_r(events[i].t) > 1 ? abs_r(events[i].t) : Real(1);
    EXPECT_LT(abs_r(p.t_end - Real(events[i].t)), Real("1e-40") * scale) << "event " << i;
    EXPECT_LT(abs_r(p.x_end - Real(events[i].x)), Real("1e-40") * (1 + abs_r(p.x_end)))
        << "event " << i;
    EXPECT_EQ(gref::sign_of(r.phases[i + 1].kind), events[i].kind_after) << "event " << i;
  }
}

}  // namespace

TEST(GeneralReferenceSolverRecord, RigidBlockMatchesTheRecordReference) {
  // Stuck until t_0, where the jump of a_g (N = 0.125 - 0.8) breaks it away
  // backward; the record's end (a second jump) inside a stick or a slip.
  expect_matches_record_reference({"jump start",
                                   {0.5, 1.25, 2, 3.5, 4},
                                   {0.8, -1.5, 1.2, -0.6, 0.9},
                                   1, 0.125, 0.25, 0.375, 0, 0, 0, 8},
                                  4);
  // Starting inside the record with v0 != 0, m = 2.
  expect_matches_record_reference({"inside, moving",
                                   {-1, 0.75, 1.5, 2.25, 3},
                                   {0.3, 1.1, -0.9, 0.5, -0.2},
                                   2, 0.25, 0.5, 0.75, 0.1, 0.3, 0.25, 6},
                                  3);
  // Stuck inside the record (|N| <= Rs) until its end, where a_g jumps to 0
  // and N = F0 > Rs: a breakaway forward at exactly t_{n-1}.
  expect_matches_record_reference(
      {"end jump", {0, 1, 2}, {0.5, 0.625, 0.375}, 1, 0.625, 0.375, 0.5, 0, 0, 0.5, 4}, 1);
  // A sampled two-tone signal, 161 samples: stops, sticks and breakaways.
  BlockCase tones{"two tones", {}, {}, 1, 0.05, 0.8, 1.05, 0, 0, 0, 7};
  for (int i = 0; i <= 160; ++i) {
    const double t = 0.25 + i / 32.0;
    tones.t.push_back(t);
    tones.a.push_back(1.5 * std::sin(2.5 * t) + 0.4 * std::sin(7 * t));
  }
  expect_matches_record_reference(tones, 6);
}

// R = Rs = 0, m = 1, k = 4 from rest at 0, t0 = 0; a_g a single ramp
// a0 + q (t - t_0) on [t_0, t_1) = [0.25, 4.25) (a0 = -0.5, q = 0.45), 0
// elsewhere. At rest until t_0, where N jumps to 0.5: a breakaway forward at
// exactly t_0. Then x'' + 4 x = -(a0 + q tau), tau = t - t_0, from rest:
//   x = -(a0 + q tau)/k + (a0/k) cos(wn tau) + q/(k wn) sin(wn tau),
// and after t_1 the free oscillation from the state there; the reversals do
// not change the motion (R = 0).
TEST(GeneralReferenceSolverRecord, SpringUnderARampIsTheLinearSolution) {
  gref::RealInput in = unforced(1, 4, 0);
  in.record_t = {Real(0.25), Real(4.25)};
  in.record_a = {Real(-0.5), Real(1.3)};
  const Real k = in.stiffness, wn = 2, t_0 = in.record_t[0], t_1 = in.record_t[1];
  const Real a0 = in.record_a[0], q = (in.record_a[1] - a0) / (t_1 - t_0);
  auto ramp = [&](const Real& tau, Real& x, Real& v) {
    x = -(a0 + q * tau) / k + a0 / k * cos_r(wn * tau) + q / (k * wn) * sin_r(wn * tau);
    v = -q / k - a0 * wn / k * sin_r(wn * tau) + q / k * cos_r(wn * tau);
  };
  Real x1, v1;
  ramp(t_1 - t_0, x1, v1);
  auto exact = [&](const Real& t, Real& x, Real& v) {
    if (t < t_0) {
      x = v = 0;
    } else if (t < t_1) {
      ramp(t - t_0, x, v);
    } else {
      const Real s = t - t_1;
      x = x1 * cos_r(wn * s) + v1 / wn * sin_r(wn * s);
      v = -x1 * wn * sin_r(wn * s) + v1 * cos_r(wn * s);
    }
  };
  const gref::Result r = gref::solve(in, Real(7));
  expect_consistent(r);
  ASSERT_GE(r.phases.size(), 5u);
  EXPECT_EQ(r.phases[0].kind, Kind::stick);
  EXPECT_EQ(r.phases[0].t_end, t_0);
  EXPECT_TRUE(r.phases[0].at_record_jump);
  EXPECT_EQ(r.phases[1].kind, Kind::slip_forward);
  EXPECT_EQ(r.phases[1].start, gref::Start::breakaway);
  for (std::size_t i = 1; i < r.phases.size(); ++i) {
    const gref::Phase& p = r.phases[i];
    EXPECT_NE(p.kind, Kind::stick) << i;
    Real x, v;
    exact(p.t_end, x, v);
    EXPECT_LT(abs_r(p.x_end - x), Real("1e-40")) << i;
    EXPECT_LT(abs_r(p.v_end - v), Real("1e-40")) << i;  // v = 0 at the events
  }
}

namespace {

// The damped oscillator (m, c, k; sigma = c/2m, wn^2 = k/m, wd = sqrt(wn^2 -
// sigma^2)) under a constant force, through its equilibrium x_e: released
// from rest at x_a, x = x_e + (x_a - x_e) e^(-sigma tau)(cos wd tau + sigma/wd
// sin wd tau), v = -(x_a - x_e) (wn^2/wd) e^(-sigma tau) sin wd tau.
struct DampedStep {
  Real sigma, wd, wn2;
  void state(const Real& x_a, const Real& x_e, const Real& tau, Real& x, Real& v) const {
    const Real decay = exp_r(-sigma * tau);
    x = x_e + (x_a - x_e) * decay * (cos_r(wd * tau) + sigma / wd * sin_r(wd * tau));
    v = -(x_a - x_e) * wn2 / wd * decay * sin_r(wd * tau);
  }
  // Free from (x1, v1) towards x_e.
  void free(const Real& x1, const Real& v1, const Real& x_e, const Real& s, Real& x,
            Real& v) const {
    const Real decay = exp_r(-sigma * s), y = x1 - x_e;
    x = x_e + decay * (y * cos_r(wd * s) + (v1 + sigma * y) / wd * sin_r(wd * s));
    v = decay * (v1 * cos_r(wd * s) - (wn2 * y + sigma * v1) / wd * sin_r(wd * s));
  }
};

}  // namespace

// R = Rs = 0, m = 1.5, c = 0.9, k = 6 from rest at 0; a_g = A = 0.8 on
// [0.5, 3.5) (two samples), 0 elsewhere: the step response towards
// x_e = -m A / k, then the free decay from the state at t_1 = 3.5 (the jump
// back to 0 is a jump of the force, the state is continuous).
TEST(GeneralReferenceSolverRecord, DampedSpringStepResponse) {
  gref::RealInput in = unforced(Real(1.5), 6, Real(0.9));
  in.record_t = {Real(0.5), Real(3.5)};
  in.record_a = {Real(0.8), Real(0.8)};
  const Real m = in.mass, k = in.stiffness, A = in.record_a[0];
  const Real t_0 = in.record_t[0], t_1 = in.record_t[1];
  DampedStep d;
  d.sigma = in.damping / (2 * m);
  d.wn2 = k / m;
  d.wd = sqrt_r(d.wn2 - d.sigma * d.sigma);
  const Real x_e = -m * A / k;
  Real x1, v1;
  d.state(0, x_e, t_1 - t_0, x1, v1);
  auto exact = [&](const Real& t, Real& x, Real& v) {
    if (t < t_0) {
      x = v = 0;
    } else if (t < t_1) {
      d.state(0, x_e, t - t_0, x, v);
    } else {
      d.free(x1, v1, 0, t - t_1, x, v);
    }
  };
  const gref::Result r = gref::solve(in, Real(9));
  expect_consistent(r);
  ASSERT_GE(r.phases.size(), 5u);
  EXPECT_EQ(r.phases[0].t_end, t_0);
  EXPECT_TRUE(r.phases[0].at_record_jump);
  EXPECT_EQ(r.phases[1].kind, Kind::slip_backward);
  // The first stop of the step response at tau = pi / wd.
  EXPECT_LT(abs_r(r.phases[1].t_end - (t_0 + kPi / d.wd)), kTight);
  for (std::size_t i = 1; i < r.phases.size(); ++i) {
    const gref::Phase& p = r.phases[i];
    EXPECT_NE(p.kind, Kind::stick) << i;
    Real x, v;
    exact(p.t_end, x, v);
    EXPECT_LT(abs_r(p.x_end - x), Real("1e-40")) << i;
    EXPECT_LT(abs_r(p.v_end - v), Real("1e-40")) << i;
  }
}

// With friction (m = 1, c = 0.3, k = 2, R = 0.2, Rs = 0.3, F0 = 0.1) and
// a_g = 0.7 on [1.5, 6): stuck at 0 (|N| = 0.1) until the jump at t_0 = 1.5
// makes N = -0.6, a breakaway backward at exactly t_0; the slip is the step
// response towards x_e = (F0 - m A + R)/k and stops at t_0 + pi/wd, where
// |N| <= Rs: stuck until the jump back at t_1 = 6 makes |N| > Rs, a breakaway
// forward at exactly t_1, a step response towards (F0 - R)/k, a stop at
// t_1 + pi/wd and a stick to the horizon.
TEST(GeneralReferenceSolverRecord, RecordJumpsBreakAStickAtTheSampleTimes) {
  gref::RealInput in = unforced(1, 2, Real(0.3));
  in.friction = Real(0.2);
  in.static_friction = Real(0.3);
  in.force_offset = Real(0.1);
  in.record_t = {Real(1.5), Real(6)};
  in.record_a = {Real(0.7), Real(0.7)};
  const Real m = in.mass, k = in.stiffness, A = in.record_a[0], R = in.friction;
  const Real F0 = in.force_offset, t_0 = in.record_t[0], t_1 = in.record_t[1];
  DampedStep d;
  d.sigma = in.damping / (2 * m);
  d.wn2 = k / m;
  d.wd = sqrt_r(d.wn2 - d.sigma * d.sigma);
  const gref::Result r = gref::solve(in, Real(10));
  expect_consistent(r);
  ASSERT_EQ(r.phases.size(), 5u);
  const Kind kinds[] = {Kind::stick, Kind::slip_backward, Kind::stick, Kind::slip_forward,
                        Kind::stick};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(r.phases[i].kind, kinds[i]) << i;
  EXPECT_EQ(r.phases[0].t_end, t_0);
  EXPECT_TRUE(r.phases[0].at_record_jump);
  EXPECT_EQ(r.phases[1].start, gref::Start::breakaway);
  const Real half = kPi / d.wd;
  const Real x_e1 = (F0 - m * A + R) / k;
  Real xs1, vs1;
  d.state(0, x_e1, half, xs1, vs1);
  EXPECT_LT(abs_r(r.phases[1].t_end - (t_0 + half)), kTight);
  EXPECT_LT(abs_r(r.phases[1].x_end - xs1), kTight);
  EXPECT_EQ(r.phases[2].t_end, t_1);
  EXPECT_TRUE(r.phases[2].at_record_jump);
  EXPECT_EQ(r.phases[3].start, gref::Start::breakaway);
  const Real x_e2 = (F0 - R) / k;
  Real xs2, vs2;
  d.state(xs1, x_e2, half, xs2, vs2);
  EXPECT_LT(abs_r(r.phases[3].t_end - (t_1 + half)), kTight);
  EXPECT_LT(abs_r(r.phases[3].x_end - xs2), kTight);
  EXPECT_TRUE(r.phases[4].at_horizon);
}

// Every feature with a record (41 samples on [1, 11], jumps at both ends;
// slips, stops, sticks, breakaways): Taylor steps of 1/2 and 1/9 of 1/Omega
// give the same events to 1e-42.
TEST(GeneralReferenceSolverRecord, IndependentOfTheTaylorStep) {
  gref::Input in;
  in.mass = 1.25;
  in.amplitude = 0.6;
  in.omega = 1.7;
  in.friction = 0.8;
  in.static_friction = 1;
  in.stiffness = 1.5;
  in.damping = 0.2;
  in.force_offset = 0.05;
  in.harmonics = {{0.3, 3.1, 0.4}};
  for (int i = 0; i <= 40; ++i) {
    const double t = 1 + i / 4.0;
    in.record_t.push_back(t);
    in.record_a.push_back(0.9 * std::sin(1.3 * t) + 0.5 * std::cos(4.1 * t) + 0.2);
  }
  in.t0 = 0.5;
  std::vector<std::vector<Real>> runs;
  for (const Real& fraction : {Real(1) / 2, Real(1) / 9}) {
    gref::Options options;
    options.step_fraction = fraction;
    const gref::Result r = gref::solve(gref::RealInput::from_double(in), Real(14), options);
    expect_consistent(r);
    runs.push_back(event_times(r));
  }
  ASSERT_GE(runs[0].size(), 8u);
  ASSERT_EQ(runs[1].size(), runs[0].size());
  for (std::size_t i = 0; i < runs[0].size(); ++i)
    EXPECT_LT(abs_r(runs[1][i] - runs[0][i]), Real("1e-42")) << i;
}

TEST(GeneralReferenceSolverRecord, RejectsBadRecords) {
  gref::Input in;
  in.record_t = {0, 1, 2};
  in.record_a = {0.1, 0.2, 0.3};
  EXPECT_NO_THROW(gref::solve(in, 3));
  auto rejects = [&](const std::vector<double>& t, const std::vector<double>& a) {
    gref::Input bad = in;
    bad.record_t = t;
    bad.record_a = a;
    EXPECT_THROW(gref::solve(bad, 3), std::invalid_argument);
  };
  rejects({0, 1}, {0.1, 0.2, 0.3});                // lengths differ
  rejects({1}, {0.1});                             // one sample
  rejects({0, 1, 1}, {0.1, 0.2, 0.3});             // not strictly increasing
  rejects({0, 2, 1}, {0.1, 0.2, 0.3});             // decreasing
  rejects({0, 1, 2}, {0.1, std::nan(""), 0.3});    // non-finite
  rejects({0, 1, HUGE_VAL}, {0.1, 0.2, 0.3});      // non-finite
}
