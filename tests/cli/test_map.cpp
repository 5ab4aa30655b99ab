// `frictionref map`: the grid (x outer, both ends included), the columns, and
// the steady state at points whose answer is known independently: Den
// Hartog's non-stop region (his closed-form amplitude exists and the mass
// leaves at once at each reversal, beta^2 X > Rs / B, recomputed here) has
// no stops; static friction above the force keeps the mass at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

const double pi = 3.141592653589793;

// Den Hartog's non-stop conditions for k = m = B = 1, frequency ratio beta,
// r = R / B = Rs / B: the amplitude exists and beta^2 X > r (both with a
// margin, so that the point is not on the boundary).
bool den_hartog_non_stop(double beta, double r) {
  const double nu = 1 / beta;
  const double v = 1 / (1 - beta * beta), u = nu * std::tan(nu * pi / 2);
  const double disc = v * v - r * r * u * u;
  if (!(disc > 0.01)) return false;
  return beta * beta * std::sqrt(disc) > 1.2 * r;
}

TEST(Map, GridColumnsAndDenHartogsRegion) {
  const RunResult result = run_frictionref({"map", "--x", "lambda:0.05:0.45:5", "--y",
                                            "frequency-ratio:1.5:3:4", "--stiffness", "1",
                                            "--periods", "300", "--threads", "2"});
  ASSERT_TRUE(succeeded(result)) << result.err;
  const Csv table = parse_csv(result.out);
  EXPECT_EQ(table.header,
            "lambda,frequency_ratio,regime,stops_per_period,reversals_per_period,multiplicity,"
            "stuck_fraction,transient_periods");
  ASSERT_EQ(table.rows.size(), 20u);
  int checked = 0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const double lambda = to_double(table.rows[i][0]), beta = to_double(table.rows[i][1]);
    EXPECT_NEAR(lambda, 0.05 + 0.1 * static_cast<double>(i / 4), 1e-15);  // x outer
    EXPECT_NEAR(beta, 1.5 + 0.5 * static_cast<double>(i % 4), 1e-15);
    if (den_hartog_non_stop(beta, lambda)) {
      EXPECT_EQ(to_double(table.rows[i][table.column("stops_per_period")]), 0.0) << "lambda " << lambda << " beta " << beta;
      ++checked;
    }
  }
  EXPECT_GT(checked, 5);
}

TEST(Map, StaticFrictionAboveTheForceKeepsTheMassAtRest) {
  const RunResult result =
      run_frictionref({"map", "--x", "static-friction:1.1:2:2", "--y", "omega:0.5:2:2",
                       "--friction", "0.5", "--periods", "20", "--threads", "1"});
  ASSERT_TRUE(succeeded(result)) << result.err;
  const Csv table = parse_csv(result.out);
  ASSERT_EQ(table.rows.size(), 4u);
  for (const auto& row : table.rows) EXPECT_EQ(to_double(row[table.column("stuck_fraction")]), 1.0);
}

}  // namespace
}  // namespace frictionref::cli_test
