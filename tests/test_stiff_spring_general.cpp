// The stiff-spring (penalty) simulator on the general model (spring k,
// damper c, offset F0, extra harmonics, static friction Rs > R, contact
// damping), checked against what does not come from it: the closed form of
// the forced damped linear oscillator (no friction), and the exact
// event-driven solution of the library as kf grows. The measured numbers
// quoted in docs/stiff-spring.md are printed ("measured:").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "frictionref/comparison.hpp"
#include "frictionref/model.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/stiff_spring.hpp"

namespace frictionref {
namespace {

// m x'' + c x' + k x = F0 + B sin(w t) + sum B_i sin(w_i t + phi_i), no
// friction, under-damped: x = F0/k + sum Im(X_i e^{i (w_i t + phi_i)})
// + e^{-s (t - t0)} (C cos(wd (t - t0)) + D sin(wd (t - t0))), with
// X_i = B_i / (k - m w_i^2 + i c w_i), s = c / 2m, wd = sqrt(k/m - s^2), and C, D
// from x(t0) = x0, v(t0) = v0.
struct LinearOscillator {
  struct Term {
    std::complex<double> gain;  // X_i
    double omega, phase;
  };
  std::vector<Term> terms;
  double offset = 0, s = 0, wd = 0, t0 = 0, C = 0, D = 0;

