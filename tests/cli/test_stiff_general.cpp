// `stiff`, `compare`, `convergence` and `report` on the general model
// (spring, damper, offset, extra harmonics, static friction above R) through
// the real binary: a stiff run with a damped contact passes compare against
// the exact solution (a different method), the undamped contact with Rs > R
// carries a note and fails, the errors fall with K_f, and the steady state
// comes from simulation where no closed form applies.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::vector<std::string> kModel = {"--lambda",    "0.6", "--static-lambda", "0.8",
                                         "--stiffness", "0.5", "--harmonic",      "0.3,2"};

std::vector<std::string> with_model(std::vector<std::string> args) {
  args.insert(args.begin() + 1, kModel.begin(), kModel.end());
  return args;
}

TEST(StiffGeneral, DampedContactRunPassesCompareOnTheGeneralModel) {
  TempDir dir;
  const std::string file = (dir.path() / "stiff.csv").string();
  const RunResult run = run_frictionref(
      with_model({"stiff", "--t-end", "30", "--kf", "1e8", "--contact-damping", "1", "-o", file}));
  ASSERT_TRUE(succeeded(run)) << run.err;
  const RunResult result =
      run_frictionref(with_model({"compare", "--candidate", file, "--displacement-column", "x"}));
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_TRUE(contains(result.out, "\nverdict: PASS\n")) << result.out;
  EXPECT_TRUE(contains(result.out, "static_friction=0.8 stiffness=0.5 harmonic=0.3,2,0"))
      << result.out;
  EXPECT_TRUE(contains(result.out, "steady state dead-bands (by simulation)")) << result.out;

  const RunResult json = run_frictionref(with_model({"compare", "--candidate", file, "--json"}));
  EXPECT_EQ(json.exit_code, 0) << json.err;
  EXPECT_TRUE(contains(json.out, R"("steady_state_method": "simulation")")) << json.out;

  const std::string page = (dir.path() / "report.html").string();
  const RunResult report = run_frictionref(with_model({"report", "--candidate", file, "-o", page}));
  EXPECT_EQ(report.exit_code, 0) << report.err;
  EXPECT_TRUE(contains(read_file(page), "Steady state of this model: dead-bands (simulation)"));
}

TEST(StiffGeneral, UndampedContactWithStaticFrictionIsNotedAndFails) {
  TempDir dir;
  const std::string file = (dir.path() / "stiff.csv").string();
  const RunResult run =
      run_frictionref(with_model({"stiff", "--t-end", "30", "--kf", "1e8", "-o", file}));
  ASSERT_TRUE(succeeded(run)) << run.err;
  const Csv csv = parse_csv(read_file(file));
  EXPECT_TRUE(contains(csv.meta("note"), "--contact-damping 1")) << csv.meta("note");
  EXPECT_TRUE(contains(csv.meta("stiff"), "contact_damping=0 ")) << csv.meta("stiff");
  const RunResult result = run_frictionref(with_model({"compare", "--candidate", file}));
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;

  // Rs = R: no note.
  const RunResult plain = run_frictionref(
      {"stiff", "--lambda", "0.6", "--stiffness", "0.5", "--t-end", "1", "--kf", "1e4"});
  ASSERT_TRUE(succeeded(plain));
  EXPECT_EQ(parse_csv(plain.out).meta("note"), "");
}

TEST(StiffGeneral, ConvergenceErrorsFallOnTheGeneralModel) {
  const RunResult result =
      run_frictionref(with_model({"convergence", "--contact-damping", "1", "--kf-list",
                                  "1e4,1e6,1e8", "--dt-fractions", "0.1", "--t-end", "20"}));
  ASSERT_TRUE(succeeded(result)) << result.err;
  const Csv csv = parse_csv(result.out);
  ASSERT_EQ(csv.rows.size(), 3u);
  EXPECT_TRUE(contains(csv.meta("convergence"), "contact_damping=1"));
  const std::size_t error = csv.column("velocity_max_error_relative");
  for (std::size_t i = 1; i < csv.rows.size(); ++i)
    EXPECT_LT(to_double(csv.rows[i][error]), to_double(csv.rows[i - 1][error]) / 5) << i;
  EXPECT_EQ(csv.rows.back()[csv.column("verdict")], "PASS");
}

}  // namespace
}  // namespace frictionref::cli_test
