// `frictionref classify` on the general model (docs/theory.md 8): the
// simulation against the closed forms it must reproduce (the seed's dead
// bands; Den Hartog's non-stop solution, whose amplitude is recomputed here
// from his formula), the forcing's common period, and the method field.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

const double pi = 3.141592653589793;

nlohmann::json classify_json(std::vector<std::string> args) {
  args.insert(args.begin(), {"classify", "--json"});
  const RunResult result = run_frictionref(args);
  EXPECT_TRUE(succeeded(result)) << result.err;
  return nlohmann::json::parse(result.out);
}

// The seed's dead bands at lambda = 0.7, by the engine period after period,
// against the closed form: two stops per period and the stuck fraction.
TEST(ClassifyGeneral, SimulationReproducesTheSeedsClosedForm) {
  const auto closed = classify_json({"--lambda", "0.7"});
  const auto simulated = classify_json({"--lambda", "0.7", "--simulate"});
  EXPECT_EQ(closed.at("method"), "closed-form");
  EXPECT_EQ(simulated.at("method"), "simulation");
  EXPECT_EQ(simulated.at("regime"), "dead-bands");
  EXPECT_EQ(simulated.at("stops_per_period").get<double>(), 2.0);
  EXPECT_NEAR(simulated.at("stuck_fraction").get<double>(),
              closed.at("stuck_fraction").get<double>(), 1e-9);
  EXPECT_NEAR(simulated.at("peak_velocity").get<double>(),
              closed.at("peak_velocity").get<double>(), 1e-9);
}

// Den Hartog (1931): k = m = B = 1, beta = w / w_n = 2, r = R / B = 0.1. In
// units of B / k: V = 1 / (1 - beta^2), U = nu tan(nu pi / 2) with nu = 1 /
// beta, amplitude X = sqrt(V^2 - r^2 U^2).
TEST(ClassifyGeneral, DenHartogsAmplitudeAndTheSimulationAgree) {
  const double beta = 2, r = 0.1, nu = 1 / beta;
  const double v = 1 / (1 - beta * beta), u = nu * std::tan(nu * pi / 2);
  const double amplitude = std::sqrt(v * v - r * r * u * u);
  const std::vector<std::string> model = {"--stiffness", "1", "--omega", "2", "--lambda", "0.1"};
  const auto closed = classify_json(model);
  ASSERT_FALSE(closed.at("den_hartog").is_null());
  EXPECT_TRUE(closed.at("den_hartog").at("non_stop").get<bool>());
  EXPECT_NEAR(closed.at("den_hartog").at("amplitude").get<double>(), amplitude, 1e-12);
  auto simulate = model;
  simulate.push_back("--simulate");
  const auto simulated = classify_json(simulate);
  EXPECT_EQ(simulated.at("regime"), "continuous");
  EXPECT_EQ(simulated.at("stops_per_period").get<double>(), 0.0);
  EXPECT_EQ(simulated.at("multiplicity").get<int>(), 1);
  EXPECT_NEAR(simulated.at("peak_velocity").get<double>(),
              closed.at("peak_velocity").get<double>(), 1e-7);
}

// Two harmonics at w and 2.5 w repeat every 2 periods of w: 4 pi / w.
TEST(ClassifyGeneral, ForcingPeriodOfSeveralHarmonics) {
  const auto json = classify_json({"--lambda", "0.3", "--harmonic", "0.4,2.5", "--stiffness", "1",
                                   "--damping", "0.2"});
  EXPECT_EQ(json.at("method"), "simulation");
  EXPECT_NEAR(json.at("forcing_period").get<double>(), 4 * pi, 1e-12);
  EXPECT_GE(json.at("multiplicity").get<int>(), 1);
}

// Static friction above the force's amplitude: the mass never moves.
TEST(ClassifyGeneral, StaticFrictionAboveTheForceHoldsTheMass) {
  const auto json = classify_json({"--lambda", "0.5", "--static-lambda", "1.2"});
  EXPECT_EQ(json.at("regime"), "stops");
  EXPECT_EQ(json.at("stuck_fraction").get<double>(), 1.0);
}

}  // namespace
}  // namespace frictionref::cli_test