  double particular_x(double t) const {
    double x = offset;
    for (const Term& h : terms) x += std::imag(h.gain * std::polar(1.0, h.omega * t + h.phase));
    return x;
  }
  double particular_v(double t) const {
    double v = 0;
    for (const Term& h : terms)
      v += h.omega * std::real(h.gain * std::polar(1.0, h.omega * t + h.phase));
    return v;
  }
  double x(double t) const {
    const double u = t - t0;
    return particular_x(t) + std::exp(-s * u) * (C * std::cos(wd * u) + D * std::sin(wd * u));
  }
  double v(double t) const {
    const double u = t - t0;
    const double e = std::exp(-s * u);
    return particular_v(t) +
           e * ((-s * C + wd * D) * std::cos(wd * u) + (-s * D - wd * C) * std::sin(wd * u));
  }
};

LinearOscillator linear_oscillator(const Model& m) {
  LinearOscillator o;
  const auto term = [&](double amplitude, double omega, double phase) {
    const std::complex<double> impedance(m.stiffness - m.mass * omega * omega, m.damping * omega);
    o.terms.push_back({amplitude / impedance, omega, phase});
  };
  term(m.amplitude, m.omega, 0);
  for (const Harmonic& h : m.harmonics) term(h.amplitude, h.omega, h.phase);
  o.offset = m.force_offset / m.stiffness;
  o.s = m.damping / (2 * m.mass);
  o.wd = std::sqrt(m.stiffness / m.mass - o.s * o.s);
  o.t0 = m.t0;
  o.C = m.x0 - o.particular_x(m.t0);
  o.D = (m.v0 - o.particular_v(m.t0) + o.s * o.C) / o.wd;
  return o;
}

Model frictionless_oscillator() {
  Model m;
  m.mass = 1.5;
  m.amplitude = 1;
  m.omega = 1.3;
  m.friction = 0;
  m.stiffness = 2;
  m.damping = 0.3;
  m.force_offset = 0.4;
  m.harmonics = {{0.5, 2.7, 0.4}, {-0.2, 0.45, -1}};
  m.x0 = 0.25;
  m.v0 = -0.6;
  m.t0 = 0.5;
  return m;
}

// Max |v - v_exact| of the simulator archived at every step of dt =
// fraction * limit, against the closed form.
double oscillator_velocity_error(const Model& model, double fraction) {
  StiffSpringOptions options;
  options.kf = 100;
  options.dt = fraction * options.stability_limit(model);
  options.output_dt = options.dt;
  const LinearOscillator exact = linear_oscillator(model);
  StiffSpringSimulator simulator(model, model.t0 + 20, options);
  double error = 0;
  StiffSample s;
  while (simulator.next(s)) {
    error = std::max(error, std::fabs(s.v - exact.v(s.t)));
    EXPECT_EQ(s.f, 0) << "no friction, no contact force, at t = " << s.t;
  }
  return error;
}

TEST(StiffSpringGeneral, FrictionlessModelIsTheDampedForcedOscillatorToSecondOrder) {
  const Model model = frictionless_oscillator();
  std::vector<double> errors;
  for (const double fraction : {0.08, 0.04, 0.02}) {
    errors.push_back(oscillator_velocity_error(model, fraction));
    std::printf("measured: k c F0 harmonics, no friction, dt = %.2f limit: max |dv| %.3g\n",
                fraction, errors.back());
  }
  EXPECT_LT(errors.back(), 1e-4);
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("measured: damped oscillator velocity error order in dt %.3f\n", order);
    EXPECT_GT(order, 1.9);
    EXPECT_LT(order, 2.1);
  }
}

// The stiff record, archived every output_dt, as a candidate history.
TimeHistory stiff_history(const Model& model, double t_end, double kf, double contact_damping) {
  StiffSpringOptions options;
  options.kf = kf;
  options.contact_damping = contact_damping;
  options.output_dt = 0.01;
  StiffSpringSimulator simulator(model, t_end, options);
  TimeHistory history;
  history.x.emplace();
  StiffSample s;
  while (simulator.next(s)) {
    history.t.push_back(s.t);
    history.v.push_back(s.v);
    history.x->push_back(s.x);
  }
  history.source = "stiff kf=" + std::to_string(kf);
  return history;
}

struct Feature {
  const char* name;
  Model model;
};

std::vector<Feature> general_features() {
  std::vector<Feature> features;
  const auto add = [&](const char* name, auto&& set) {
    Model m;
    m.friction = 0.5;
    set(m);
    features.push_back({name, m});
  };
  add("spring + damper, resonance", [](Model& m) {
    m.friction = 0.3;
    m.stiffness = 1;
    m.damping = 0.1;
  });
  add("static > kinetic, spring, second harmonic", [](Model& m) {
    m.friction = 0.6;
    m.static_friction = 0.8;
    m.stiffness = 0.5;
    m.harmonics = {{0.3, 2, 0}};
  });
  add("static > kinetic, offset, damper", [](Model& m) {
    m.static_friction = 0.9;
    m.force_offset = 0.2;
    m.damping = 0.3;
  });
  add("over-damped spring, moving start", [](Model& m) {
    m.friction = 0.2;
    m.stiffness = 0.3;
    m.damping = 3;
    m.v0 = 1;
    m.x0 = -0.5;
  });
  return features;
}

// As kf grows (with the automatic step), the penalty model converges to the
// exact motion for every feature of the family when the contact is damped:
// the velocity error drops about 10x per 100x kf, and compare() passes.
TEST(StiffSpringGeneral, ConvergesToTheExactMotionForEveryFeature) {
  for (const Feature& f : general_features()) {
    SCOPED_TRACE(f.name);
    std::vector<double> errors;
    for (const double kf : {1e4, 1e6, 1e8}) {
      const ComparisonReport r = compare(f.model, stiff_history(f.model, 30, kf, 1));
      errors.push_back(r.velocity_max_error / r.scales.velocity);
      std::printf("measured: %s, contact damping 1, kf=%g: max |dv| %.3g B/(m w), verdict %s\n",
                  f.name, kf, errors.back(), std::string(to_string(r.verdict)).c_str());
      if (kf == 1e8) {
        EXPECT_EQ(r.verdict, Verdict::pass) << r.brief_report();
        EXPECT_EQ(r.missed.size(), 0u);
        EXPECT_EQ(r.extra.size(), 0u);
      }
    }
    EXPECT_GT(errors[0] / errors[1], 5);
    EXPECT_GT(errors[1] / errors[2], 5);
    EXPECT_LT(errors[2], 1e-3);
  }
}

// Why the contact damping exists (docs/stiff-spring.md): without it, the
// spring rings past Rs after a stop and the contact breaks loose again, at
// any kf; the error does not go down.
TEST(StiffSpringGeneral, UndampedContactWithStaticFrictionDoesNotConverge) {
  const Feature f = general_features()[2];
  for (const double kf : {1e6, 1e8}) {
    const ComparisonReport r = compare(f.model, stiff_history(f.model, 30, kf, 0));
    std::printf("measured: %s, contact damping 0, kf=%g: max |dv| %.3g B/(m w)\n", f.name, kf,
                r.velocity_max_error / r.scales.velocity);
    EXPECT_GT(r.velocity_max_error / r.scales.velocity, 0.1);
    EXPECT_EQ(r.verdict, Verdict::fail);
  }
}

// The slider holds while the spring's force is within Rs, and slides with
// exactly R; the contact dashpot adds to the force only while stuck.
TEST(StiffSpringGeneral, SpringForceStaysWithinStaticFrictionAndSlidesWithR) {
  for (const Feature& f : general_features()) {
    SCOPED_TRACE(f.name);
    const double kf = 1e5;
    StiffSpringOptions options;
    options.kf = kf;
    options.contact_damping = 0.5;
    options.output_dt = options.step(f.model);
    StiffSpringSimulator simulator(f.model, 20, options);
    const double rs = f.model.static_limit(), r = f.model.friction;
    StiffSample s, previous;
    bool first = true;
    std::size_t slides = 0;
    while (simulator.next(s)) {
      const double spring = -kf * (s.x - s.z);
      EXPECT_LE(std::fabs(spring), rs * (1 + 1e-9) + 1e-12) << "t = " << s.t;
      EXPECT_LE(std::fabs(s.f), rs) << "t = " << s.t;
      // (z = x - (x - z) rounds: a held slider wanders by ulps of x.)
      if (!first && std::fabs(s.z - previous.z) > 1e-9) {
        // The slider moved: the spring carries exactly R.
        EXPECT_NEAR(std::fabs(spring), r, 1e-9 * rs) << "t = " << s.t;
        EXPECT_NEAR(s.f, spring, 1e-9 * rs) << "t = " << s.t;
        ++slides;
      }
      previous = s;
      first = false;
    }
    EXPECT_GT(slides, 100u);
  }
}

// A model of the general path that is the seed's model in substance (an
// extra harmonic of amplitude 0) gives the seed path's answer up to the
// order of the additions.
TEST(StiffSpringGeneral, GeneralPathAgreesWithTheSeedPathOnTheSeedModel) {
  Model seed;
  seed.friction = 0.7;
  Model general = seed;
  general.harmonics = {{0, 1, 0}};
  ASSERT_TRUE(seed.is_harmonic_coulomb());
  ASSERT_FALSE(general.is_harmonic_coulomb());
  StiffSpringOptions options;
  options.kf = 1e6;
  StiffSpringSimulator a(seed, 30, options), b(general, 30, options);
  StiffSample sa, sb;
  double worst = 0;
  while (a.next(sa)) {
    ASSERT_TRUE(b.next(sb));
    EXPECT_EQ(sa.t, sb.t);
    worst = std::max(worst, std::fabs(sa.v - sb.v));
  }
  EXPECT_FALSE(b.next(sb));
  EXPECT_LT(worst, 1e-9);
}

TEST(StiffSpringGeneral, StabilityLimitCountsTheModelSpringAndTheContactDashpot) {
  Model m;
  m.mass = 2;
  m.stiffness = 50;
  StiffSpringOptions options;
  options.kf = 150;
  EXPECT_DOUBLE_EQ(options.stability_limit(m), 2 * std::sqrt(2.0 / 200));
  options.contact_damping = 0.75;  // sqrt(1 + 0.5625) - 0.75 = 0.5
  EXPECT_DOUBLE_EQ(options.stability_limit(m), std::sqrt(2.0 / 200));
  options.contact_damping = -0.1;
  EXPECT_THROW(options.validate(m), InvalidInput);
}

}  // namespace
}  // namespace frictionref
