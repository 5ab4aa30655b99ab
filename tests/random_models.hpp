// Random models spread over many decades, for the property tests
// (test_properties.cpp). Deterministic: a fixed seed gives the same stream of
// raw numbers everywhere (std::mt19937_64 is fully specified, and the
// distributions are built here from its output, not from
// std::*_distribution, whose algorithms differ between standard libraries);
// the models themselves go through std::pow and std::asin, so another libm
// may change their last bits.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "frictionref/model.hpp"

namespace frictionref::testing {

// lambda* = 2 / sqrt(4 + pi^2), the continuous / dead-band threshold.
inline constexpr double kLambdaStar = 0.5370292721463151;
inline constexpr double kPiDouble = 3.141592653589793;

// Where lambda = R / B was drawn from (printed with a failing model).
enum class LambdaFamily {
  zero,        // R = 0 (B > 0)
  tiny,        // 1e-15 .. 1e-3, log-uniform
  continuous,  // uniform on (0, lambda*)
  near_star,   // lambda* (1 +- 10^-u), u uniform on [1, 15]
  dead_bands,  // uniform on (lambda*, 1)
  near_one,    // 1 +- 10^-u, u uniform on [1, 15]
  one,         // exactly 1 (R = B)
  above_one,   // 1 .. 10, log-uniform
  unforced,    // B = 0: R = 0 or log-uniform over decades
};

inline const char* to_string(LambdaFamily family) {
  switch (family) {
    case LambdaFamily::zero:
      return "zero";
    case LambdaFamily::tiny:
      return "tiny";
    case LambdaFamily::continuous:
      return "continuous";
    case LambdaFamily::near_star:
      return "near-lambda*";
    case LambdaFamily::dead_bands:
      return "dead-bands";
    case LambdaFamily::near_one:
      return "near-one";
    case LambdaFamily::one:
      return "one";
    case LambdaFamily::above_one:
      return "above-one";
    case LambdaFamily::unforced:
      return "unforced";
  }
  return "?";
}

struct RandomModel {
  Model model;
  double t_end = 0;  // t0 + periods * 2 pi / w
  double periods = 0;
  LambdaFamily family = LambdaFamily::zero;
  std::uint64_t index = 0;  // position in the stream (reproduces the model)
};

// The model and its horizon with 17 significant digits (round-trip), ready to
// paste into a test or onto the frictionref command line.
inline std::string describe(const RandomModel& r) {
  const Model& m = r.model;
  char text[512];
  std::snprintf(text, sizeof text,
                "model #%llu (lambda family %s): m=%.17g B=%.17g w=%.17g R=%.17g x0=%.17g "
                "v0=%.17g t0=%.17g t_end=%.17g (lambda=%.17g, w*t0=%.17g rad)",
                static_cast<unsigned long long>(r.index), to_string(r.family), m.mass, m.amplitude,
                m.omega, m.friction, m.x0, m.v0, m.t0, r.t_end,
                m.amplitude > 0 ? m.friction / m.amplitude : HUGE_VAL, m.omega * m.t0);
  return text;
}

// The stream of random models. Distributions (all independent):
//   m, w        log-uniform on [1e-6, 1e6]
//   B           0 with probability 4 %, else log-uniform on [1e-6, 1e6]
//   R = lambda B, lambda from a mixture (LambdaFamily): 0 (5 %), log-uniform
//               on [1e-15, 1e-3] (10 %), uniform on [0, lambda*) (18 %),
//               lambda* (1 +- 10^-u) (10 %), uniform on [lambda*, 1) (18 %),
//               1 +- 10^-u (10 %), exactly 1 (3 %), log-uniform on [1, 10]
//               (26 %), u uniform on [1, 15], signs even;
//               B = 0: R = 0 (30 %) or log-uniform on [1e-6, 1e6]
//   v0          0 (30 %), else +-V 10^u, u uniform on [-8, 4], V the velocity
//               unit (B + R) / (m w) (or 10^[-6,6] when B = R = 0)
//   x0          0 (25 %), else +-(V / w) 10^u, u uniform on [-6, 8]
//   t0          0 (15 %); a force crossing (alpha + k pi or pi - alpha + k pi,
//               |k| < 10^6) with v0 = 0 (5 % when 0 < lambda < 1); else
//               +-10^u / w with u uniform on [-6, 10], kept within
//               |w t0| <= 1e10 - 100 rad (the engine's rule, with the horizon)
//   horizon     t0 + P 2 pi / w, P uniform on [1, 3] forcing periods
class ModelStream {
 public:
  explicit ModelStream(std::uint64_t seed) : random_(seed) {}

