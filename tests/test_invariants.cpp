// Checks that need no oracle (THEORY.md "Useful checks"): work-energy balance
// by quadrature, stick only where |F| <= R, slips keep their sign and end
// where v = 0, and the mirror symmetry (v0, t0) <-> (-v0, t0 + pi / w).
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "frictionref/frictionref.hpp"
#include "solution_checks.hpp"

namespace frictionref {
namespace {

const double kPi = 3.141592653589793;

// Models over several decades of m, B, w with lambda in [0, 3] and v0 up to
// +-3 B / (m w); fixed seed, so failures reproduce.
std::vector<Model> random_models(int count) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Model> models;
  for (int i = 0; i < count; ++i) {
    Model m;
    m.mass = std::pow(10.0, -2 + 4 * unit(random));
    m.amplitude = std::pow(10.0, -2 + 4 * unit(random));
    m.omega = std::pow(10.0, -1 + 2 * unit(random));
    m.friction = m.amplitude * 3 * unit(random) * unit(random);
    m.v0 = (unit(random) < 0.2 ? 0 : (6 * unit(random) - 3)) * m.amplitude / (m.mass * m.omega);
    m.x0 = 10 * unit(random) - 5;
    m.t0 = (20 * unit(random) - 10) / m.omega;
    models.push_back(m);
  }
  return models;
}

double horizon(const Model& m, double periods) { return m.t0 + periods * 2 * kPi / m.omega; }

// Work of the force minus friction dissipation equals the change of kinetic
// energy. The work integral is done by Gauss-Kronrod quadrature on the dense
// closed form: a different computation from the engine's event logic.
// Positions are doubles, so a slide is known to ulp(x) at each end: that
// representation limit (large x0, tiny slides) is part of the tolerance.
TEST(Invariants, WorkEnergyBalance) {
  const auto ulp = [](double x) { return std::nextafter(std::fabs(x), INFINITY) - std::fabs(x); };
  for (const Model& m : random_models(100)) {
    const double t_end = horizon(m, 6);
    const Solution s = solve(m, t_end);
    SCOPED_TRACE(testing::describe(m));
    double work = 0, dissipated = 0, scale = 0, representation = 0;
    for (const Phase& p : s.phases) {
      if (p.kind == PhaseKind::stick) continue;
      const auto power = [&](double t) { return m.force(t) * evaluate(m, p, t).v; };
      double error = 0;
      const double w = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
          power, p.t_begin, p.t_end, 10, 1e-14, &error);
      work += w;
      dissipated += m.friction * std::fabs(p.x_end - p.x_begin);
      representation += m.friction * (ulp(p.x_begin) + ulp(p.x_end));
      scale += std::fabs(w) + m.friction * std::fabs(p.x_end - p.x_begin);
    }
    const double v_end = s.phases.back().v_end;
    const double kinetic_change = 0.5 * m.mass * (v_end * v_end - m.v0 * m.v0);
    scale += 0.5 * m.mass * (v_end * v_end + m.v0 * m.v0);
    EXPECT_NEAR(kinetic_change, work - dissipated, 1e-12 * scale + representation);
  }
}

// Inside a stick |F| <= R; inside a slip v has the slip's sign and the
// acceleration is (F - s R) / m; a slip that ends before the horizon ends
// where its own closed form gives v = 0.
TEST(Invariants, PhaseLawsHoldInside) {
  for (const Model& m : random_models(200)) {
    const double t_end = horizon(m, 6);
    const Solution s = solve(m, t_end);
    testing::expect_well_formed(s, t_end);
    SCOPED_TRACE(testing::describe(m));
    const double velocity_scale = m.amplitude / (m.mass * m.omega) + std::fabs(m.v0);
    for (std::size_t i = 0; i < s.phases.size(); ++i) {
      const Phase& p = s.phases[i];
      const int sign = slip_sign(p.kind);
      for (int k = 1; k < 16; ++k) {
        const double t = p.t_begin + (p.t_end - p.t_begin) * k / 16;
        const State st = evaluate(m, p, t);
        if (sign == 0) {
          EXPECT_LE(std::fabs(m.force(t)), m.friction * (1 + 1e-12) + 1e-15 * m.amplitude)
              << "stick " << i << " at t = " << t;
        } else {
          EXPECT_GE(sign * st.v, -1e-13 * velocity_scale) << "phase " << i << " t " << t;
          EXPECT_NEAR(st.a, (m.force(t) - sign * m.friction) / m.mass,
                      1e-12 * (m.amplitude + m.friction) / m.mass);
        }
      }
      if (sign != 0 && i + 1 < s.phases.size()) {
        // v at t_end from the law started at t_begin (not the stored v_end).
        const double before_end = std::nextafter(p.t_end, p.t_begin);
        EXPECT_NEAR(evaluate(m, p, before_end).v, 0, 1e-13 * velocity_scale) << "phase " << i;
      }
    }
  }
}

// Mirror symmetry: (v0, t0) and (-v0, t0 + pi / w) are mirror images: same
// phase durations, slip directions swapped, displacements negated. Time
// shifts by pi / w are not exact in double, so times agree to a few ulps.
TEST(Invariants, MirrorSymmetry) {
  for (const Model& m : random_models(100)) {
    Model mirror = m;
    mirror.v0 = -m.v0;
    mirror.t0 = m.t0 + kPi / m.omega;
    const double span = 8 * 2 * kPi / m.omega;
    const Solution a = solve(m, m.t0 + span);
    const Solution b = solve(mirror, mirror.t0 + span);
    SCOPED_TRACE(testing::describe(m));
    ASSERT_EQ(a.phases.size(), b.phases.size());
    const double time_tolerance = 1e-12 * (std::fabs(m.t0) + span + 1 / m.omega);
    const double length_scale = m.amplitude / (m.mass * m.omega * m.omega) + std::fabs(m.v0) * span;
    for (std::size_t i = 0; i < a.phases.size(); ++i) {
      const Phase& p = a.phases[i];
      const Phase& q = b.phases[i];
      EXPECT_EQ(slip_sign(p.kind), -slip_sign(q.kind)) << "phase " << i;
      EXPECT_NEAR(p.t_end - m.t0, q.t_end - mirror.t0, time_tolerance) << "phase " << i;
      EXPECT_NEAR(p.x_end - m.x0, -(q.x_end - mirror.x0), 1e-11 * length_scale) << "phase " << i;
    }
  }
}

}  // namespace
}  // namespace frictionref
