// Checks of the 50-digit reference solver itself, against closed forms and
// properties it does not use: the continuous-regime periodic orbit, the
// frictionless motion, the single stop for lambda > 1, B = 0, the ODE by
// finite differences, mirror symmetry, independence of the scan step, and
// grazing zeros that a plain sign-test scan would miss.
// No frictionref library code is involved (the engine is not linked).
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>

#include "reference_solver.hpp"

namespace ref = frictionref_reference;
using ref::Kind;
using ref::Real;

namespace {

const Real kPi = boost::math::constants::pi<Real>();

Real abs_r(const Real& v) { return boost::multiprecision::abs(v); }

// Every phase's end state is the next phase's start; stops have v = 0; the
// closed form at each stop gives |v| at the 50-digit noise level; a stick
// only where |B sin(w t)| <= R; a slip keeps s v > 0 inside.
void expect_consistent(const ref::Result& r, const Real& tolerance = Real("1e-44")) {
  const auto& ph = r.phases;
  ASSERT_FALSE(ph.empty());
  EXPECT_EQ(ph.front().t_begin, r.model.t0);
  EXPECT_EQ(ph.back().t_end, r.t_end);
  EXPECT_TRUE(ph.back().at_horizon);
  const Real scale = 1 + abs_r(r.model.v0) +
                     r.model.amplitude / (r.model.mass * r.model.omega) *
                         (1 + r.model.omega * abs_r(r.t_end));
  for (std::size_t i = 0; i < ph.size(); ++i) {
    const ref::Phase& p = ph[i];
    EXPECT_GT(p.t_end, p.t_begin) << "phase " << i;
    if (i + 1 < ph.size()) {
      const ref::Phase& q = ph[i + 1];
      EXPECT_EQ(p.t_end, q.t_begin) << "phase " << i;
      EXPECT_EQ(p.x_end, q.x_begin) << "phase " << i;
      EXPECT_EQ(p.v_end, 0) << "phase " << i;
      EXPECT_EQ(q.v_begin, 0) << "phase " << i;
      EXPECT_FALSE(p.at_horizon);
      if (p.kind != Kind::stick) {
        const ref::StateR at_stop = ref::evaluate(r.model, p, p.t_end);
        EXPECT_LT(abs_r(at_stop.v), tolerance * scale) << "phase " << i;
      }
      if (p.kind == Kind::stick) {
        EXPECT_NE(q.kind, Kind::stick);
      }
    }
    const Real mid = (p.t_begin + p.t_end) / 2;
    const ref::StateR s = ref::evaluate(r.model, p, mid);
    if (p.kind == Kind::stick) {
      EXPECT_LE(abs_r(r.model.amplitude * boost::multiprecision::sin(r.model.omega * mid)),
                r.model.friction)
          << "phase " << i;
    } else {
      EXPECT_GT(Real(ref::sign_of(p.kind)) * s.v, 0) << "phase " << i;
    }
  }
}

std::vector<Real> event_times(const ref::Result& r) {
  std::vector<Real> t;
  for (std::size_t i = 0; i + 1 < r.phases.size(); ++i) t.push_back(r.phases[i].t_end);
  return t;
}

}  // namespace

// lambda = 0.3 < lambda*: the symmetric periodic slip reverses where
// cos(tau) = lambda pi / 2. Started exactly on it (50 digits), every stop
// comes pi later than the previous one, with no stick.
TEST(ReferenceSolver, PeriodicOrbitContinuousRegime) {
  ref::RealInput in;
  in.friction = Real(3) / 10;
  const Real tau1 = boost::multiprecision::acos(in.friction * kPi / 2);
  in.t0 = tau1;
  in.v0 = 0;
  const ref::Result r = ref::solve(in, tau1 + 200 * kPi + 1);
  expect_consistent(r);
  ASSERT_EQ(r.phases.size(), 201u);
  for (std::size_t k = 0; k < r.phases.size(); ++k) {
    const ref::Phase& p = r.phases[k];
    EXPECT_EQ(p.kind, k % 2 == 0 ? Kind::slip_forward : Kind::slip_backward);
    if (k + 1 < r.phases.size()) {
      EXPECT_LT(abs_r(p.t_end - (tau1 + Real(k + 1) * kPi)), Real("1e-44") * (1 + p.t_end))
          << "stop " << k << " at " << p.t_end.str(50);
    }
  }
}

