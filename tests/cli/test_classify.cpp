// `frictionref classify`: regimes, the exact and quoted thresholds, the JSON
// keys and the text form.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

const double pi = 3.141592653589793;
// lambda* = 2 / sqrt(4 + pi^2) (THEORY.md), computed here, not by the binary.
const double exact_threshold = 2 / std::sqrt(4 + pi * pi);

nlohmann::json classify_json(const std::vector<std::string>& args) {
  std::vector<std::string> all{"classify", "--json"};
  all.insert(all.end(), args.begin(), args.end());
  const RunResult result = run_frictionref(all);
  EXPECT_TRUE(succeeded(result));
  return nlohmann::json::parse(result.out);
}

const char* const steady_state_keys[] = {"regime",
                                         "lambda",
                                         "threshold",
                                         "threshold_quoted",
                                         "regime_by_quoted_threshold",
                                         "reversal_phase",
                                         "breakaway_phase",
                                         "stop_phase",
                                         "stops_per_period",
                                         "stuck_fraction",
                                         "slide_per_half_period",
                                         "peak_velocity",
                                         "energy_per_period"};

TEST(Classify, JsonHasEveryKey) {
  const nlohmann::json json = classify_json({"--lambda", "0.7"});
  for (const char* key : steady_state_keys) EXPECT_TRUE(json.contains(key)) << key;
  ASSERT_TRUE(json.contains("model"));
  for (const char* key : {"mass", "amplitude", "omega", "friction", "lambda", "x0", "v0", "t0"}) {
    EXPECT_TRUE(json.at("model").contains(key)) << key;
  }
  EXPECT_EQ(json.at("model").at("friction").get<double>(), 0.7);
  EXPECT_EQ(json.at("version"), std::string(FRICTIONREF_EXPECTED_VERSION));
}

TEST(Classify, ThresholdsExactAndQuoted) {
  const nlohmann::json json = classify_json({"--lambda", "0.3"});
  EXPECT_LE(ulps_apart(json.at("threshold").get<double>(), exact_threshold), 4u)
      << json.at("threshold") << " vs " << exact_threshold;
  EXPECT_EQ(json.at("threshold_quoted").get<double>(), 0.536);
}

TEST(Classify, Continuous) {
  const nlohmann::json json = classify_json({"--lambda", "0.3"});
  EXPECT_EQ(json.at("regime"), "continuous");
  EXPECT_EQ(json.at("regime_by_quoted_threshold"), "continuous");
  EXPECT_EQ(json.at("lambda").get<double>(), 0.3);
  // Reversal where cos(w t) = lambda pi / 2, forward slip starting (sin > 0).
  EXPECT_NEAR(json.at("reversal_phase").get<double>(), std::acos(0.3 * pi / 2), 1e-12);
  EXPECT_TRUE(json.at("breakaway_phase").is_null());
  EXPECT_TRUE(json.at("stop_phase").is_null());
  EXPECT_EQ(json.at("stops_per_period").get<double>(), 0.0);
  EXPECT_EQ(json.at("stuck_fraction").get<double>(), 0.0);
}

TEST(Classify, DeadBands) {
  const nlohmann::json json = classify_json({"--lambda", "0.7"});
  EXPECT_EQ(json.at("regime"), "dead-bands");
  EXPECT_EQ(json.at("regime_by_quoted_threshold"), "dead-bands");
  EXPECT_TRUE(json.at("reversal_phase").is_null());
  EXPECT_LE(ulps_apart(json.at("breakaway_phase").get<double>(), std::asin(0.7)), 4u);
  const double stop = json.at("stop_phase").get<double>();
  // The forward slip from asin(0.7) ends where v = cos a - cos t - 0.7 (t - a) = 0.
  const double a = std::asin(0.7);
  EXPECT_GT(stop, a);
  EXPECT_NEAR(std::cos(a) - std::cos(stop) - 0.7 * (stop - a), 0.0, 1e-12);
  EXPECT_EQ(json.at("stops_per_period").get<double>(), 2.0);
  const double stuck = json.at("stuck_fraction").get<double>();
  EXPECT_GT(stuck, 0.0);
  EXPECT_LT(stuck, 1.0);
}

TEST(Classify, Stops) {
  const nlohmann::json json = classify_json({"--lambda", "1.01", "--v0", "-1"});
  EXPECT_EQ(json.at("regime"), "stops");
  EXPECT_EQ(json.at("regime_by_quoted_threshold"), "stops");
  EXPECT_EQ(json.at("stuck_fraction").get<double>(), 1.0);
  EXPECT_EQ(json.at("stops_per_period").get<double>(), 0.0);
  for (const char* key : {"reversal_phase", "breakaway_phase", "stop_phase"}) {
    EXPECT_TRUE(json.at(key).is_null()) << key;
  }
}

// Between 0.536 and lambda* the seed's quoted value gives the wrong answer.
TEST(Classify, BetweenQuotedAndExactThreshold) {
  for (const char* lambda : {"0.536", "0.537"}) {
    const nlohmann::json json = classify_json({"--lambda", lambda});
    EXPECT_EQ(json.at("regime"), "continuous") << lambda;
    EXPECT_EQ(json.at("regime_by_quoted_threshold"), "dead-bands") << lambda;
  }
  EXPECT_EQ(classify_json({"--lambda", "0.5371"}).at("regime"), "dead-bands");
  EXPECT_EQ(classify_json({"--lambda", "1"}).at("regime"), "stops");
}

// The regime belongs to R / B, whatever the units.
TEST(Classify, FrictionAndAmplitude) {
  const nlohmann::json json = classify_json({"--amplitude", "2", "--friction", "1.4"});
  EXPECT_EQ(json.at("regime"), "dead-bands");
  EXPECT_EQ(json.at("lambda").get<double>(), 0.7);
}

TEST(Classify, TextIsNameValueLines) {
  const RunResult result = run_frictionref({"classify", "--lambda", "0.7"});
  ASSERT_TRUE(succeeded(result));
  std::map<std::string, std::string> values;
  for (const std::string& line : lines(result.out)) {
    const auto colon = line.find(": ");
    ASSERT_NE(colon, std::string::npos) << line;
    values[line.substr(0, colon)] = line.substr(colon + 2);
  }
  EXPECT_EQ(values["regime"], "dead-bands");
  EXPECT_EQ(values["lambda"], "0.7");
  EXPECT_EQ(values["threshold_quoted"], "0.536");
  EXPECT_EQ(values["reversal_phase"], "n/a");
  EXPECT_LE(ulps_apart(to_double(values["threshold"]), exact_threshold), 4u);
  for (const char* key : steady_state_keys) EXPECT_EQ(values.count(key), 1u) << key;
}

}  // namespace
}  // namespace frictionref::cli_test
