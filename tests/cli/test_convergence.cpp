// `frictionref convergence`: one row per (K_f, dt fraction), errors that fall
// as K_f grows, the observed order measured (the stiff-spring velocity error
// is set by the ringing (R - |F|) / sqrt(K_f m): order 1/2 in K_f,
// docs/stiff-spring.md), the markdown table, the figure, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

std::size_t column(const Csv& csv, const std::string& name) { return csv.column(name); }

TEST(Convergence, ErrorsFallAtOrderOneHalfInKf) {
  const RunResult result =
      run_frictionref({"convergence", "--lambda", "0.7", "--kf-list", "1e5,1e6,1e7,1e8",
                       "--dt-fractions", "0.5,0.1"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  ASSERT_EQ(csv.rows.size(), 8u);  // 4 stiffnesses x 2 fractions, stiffness-major
  const std::size_t kf = column(csv, "kf"), error = column(csv, "velocity_max_error_relative");
  const std::size_t order = column(csv, "order_velocity"), verdict = column(csv, "verdict");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(i));
    EXPECT_EQ(to_double(csv.rows[i][kf]), std::pow(10.0, 5 + static_cast<double>(i / 2)));
    if (i < 2) {
      EXPECT_TRUE(csv.rows[i][order].empty());  // nothing to compare with yet
      continue;
    }
    // 10x stiffer: the error falls by about sqrt(10); the order is measured.
    EXPECT_LT(to_double(csv.rows[i][error]), to_double(csv.rows[i - 2][error]) / 2.5);
    EXPECT_GT(to_double(csv.rows[i][order]), 0.4);
    EXPECT_LT(to_double(csv.rows[i][order]), 0.65);
  }
  // The seed's K_f = 1e7 passes compare; 1e5 leaves a ringing above the stick threshold.
  EXPECT_EQ(csv.rows[4][verdict], "PASS");
  EXPECT_EQ(csv.rows[0][verdict], "FAIL");
}

TEST(Convergence, MarkdownAndFigure) {
  TempDir dir;
  const RunResult result = run_frictionref(
      {"convergence", "--lambda", "0.3", "--kf-list", "1e6,1e7", "--dt-fractions", "0.1",
       "--format", "markdown", "-o", "table.md", "--plot", "convergence.svg"},
      dir.path());
  ASSERT_TRUE(succeeded(result));
  const std::string table = read_file(dir.path() / "table.md");
  EXPECT_EQ(table.rfind("| K_f |", 0), 0u) << table;
  EXPECT_EQ(lines(table).size(), 4u);  // header, rule, two rows
  const std::string svg = read_file(dir.path() / "convergence.svg");
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("K_f [force/length]"), std::string::npos);
}

TEST(Convergence, BadInput) {
  const std::vector<std::vector<std::string>> cases = {
      {"convergence", "--lambda", "0.7", "--kf-list", "1e5,-1"},
      {"convergence", "--lambda", "0.7", "--kf-list", "1e5,abc"},
      {"convergence", "--lambda", "0.7", "--dt-fractions", "0.5,1.5"},
      {"convergence", "--lambda", "0.7", "--format", "xml"},
      {"convergence", "--lambda", "0.7", "--t-end", "-1"},
      {"convergence", "--lambda", "0.7", "--amplitude", "0", "--friction", "0"},
  };
  for (const auto& args : cases) {
    TempDir dir;
    std::vector<std::string> with_output = args;
    with_output.insert(with_output.end(), {"-o", "out.csv"});
    const RunResult result = run_frictionref(with_output, dir.path());
    EXPECT_EQ(result.exit_code, 2) << args[3];
    EXPECT_EQ(lines(result.err).size(), 1u) << result.err;
    EXPECT_TRUE(dir.entries().empty()) << args[3];
  }
}

}  // namespace
}  // namespace frictionref::cli_test
