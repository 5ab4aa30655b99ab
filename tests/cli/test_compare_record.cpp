// `compare`, `report` and `convergence` with --ground-accel: a candidate
// written from the hand solution of a pulse passes, a wrong one fails, every
// scale is the record's (PGV, PGV^2/PGA, T* = 2 pi PGV/PGA) and named so, and
// a record that is zero throughout is refused (one line, exit 2, no file).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bad_input.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The pulse a_g = 3 on 0 <= t <= 2 (g = 1 with --gravity 1), KY = 1,
// two-way. The record enters the model as -m a_g: x'' = -3 + 1 = -2 until
// t = 2 (v = -4, x = -4), then friction alone, x'' = +1, until rest at t = 6,
// x = -12. Ground velocity 3 t, then 6: PGV = 6, PGA = 3, T* = 4 pi.
const char* const kPulse = "t,a\n0,3\n2,3\n";

// The candidate t, v, x every 0.01 on [0, 10], from the hand solution with
// the deceleration after the pulse `decel` (1 is right).
std::string hand_candidate(double decel) {
  std::string out = "t,v,x\n";
  for (int i = 0; i <= 1000; ++i) {
    const double t = i * 0.01;
    const double stop = 2 + 4 / decel;
    double v = 0, x = 0;
    if (t <= 2) {
      v = -2 * t;
      x = -t * t;
    } else if (t <= stop) {
      const double s = t - 2;
      v = -4 + decel * s;
      x = -4 - 4 * s + decel * s * s / 2;
    } else {
      x = -4 - 8 / decel;
    }
    out += std::to_string(t) + "," + std::to_string(v) + "," + std::to_string(x) + "\n";
  }
  return out;
}

std::vector<std::string> compare_args(const std::string& candidate) {
  return {"compare", "--ground-accel",    "pulse.csv", "--gravity",
          "1",       "--yield-accel",     "1",         "--candidate",
          candidate, "--velocity-column", "v",         "--displacement-column",
          "x"};
}

TEST(CompareRecord, HandSolvedPulsePassesInTheRecordsScales) {
  TempDir dir;
  write(dir.path() / "pulse.csv", kPulse);
  write(dir.path() / "right.csv", hand_candidate(1));
  std::vector<std::string> args = compare_args("right.csv");
  args.push_back("--json");
  const RunResult result = run_frictionref(args, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["verdict"], "PASS") << result.out;
  EXPECT_EQ(j["scales"]["velocity"], 6);
  EXPECT_EQ(j["scales"]["velocity_name"], "PGV");
  EXPECT_EQ(j["scales"]["displacement"], 12);
  EXPECT_EQ(j["scales"]["displacement_name"], "PGV^2/PGA");
  EXPECT_NEAR(j["scales"]["period"].get<double>(), 4 * M_PI, 1e-12);
  EXPECT_EQ(j["regime"]["steady_state"], "stops");
  // The candidate's values are printed to 6 digits: errors of that size.
  EXPECT_LT(j["velocity_error"]["max"].get<double>(), 1e-5);
}

TEST(CompareRecord, WrongDecelerationFailsNamingPgvAndTStar) {
  TempDir dir;
  write(dir.path() / "pulse.csv", kPulse);
  write(dir.path() / "wrong.csv", hand_candidate(1.5));  // stops at t = 4.67, not 6
  const RunResult result = run_frictionref(compare_args("wrong.csv"), dir.path());
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_TRUE(contains(result.out, "velocity_max: FAIL")) << result.out;
  EXPECT_TRUE(contains(result.out, "stop_times: FAIL")) << result.out;
  EXPECT_TRUE(contains(result.out, " PGV (")) << result.out;
  EXPECT_TRUE(contains(result.out, " T*; tolerance 0.01 T*")) << result.out;
  EXPECT_FALSE(contains(result.out, "B/(m w)")) << result.out;
}

TEST(CompareRecord, ReportPageUsesTheRecordsScales) {
  TempDir dir;
  write(dir.path() / "pulse.csv", kPulse);
  write(dir.path() / "right.csv", hand_candidate(1));
  std::vector<std::string> args = compare_args("right.csv");
  args[0] = "report";
  args.insert(args.end(), {"-o", "report.html"});
  const RunResult result = run_frictionref(args, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  std::ifstream in(dir.path() / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(contains(html, "velocity PGV = 6")) << html.substr(0, 2000);
  EXPECT_TRUE(contains(html, "T* = 2 pi PGV/PGA = ")) << html.substr(0, 2000);
  EXPECT_FALSE(contains(html, "B/(m w)"));
}

TEST(ConvergenceRecord, StiffSpringOnThePulseConvergesInPgv) {
  TempDir dir;
  write(dir.path() / "pulse.csv", kPulse);
  const RunResult result = run_frictionref(
      {"convergence", "--ground-accel", "pulse.csv", "--gravity", "1", "--yield-accel", "1",
       "--t-end", "10", "--kf-list", "1e3,1e5", "--dt-fractions", "0.1", "--format", "markdown"},
      dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "max \\|v error\\| / (PGV)")) << result.out;
  EXPECT_EQ(result.out.find("B/(m w)"), std::string::npos) << result.out;
}

class RecordScalesRefused : public ::testing::TestWithParam<BadInput> {};

TEST_P(RecordScalesRefused, OneLineExit2NoFile) { expect_rejected(GetParam()); }

// A record of zeros (tests/data/records/zeros.txt, one column) has no scale
// to judge errors by; refused before the candidate is read.
INSTANTIATE_TEST_SUITE_P(
    Records, RecordScalesRefused,
    ::testing::Values(
        BadInput{writing("compare",
                         {"--ground-accel", FRICTIONREF_SOURCE_DIR "/tests/data/records/zeros.txt",
                          "--record-dt", "0.01", "--yield-accel", "0.1", "--candidate",
                          FRICTIONREF_SOURCE_DIR "/tests/data/records/zeros.txt"}),
                 "--ground-accel", "must not be zero throughout to compare"},
        BadInput{writing("convergence",
                         {"--ground-accel", FRICTIONREF_SOURCE_DIR "/tests/data/records/zeros.txt",
                          "--record-dt", "0.01", "--yield-accel", "0.1"}),
                 "--ground-accel", "must not be zero throughout for convergence"}),
    bad_input_name);

}  // namespace
}  // namespace frictionref::cli_test