// The same orbit entered from the double nearest tau1 (what a user would
// type): it converges to tau1 + k pi (the orbit is attracting).
TEST(ReferenceSolver, PeriodicOrbitFromDoubleStartConverges) {
  ref::Input in;
  in.friction = 0.3;
  const Real lambda(in.friction);
  const Real tau1 = boost::multiprecision::acos(lambda * kPi / 2);
  in.t0 = static_cast<double>(tau1);
  const ref::Result r = ref::solve(in, in.t0 + 400 * 3.14159265358979 + 1);
  expect_consistent(r);
  const std::vector<Real> t = event_times(r);
  ASSERT_EQ(t.size(), 400u);
  const Real initial_offset = abs_r(Real(in.t0) - tau1);
  Real previous = initial_offset;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Real dev = abs_r(t[k] - (tau1 + Real(k + 1) * kPi));
    EXPECT_LE(dev, 2 * initial_offset + Real("1e-44")) << "stop " << k;
    if (k >= 200) {
      EXPECT_LT(dev, Real("1e-43") * t[k]) << "stop " << k;
    }
    if (dev > Real("1e-40")) {
      EXPECT_LT(dev, previous) << "not contracting at stop " << k;
    }
    previous = dev;
  }
}

// No friction: v = v0 + b (cos tau0 - cos tau) for all time; with v0 > 2b
// the mass never stops.
TEST(ReferenceSolver, FrictionlessNoStop) {
  ref::Input in;
  in.mass = 2;
  in.amplitude = 3;
  in.omega = 4;
  in.v0 = 5;
  in.x0 = -1.5;
  in.t0 = 0.75;
  const ref::Result r = ref::solve(in, 100.0);
  ASSERT_EQ(r.phases.size(), 1u);
  const ref::Phase& p = r.phases[0];
  EXPECT_EQ(p.kind, Kind::slip_forward);
  const Real b = Real(3) / 8, tau0 = Real(3), tau = Real(400);
  using boost::multiprecision::cos;
  using boost::multiprecision::sin;
  EXPECT_LT(abs_r(p.v_end - (5 + b * (cos(tau0) - cos(tau)))), Real("1e-45"));
  const Real x = Real(-1.5) + ((5 + b * cos(tau0)) * (tau - tau0) - b * (sin(tau) - sin(tau0))) / 4;
  EXPECT_LT(abs_r(p.x_end - x), Real("1e-45") * abs_r(x));
}

// No friction, small v0: the velocity changes sign exactly where
// cos(tau) = cos(tau0) + v0 / b, i.e. at +-acos(c) + 2 pi k; every stop is a
// reversal (R = 0 < |B sin|).
TEST(ReferenceSolver, FrictionlessReversalsAtClosedFormTimes) {
  ref::Input in;
  in.mass = 2;
  in.amplitude = 3;
  in.omega = 0.5;
  in.v0 = 0.25;
  in.t0 = -2.5;
  const Real b = Real(3) / (Real(2) * Real(0.5));
  const Real tau0 = Real(-1.25);
  const Real c = boost::multiprecision::cos(tau0) + Real(0.25) / b;
  const Real alpha = boost::multiprecision::acos(c);
  std::vector<Real> expected;
  for (int k = -1; k < 20; ++k)
    for (const Real& z : {-alpha + 2 * kPi * k, alpha + 2 * kPi * k})
      if (z > tau0 && z < Real(0.5) * 200) expected.push_back(z / Real(0.5));
  const ref::Result r = ref::solve(in, 200.0);
  expect_consistent(r);
  const std::vector<Real> t = event_times(r);
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_LT(abs_r(t[k] - expected[k]), Real("1e-44") * (1 + abs_r(t[k]))) << "event " << k;
    EXPECT_NE(r.phases[k].kind, r.phases[k + 1].kind);
    EXPECT_NE(r.phases[k + 1].kind, Kind::stick);
  }
}

// lambda > 1 from v0 != 0: one stop, then stuck for good.
TEST(ReferenceSolver, LambdaAboveOneStopsOnceAndSticks) {
  for (const double lambda : {1.01, 1.5, 5.0}) {
    for (const double v0 : {-5.0, -1.0, 0.25, 1.0}) {
      ref::Input in;
      in.friction = lambda;
      in.v0 = v0;
      const ref::Result r = ref::solve(in, 2000.0);
      expect_consistent(r);
      ASSERT_EQ(r.phases.size(), 2u) << "lambda " << lambda << " v0 " << v0;
      EXPECT_EQ(r.phases[0].kind, v0 > 0 ? Kind::slip_forward : Kind::slip_backward);
      EXPECT_EQ(r.phases[1].kind, Kind::stick);
      // The velocity is monotone in a slip when lambda >= 1: the stop is
      // before |v0| / (r - b) (the slowest possible deceleration).
      EXPECT_LT(r.phases[0].t_end, std::abs(v0) / (lambda - 1) + 1e-30);
    }
  }
}

