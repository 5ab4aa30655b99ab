// The closed-form law inside one phase (closed_form.hpp) and evaluate()
// (phase.hpp).
//
// Independent checks: the law must satisfy the equation of motion
//   m x'' = B sin(w t) - s R   (s = +1, -1; stick: x' = x'' = 0)
// which is verified with 5-point central finite differences in tau = w t
// (so d/dt = w d/dtau) and against the right-hand side computed here from the
// model. Interior values of evaluate() are compared with mpmath's Taylor ODE
// integrator (odefun), a different method from the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdint>
#include <random>
#include <string>

#include "laws/harmonic_coulomb/phase_law.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/phase.hpp"

namespace frictionref {
namespace {

using Long = long double;
using detail::PhaseLaw;

// Portable uniform numbers in [lo, hi) from a fixed seed (the standard
// distributions are implementation-defined; the engine is not).
class Numbers {
 public:
  explicit Numbers(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    const double u = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * u;
  }

 private:
  std::mt19937_64 engine_;
};

// d f / d tau by the 5-point central stencil; truncation error h^4 f^(5) / 30.
template <class F>
Long derivative(const F& f, Long tau, Long h) {
  return (-f(tau + 2 * h) + 8 * f(tau + h) - 8 * f(tau - h) + f(tau - 2 * h)) / (12 * h);
}

struct Case {
  Model model;
  PhaseKind kind;
  Long tau_a, x_a, v_a;
};

std::string describe(const Case& c) {
  char text[400];
  std::snprintf(text, sizeof text,
                "kind=%d m=%.17g B=%.17g w=%.17g R=%.17g tau_a=%.21Lg x_a=%.21Lg v_a=%.21Lg",
                slip_sign(c.kind), c.model.mass, c.model.amplitude, c.model.omega,
                c.model.friction, c.tau_a, c.x_a, c.v_a);
  return text;
}

std::vector<Case> random_cases() {
  Numbers numbers(20240611);
  std::vector<Case> cases;
  for (int i = 0; i < 150; ++i) {
    Case c;
    c.model.mass = numbers.uniform(0.5, 4);
    // Every tenth case unforced (B = 0), every seventh frictionless.
    c.model.amplitude = i % 10 == 3 ? 0.0 : numbers.uniform(0.05, 4);
    c.model.omega = numbers.uniform(0.3, 3);
    c.model.friction = i % 7 == 2 ? 0.0 : numbers.uniform(0.05, 3);
    const PhaseKind kinds[3] = {PhaseKind::slip_forward, PhaseKind::slip_backward,
                                PhaseKind::stick};
    c.kind = kinds[i % 3];
    c.tau_a = numbers.uniform(-60, 60);
    c.x_a = numbers.uniform(-10, 10);
    c.v_a = c.kind == PhaseKind::stick ? 0.0 : numbers.uniform(-5, 5);
    cases.push_back(c);
  }
  return cases;
}

// The right-hand side of the equation of motion, straight from the model:
// (B sin(w t) - s R) / m at w t = tau.
Long rhs(const Model& model, int s, Long tau) {
  if (s == 0) return 0;
  return (Long(model.amplitude) * std::sin(tau) - Long(s) * Long(model.friction)) /
         Long(model.mass);
}

TEST(PhaseLaw, FiniteDifferencesSatisfyTheEquationOfMotion) {
  const Long h = 1e-3L;
  for (const Case& c : random_cases()) {
    SCOPED_TRACE(describe(c));
    const PhaseLaw<Long> law(c.model, c.kind, c.tau_a, c.x_a, c.v_a);
    const int s = slip_sign(c.kind);
    const Long w = c.model.omega;
    const Long b = Long(c.model.amplitude) / (Long(c.model.mass) * w);
    const Long r = Long(c.model.friction) / (Long(c.model.mass) * w);
    const auto position = [&](Long tau) { return law.position(tau); };
    const auto velocity = [&](Long tau) { return law.velocity(tau); };
    for (int k = 1; k <= 12; ++k) {
      const Long tau = c.tau_a + Long(k) * 2.5L;  // up to 30 radians into the phase
      // Rounding of the stencil ~ eps * |f| / h; truncation ~ h^4 (b + b / w) / 30.
      const Long scale_x = 1 + std::fabs(position(tau)) + std::fabs(position(tau + 2 * h));
      const Long scale_v = 1 + std::fabs(velocity(tau)) + std::fabs(velocity(tau + 2 * h));
      const Long trunc = 1e-10L * (1 + b + r + b / w);
      // dx/dt = w dx/dtau = v
      EXPECT_NEAR(double(w * derivative(position, tau, h)), double(law.velocity(tau)),
                  double(w * (1e-12L * scale_x / h + trunc)))
          << "tau=" << double(tau);
      // dv/dt = w dv/dtau = a
      EXPECT_NEAR(double(w * derivative(velocity, tau, h)), double(law.acceleration(tau)),
                  double(w * (1e-12L * scale_v / h + trunc)))
          << "tau=" << double(tau);
      // a = (B sin(w t) - s R) / m, from the model, not from b and r.
      EXPECT_NEAR(double(law.acceleration(tau)), double(rhs(c.model, s, tau)),
                  double(1e-15L * (1 + std::fabs(rhs(c.model, s, tau)) +
                                   Long(c.model.amplitude + c.model.friction) /
                                       Long(c.model.mass))))
          << "tau=" << double(tau);
    }
  }
}

TEST(PhaseLaw, StartValuesAreTheStartState) {
  for (const Case& c : random_cases()) {
    SCOPED_TRACE(describe(c));
    const PhaseLaw<Long> law(c.model, c.kind, c.tau_a, c.x_a, c.v_a);
    EXPECT_EQ(law.sign(), slip_sign(c.kind));
    EXPECT_EQ(law.tau_begin(), c.tau_a);
    // sin_cos is within 4 ulps of long double of the true cos; cosl within 1.
    EXPECT_LE(std::fabs(law.cos_begin() - std::cos(c.tau_a)),
              5 * std::numeric_limits<Long>::epsilon());
    EXPECT_EQ(law.position(c.tau_a), c.x_a);
    EXPECT_EQ(law.velocity(c.tau_a), c.kind == PhaseKind::stick ? 0.0L : c.v_a);
    // For a slip, s v at the start is s v_a (positive for a genuine slip).
    if (c.kind != PhaseKind::stick) {
      EXPECT_EQ(law.speed_along_slip(c.tau_a), Long(slip_sign(c.kind)) * c.v_a);
    }
  }
}

TEST(PhaseLaw, StickHoldsStill) {
  for (const Case& c : random_cases()) {
    if (c.kind != PhaseKind::stick) continue;
    SCOPED_TRACE(describe(c));
    const PhaseLaw<Long> law(c.model, c.kind, c.tau_a, c.x_a, 0.0L);
    for (int k = 0; k <= 10; ++k) {
      const Long tau = c.tau_a + Long(k) * 1.7L;
      EXPECT_EQ(law.position(tau), c.x_a);
      EXPECT_EQ(law.velocity(tau), 0.0L);
      EXPECT_EQ(law.acceleration(tau), 0.0L);
    }
  }
}

TEST(PhaseLaw, SpeedAlongSlipIsSignTimesVelocityAndSlopeIsItsDerivative) {
  const Long h = 1e-3L;
  for (const Case& c : random_cases()) {
    if (c.kind == PhaseKind::stick) continue;
    SCOPED_TRACE(describe(c));
    const PhaseLaw<Long> law(c.model, c.kind, c.tau_a, c.x_a, c.v_a);
    const Long s = slip_sign(c.kind);
    const Long b = Long(c.model.amplitude) / (Long(c.model.mass) * Long(c.model.omega));
    const Long r = Long(c.model.friction) / (Long(c.model.mass) * Long(c.model.omega));
    const auto speed = [&](Long tau) { return law.speed_along_slip(tau); };
    for (int k = 0; k <= 12; ++k) {
      const Long tau = c.tau_a + Long(k) * 2.5L + 0.1L;
      const Long scale = 1 + std::fabs(c.v_a) + 2 * b + r * std::fabs(tau - c.tau_a);
      EXPECT_NEAR(double(law.speed_along_slip(tau)), double(s * law.velocity(tau)),
                  double(1e-16L * scale))
          << "tau=" << double(tau);
      // d(s v)/dtau = s b sin(tau) - r, checked by finite differences.
      EXPECT_NEAR(double(derivative(speed, tau, h)), double(law.speed_slope(tau)),
                  double(1e-12L * (scale + 2 * r * h) / h + 1e-10L * (1 + b)))
          << "tau=" << double(tau);
      // and against the formula written out here.
      EXPECT_NEAR(double(law.speed_slope(tau)), double(s * b * std::sin(tau) - r),
                  double(1e-17L * (1 + b + r)));
    }
  }
}

TEST(PhaseLaw, FrictionlessFromRestIsTMinusSinT) {
  // m = B = w = 1, R = 0, forward from rest at t = 0: v = 1 - cos t, x = t - sin t.
  Model model;
  const PhaseLaw<Long> law(model, PhaseKind::slip_forward, 0.0L, 0.0L, 0.0L);
  for (Long t : {0.5L, 1.0L, 3.0L, 10.0L, 100.0L}) {
    EXPECT_NEAR(double(law.velocity(t)), double(1 - std::cos(t)), 1e-17 * double(1 + t));
    EXPECT_NEAR(double(law.position(t)), double(t - std::sin(t)), 1e-17 * double(1 + t));
    EXPECT_NEAR(double(law.acceleration(t)), double(std::sin(t)), 1e-18);
  }
}

TEST(PhaseLaw, UnforcedSlideDeceleratesUniformly) {
  // B = 0: v(t) = v_a - s (R / m)(t - t_a), x(t) = x_a + v_a (t - t_a) - s (R / m)(t - t_a)^2 / 2.
  // m = 2, w = 0.5, R = 0.5, v_a = 1 forward from t_a = 4 (tau_a = 2), x_a = 3:
  // stops at t - t_a = m v_a / R = 4 having slid m v_a^2 / (2 R) = 2.
  Model model;
  model.mass = 2;
  model.amplitude = 0;
  model.omega = 0.5;
  model.friction = 0.5;
  const PhaseLaw<Long> forward(model, PhaseKind::slip_forward, 2.0L, 3.0L, 1.0L);
  const Long tau_stop = 0.5L * (4.0L + 4.0L);
  EXPECT_NEAR(double(forward.velocity(tau_stop)), 0.0, 1e-18);
  EXPECT_NEAR(double(forward.position(tau_stop)), 5.0, 1e-17);
  EXPECT_NEAR(double(forward.acceleration(tau_stop)), -0.25, 1e-18);
  EXPECT_NEAR(double(forward.speed_along_slip(tau_stop)), 0.0, 1e-18);
  // Backward, mirrored.
  const PhaseLaw<Long> backward(model, PhaseKind::slip_backward, 2.0L, 3.0L, -1.0L);
  EXPECT_NEAR(double(backward.velocity(tau_stop)), 0.0, 1e-18);
  EXPECT_NEAR(double(backward.position(tau_stop)), 1.0, 1e-17);
  EXPECT_NEAR(double(backward.acceleration(tau_stop)), 0.25, 1e-18);
  EXPECT_NEAR(double(backward.speed_along_slip(tau_stop)), 0.0, 1e-18);
  // Half way: v = 0.5, x = 3 + 2 - 0.5 = 4.5 (t - t_a = 2, tau - tau_a = 1).
  EXPECT_NEAR(double(forward.velocity(3.0L)), 0.5, 1e-18);
  EXPECT_NEAR(double(forward.position(3.0L)), 4.5, 1e-17);
}

// ---- evaluate() ------------------------------------------------------------

Model evaluate_model() {
  Model model;
  model.mass = 2;
  model.amplitude = 3;
  model.omega = 0.5;
  model.friction = 0.75;
  return model;
}

// A phase whose stored end state is deliberately not the closed-form value:
// evaluate() must hand back what is stored, bit for bit.
Phase hand_made_phase(PhaseKind kind, double v_begin) {
  Phase phase;
  phase.kind = kind;
  phase.t_begin = 1.25;
  phase.t_end = 3.0;
  phase.x_begin = 0.5;
  phase.v_begin = v_begin;
  phase.x_end = 10.0;
  phase.v_end = -2.0;
  return phase;
}

TEST(Evaluate, ReturnsStoredStatesExactlyAtTheEnds) {
  const Model model = evaluate_model();
  for (PhaseKind kind : {PhaseKind::slip_forward, PhaseKind::slip_backward, PhaseKind::stick}) {
    SCOPED_TRACE(to_string(kind));
    const double v_begin = kind == PhaseKind::slip_backward ? -0.75 : kind == PhaseKind::stick ? 0.0 : 0.75;
    const Phase phase = hand_made_phase(kind, v_begin);
    const State end = evaluate(model, phase, phase.t_end);
    EXPECT_EQ(end.t, 3.0);
    EXPECT_EQ(end.x, 10.0);
    EXPECT_EQ(end.v, -2.0);
    EXPECT_EQ(end.phase, kind);
    // a is the phase's own acceleration at t_end: (B sin(w t) - s R) / m.
    EXPECT_NEAR(end.a, double(rhs(model, slip_sign(kind), 1.5L)), 2e-16);
    const State begin = evaluate(model, phase, phase.t_begin);
    EXPECT_EQ(begin.t, 1.25);
    EXPECT_EQ(begin.x, 0.5);
    EXPECT_EQ(begin.v, v_begin);
    EXPECT_EQ(begin.phase, kind);
    EXPECT_NEAR(begin.a, double(rhs(model, slip_sign(kind), 0.625L)), 2e-16);
  }
}

TEST(Evaluate, InteriorMatchesAnIndependentOdeIntegration) {
  // mpmath (dps 30): odefun(lambda t, y: [y[1], (3*sin(0.5*t) - s*0.75)/2], 1.25, [0.5, v_a])
  // evaluated at t = 2 and t = 2.75; a = (3 sin(0.5 t) - s 0.75) / 2.
  struct Expected {
    PhaseKind kind;
    double v_a, t, x, v, a;
  };
  const Expected table[] = {
      {PhaseKind::slip_forward, 0.75, 2.0, 1.243455997682134168844, 1.280732440911234554366,
       0.8872064772118447599788},
      {PhaseKind::slip_forward, 0.75, 2.75, 2.47768433327731931215, 2.036746234548692153224,
       1.096339585534733544134},
      {PhaseKind::slip_backward, -0.75, 2.0, 0.3293934976821341688438, 0.3432324409112345543658,
       1.637206477211844759979},
      {PhaseKind::slip_backward, -0.75, 2.75, 1.07143433327731931215, 1.661746234548692153224,
       1.846339585534733544134},
  };
  const Model model = evaluate_model();
  for (const Expected& e : table) {
    SCOPED_TRACE(std::string(to_string(e.kind)) + " t=" + std::to_string(e.t));
    const Phase phase = hand_made_phase(e.kind, e.v_a);
    const State state = evaluate(model, phase, e.t);
    EXPECT_EQ(state.t, e.t);
    EXPECT_EQ(state.phase, e.kind);
    EXPECT_NEAR(state.x, e.x, 4e-16 * std::fabs(e.x));
    EXPECT_NEAR(state.v, e.v, 4e-16 * std::fabs(e.v));
    EXPECT_NEAR(state.a, e.a, 4e-16 * std::fabs(e.a));
  }
  // Stick: holds x_begin with v = a = 0 inside.
  const State stuck = evaluate(model, hand_made_phase(PhaseKind::stick, 0.0), 2.0);
  EXPECT_EQ(stuck.x, 0.5);
  EXPECT_EQ(stuck.v, 0.0);
  EXPECT_EQ(stuck.a, 0.0);
  EXPECT_EQ(stuck.phase, PhaseKind::stick);
}

TEST(Evaluate, EnginePhasesReturnTheirStoredEndsExactly) {
  // Seed case 10.2 (lambda = 0.7) and 10.1 (lambda = 0.3) over a few periods:
  // every phase, evaluated at its own ends, gives its stored states.
  for (double friction : {0.7, 0.3}) {
    Model model;
    model.friction = friction;
    const Solution solution = solve(model, 40.0);
    ASSERT_GE(solution.phases.size(), 5u);
    for (const Phase& phase : solution.phases) {
      const State end = evaluate(model, phase, phase.t_end);
      EXPECT_EQ(end.x, phase.x_end);
      EXPECT_EQ(end.v, phase.v_end);
      EXPECT_EQ(end.phase, phase.kind);
      const State begin = evaluate(model, phase, phase.t_begin);
      EXPECT_EQ(begin.x, phase.x_begin);
      EXPECT_EQ(begin.v, phase.v_begin);
      EXPECT_EQ(begin.phase, phase.kind);
      // The acceleration at either end is the phase's own: (sin t - s R).
      const int s = slip_sign(phase.kind);
      EXPECT_NEAR(end.a, s == 0 ? 0.0 : std::sin(phase.t_end) - s * friction, 1e-15);
      EXPECT_NEAR(begin.a, s == 0 ? 0.0 : std::sin(phase.t_begin) - s * friction, 1e-15);
    }
  }
}

}  // namespace
}  // namespace frictionref