  RandomModel next() {
    RandomModel r;
    r.index = count_++;
    Model& m = r.model;
    m.mass = log_uniform(-6, 6);
    m.omega = log_uniform(-6, 6);
    m.amplitude = unit() < 0.04 ? 0.0 : log_uniform(-6, 6);
    double lambda = 0;
    if (m.amplitude == 0) {
      r.family = LambdaFamily::unforced;
      m.friction = unit() < 0.3 ? 0.0 : log_uniform(-6, 6);
    } else {
      const double pick = unit();
      if (pick < 0.05) {
        r.family = LambdaFamily::zero;
        lambda = 0;
      } else if (pick < 0.15) {
        r.family = LambdaFamily::tiny;
        lambda = log_uniform(-15, -3);
      } else if (pick < 0.33) {
        r.family = LambdaFamily::continuous;
        lambda = kLambdaStar * unit();
      } else if (pick < 0.43) {
        r.family = LambdaFamily::near_star;
        lambda = kLambdaStar * (1 + sign() * std::pow(10.0, -uniform(1, 15)));
      } else if (pick < 0.61) {
        r.family = LambdaFamily::dead_bands;
        lambda = kLambdaStar + (1 - kLambdaStar) * unit();
      } else if (pick < 0.71) {
        r.family = LambdaFamily::near_one;
        lambda = 1 + sign() * std::pow(10.0, -uniform(1, 15));
      } else if (pick < 0.74) {
        r.family = LambdaFamily::one;
        lambda = 1;
      } else {
        r.family = LambdaFamily::above_one;
        lambda = log_uniform(0, 1);
      }
      m.friction = lambda * m.amplitude;
    }
    double velocity_unit = (m.amplitude + m.friction) / (m.mass * m.omega);
    if (velocity_unit == 0) velocity_unit = log_uniform(-6, 6);
    m.v0 = unit() < 0.3 ? 0.0 : sign() * velocity_unit * std::pow(10.0, uniform(-8, 4));
    m.x0 = unit() < 0.25 ? 0.0 : sign() * velocity_unit / m.omega * std::pow(10.0, uniform(-6, 8));
    const double kMaxPhase = 1e10 - 100;
    const double pick_t0 = unit();
    const double crossing_pick = unit();
    if (pick_t0 < 0.15) {
      m.t0 = 0;
    } else if (pick_t0 < 0.20 && m.amplitude > 0 && lambda > 0 && lambda < 1) {
      // Exactly at (the double nearest) a force crossing, from rest: a
      // breakaway (merged stick, section 4.7) or a release.
      const double alpha = std::asin(lambda);
      const double k = std::floor(uniform(-1e6, 1e6));
      const double base = crossing_pick < 0.5 ? alpha : kPiDouble - alpha;
      m.t0 = (base + k * kPiDouble) / m.omega;
      m.v0 = 0;
    } else {
      const double phase = std::fmin(std::pow(10.0, uniform(-6, 10)), kMaxPhase);
      m.t0 = sign() * phase / m.omega;
    }
    r.periods = uniform(1, 3);
    r.t_end = m.t0 + r.periods * 2 * kPiDouble / m.omega;
    return r;
  }

 private:
  // Uniform on [0, 1) from the top 53 bits: the same on every platform.
  double unit() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  double log_uniform(double lo_exponent, double hi_exponent) {
    return std::pow(10.0, uniform(lo_exponent, hi_exponent));
  }
  double sign() { return unit() < 0.5 ? -1.0 : 1.0; }

  std::mt19937_64 random_;
  std::uint64_t count_ = 0;
};

}  // namespace frictionref::testing