// B = 0: a slide decelerates uniformly, v = v0 - s R (t - t0) / m, and
// stops at t0 + |v0| m / R exactly; from rest it never moves.
TEST(ReferenceSolver, NoForcing) {
  ref::Input in;
  in.amplitude = 0;
  in.mass = 2;
  in.friction = 0.5;
  in.v0 = -3;
  in.t0 = 100.125;
  in.x0 = 1;
  const ref::Result r = ref::solve(in, 200.0);
  ASSERT_EQ(r.phases.size(), 2u);
  EXPECT_EQ(r.phases[0].kind, Kind::slip_backward);
  const Real t_stop = Real(100.125) + Real(3) * 2 / Real(0.5);
  EXPECT_LT(abs_r(r.phases[0].t_end - t_stop), Real("1e-45") * t_stop);
  EXPECT_LT(abs_r(r.phases[0].x_end - (1 - Real(3) * 12 / 2)), Real("1e-45"));
  EXPECT_EQ(r.phases[1].kind, Kind::stick);
  in.v0 = 0;
  const ref::Result rest = ref::solve(in, 200.0);
  ASSERT_EQ(rest.phases.size(), 1u);
  EXPECT_EQ(rest.phases[0].kind, Kind::stick);
  in.friction = 0;
  in.v0 = 2;
  const ref::Result free = ref::solve(in, 200.0);
  ASSERT_EQ(free.phases.size(), 1u);
  EXPECT_EQ(free.phases[0].x_end, Real(1) + Real(2) * (200 - Real(100.125)));
}

// The closed forms solve the ODE: central differences in 50 digits give
// dx/dt = v and m dv/dt = B sin(w t) - s R inside every slip.
TEST(ReferenceSolver, ClosedFormSatisfiesTheOde) {
  ref::Input in;
  in.mass = 2;
  in.amplitude = 3;
  in.omega = 4;
  in.friction = 2.1;
  in.v0 = -1;
  in.t0 = 0.75;
  const ref::Result r = ref::solve(in, 20.0);
  expect_consistent(r);
  const Real h("1e-15");
  int slips = 0;
  for (const ref::Phase& p : r.phases) {
    if (p.kind == Kind::stick) continue;
    ++slips;
    for (int j = 1; j < 8; ++j) {
      const Real t = p.t_begin + (p.t_end - p.t_begin) * j / 8;
      const ref::StateR s = ref::evaluate(r.model, p, t);
      const ref::StateR lo = ref::evaluate(r.model, p, t - h);
      const ref::StateR hi = ref::evaluate(r.model, p, t + h);
      EXPECT_LT(abs_r((hi.x - lo.x) / (2 * h) - s.v), Real("1e-26"));
      EXPECT_LT(abs_r((hi.v - lo.v) / (2 * h) - s.a), Real("1e-26"));
      const Real force = 3 * boost::multiprecision::sin(4 * t);
      EXPECT_LT(abs_r(2 * s.a - (force - ref::sign_of(p.kind) * Real(2.1))), Real("1e-45"));
    }
  }
  EXPECT_GE(slips, 10);
}

// Mirror symmetry: (v0, t0) and (-v0, t0 + pi / w) give mirrored motions
// whose events are pi / w apart.
TEST(ReferenceSolver, MirrorSymmetry) {
  for (const char* lambda : {"0.3", "0.7", "1.01"}) {
    ref::RealInput a;
    a.friction = Real(lambda);
    a.v0 = Real("-0.25");
    a.t0 = Real("0.75");
    ref::RealInput b = a;
    b.v0 = -a.v0;
    b.t0 = a.t0 + kPi;
    const ref::Result ra = ref::solve(a, a.t0 + 60);
    const ref::Result rb = ref::solve(b, b.t0 + 60);
    ASSERT_EQ(ra.phases.size(), rb.phases.size()) << lambda;
    for (std::size_t i = 0; i + 1 < ra.phases.size(); ++i) {
      EXPECT_EQ(static_cast<int>(ra.phases[i].kind) == 0, static_cast<int>(rb.phases[i].kind) == 0);
      EXPECT_EQ(ref::sign_of(ra.phases[i].kind), -ref::sign_of(rb.phases[i].kind));
      EXPECT_LT(abs_r(rb.phases[i].t_end - ra.phases[i].t_end - kPi), Real("1e-44"));
      EXPECT_LT(abs_r(rb.phases[i].x_end + ra.phases[i].x_end), Real("1e-44"));
    }
  }
}

// The answer does not depend on the scan step (only the work does).
TEST(ReferenceSolver, IndependentOfScanStep) {
  ref::Input in;
  in.mass = 2;
  in.amplitude = 3;
  in.omega = 0.5;
  in.friction = 1.5;  // lambda = 0.5
  in.v0 = 1;
  in.t0 = -2.5;
  const ref::Result base = ref::solve(in, 150.0);
  expect_consistent(base);
  for (const char* step : {"0.05", "1", "3"}) {
    ref::Options options;
    options.step = Real(step);
    const ref::Result other = ref::solve(in, 150.0, options);
    ASSERT_EQ(other.phases.size(), base.phases.size()) << step;
    for (std::size_t i = 0; i < base.phases.size(); ++i) {
      EXPECT_EQ(other.phases[i].kind, base.phases[i].kind);
      EXPECT_LT(abs_r(other.phases[i].t_end - base.phases[i].t_end), Real("1e-45") * 200);
    }
  }
}

// A velocity that dips below zero by 1e-30 for ~1e-15 rad inside one scan
// step: a sign test at the step ends misses it, the curvature bound does
// not. (lambda = 0.5, t0 = 0: the minimum of v is at tau = pi / 6.)
TEST(ReferenceSolver, FindsGrazingZerosInsideAStep) {
  const Real lambda("0.5");
  const Real tau_min = kPi / 6;
  // f(tau_min) = v0 + 1 - cos(tau_min) - lambda tau_min = depth
  for (const char* depth : {"-1e-30", "1e-30"}) {
    ref::RealInput in;
    in.friction = lambda;
    in.v0 = Real(depth) - 1 + boost::multiprecision::cos(tau_min) + lambda * tau_min;
    const ref::Result r = ref::solve(in, Real(3));
    expect_consistent(r);
    if (Real(depth) < 0) {
      // slip+, a stop just before pi/6, a stick of ~1.5e-15 until the
      // breakaway at asin(0.5) = pi/6, slip+ again.
      ASSERT_EQ(r.phases.size(), 3u);
      EXPECT_EQ(r.phases[0].kind, Kind::slip_forward);
      EXPECT_EQ(r.phases[1].kind, Kind::stick);
      EXPECT_LT(abs_r(r.phases[1].t_end - tau_min), Real("1e-45"));
      EXPECT_GT(r.phases[1].duration(), Real("1e-15"));
      EXPECT_LT(r.phases[1].duration(), Real("2e-15"));
      EXPECT_EQ(r.phases[2].kind, Kind::slip_forward);
    } else {
      ASSERT_EQ(r.phases.size(), 1u);
    }
  }
}

// lambda >= lambda* = 2 / sqrt(4 + pi^2): dead bands, two stops per period
// from the first breakaway on; below it no stick after the first breakaway.
TEST(ReferenceSolver, RegimesAroundTheThreshold) {
  const Real threshold = ref::regime_threshold();
  // 40 digits, computed independently (mpmath).
  EXPECT_LT(abs_r(threshold - Real("0.5370292721463150768526283946638993461413")),
            Real("1e-39"));
  for (const char* lambda : {"0.5", "0.6", "0.7", "0.9"}) {
    ref::RealInput in;
    in.friction = Real(lambda);
    const ref::Result r = ref::solve(in, Real(2) * kPi * 30);
    expect_consistent(r);
    std::size_t sticks = 0;
    for (std::size_t i = 1; i < r.phases.size(); ++i)
      if (r.phases[i].kind == Kind::stick) ++sticks;
    if (Real(lambda) < threshold) {
      EXPECT_EQ(sticks, 0u) << lambda;
    } else {
      EXPECT_GE(sticks, 59u) << lambda;
      for (std::size_t i = 1; i < r.phases.size(); ++i) {
        if (r.phases[i].kind != Kind::stick) {
          EXPECT_EQ(r.phases[i].start, ref::Start::breakaway);
        }
      }
    }
  }
}

// lambda = 0 from rest at t0 = 0: v = b (1 - cos w t) >= 0 touches zero at
// w t = 2 pi k (a double root, where the force is 0 = R). The touches are
// decided by the breakaway time they sit on: the slip goes on forward, with
// sticks of zero length in 50 digits (< 1e-20) at most.
TEST(ReferenceSolver, TouchesAtDoubleRootsContinueTheSlip) {
  ref::Input in;
  in.friction = 0;
  const ref::Result r = ref::solve(in, 40.0);
  for (std::size_t i = 0; i < r.phases.size(); ++i) {
    const ref::Phase& p = r.phases[i];
    if (p.kind == Kind::stick) {
      EXPECT_LT(p.duration(), Real("1e-20"));
    } else {
      EXPECT_EQ(p.kind, Kind::slip_forward);
    }
    if (!p.at_horizon) {
      const Real k = boost::multiprecision::round(p.t_end / (2 * kPi));
      EXPECT_LT(abs_r(p.t_end - 2 * kPi * k), Real("1e-20")) << i;
    }
  }
  EXPECT_GE(r.phases.size(), 11u);  // six touches before t = 40
}
