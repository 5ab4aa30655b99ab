// `frictionref curve`: the grid rule, the optional event rows, and the states
// against the independent reference solution.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "csv_reader.hpp"
#include "reference_motion.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

Csv run_curve(const std::vector<std::string>& args) {
  std::vector<std::string> all{"curve"};
  all.insert(all.end(), args.begin(), args.end());
  const RunResult result = run_frictionref(all);
  EXPECT_TRUE(succeeded(result));
  return parse_csv(result.out);
}

// The documented grid (sampling.hpp): t_i = t0 + i dt while t_i < T - 1e-9 dt,
// then T itself.
std::vector<double> expected_grid(double t0, double t_end, double dt) {
  std::vector<double> times;
  for (std::uint64_t i = 0;; ++i) {
    const double t = t0 + static_cast<double>(i) * dt;
    if (!(t < t_end - 1e-9 * dt)) break;
    times.push_back(t);
  }
  times.push_back(t_end);
  return times;
}

TEST(Curve, MetadataAndHeader) {
  const Csv csv = run_curve({"--lambda", "0.7", "--t-end", "30", "--dt", "0.01"});
  EXPECT_EQ(csv.metadata.at(0), std::string("frictionref ") + FRICTIONREF_EXPECTED_VERSION);
  EXPECT_EQ(csv.meta("model"), "mass=1 amplitude=1 omega=1 friction=0.7 lambda=0.7 x0=0 v0=0 t0=0");
  EXPECT_NE(csv.meta("command").find("curve --lambda 0.7 --t-end 30 --dt 0.01"), std::string::npos);
  EXPECT_EQ(csv.meta("grid"), "t0=0 t_end=30 dt=0.01 include_events=false grid_rows=3001");
  EXPECT_EQ(csv.header, "t,x,v,a,phase");
}

// Row count = grid + T, each grid time exactly t0 + i dt (never accumulated),
// T not repeated when it lies on the grid.
TEST(Curve, GridTimesAreExact) {
  struct Grid {
    const char *t0, *t_end, *dt;
  };
  for (const Grid grid :
       {Grid{"0", "30", "0.01"}, Grid{"0", "1", "0.01"}, Grid{"0", "1.005", "0.01"},
        Grid{"-5", "5", "0.5"}, Grid{"0.1", "0.35", "0.1"}}) {
    SCOPED_TRACE(std::string(grid.t0) + " " + grid.t_end + " " + grid.dt);
    const Csv csv =
        run_curve({"--lambda", "0.3", "--t0", grid.t0, "--t-end", grid.t_end, "--dt", grid.dt});
    const std::vector<double> times =
        expected_grid(std::strtod(grid.t0, nullptr), std::strtod(grid.t_end, nullptr),
                      std::strtod(grid.dt, nullptr));
    ASSERT_EQ(csv.rows.size(), times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
      EXPECT_EQ(to_double(csv.rows[i][0]), times[i]) << "row " << i;
    }
  }
}

// The event row at the first breakaway, t = asin(0.7), and the state just
// after it (closed form) must come back from the printed digits.
TEST(Curve, EventRowRoundTrips) {
  const Csv csv =
      run_curve({"--lambda", "0.7", "--t-end", "1", "--dt", "0.25", "--include-events"});
  ASSERT_EQ(csv.rows.size(), 6u);  // 0, 0.25, 0.5, 0.75, the breakaway, 1
  const auto& event = csv.rows[4];
  EXPECT_LE(ulps_apart(to_double(event[0]), std::asin(0.7)), 4u) << event[0];
  EXPECT_EQ(event[4], "slip+");
  EXPECT_EQ(to_double(event[1]), 0.0);
  EXPECT_EQ(to_double(event[2]), 0.0);
  // At t = 1: v = cos a - cos 1 - 0.7 (1 - a), x = cos a (1 - a) - (sin 1 - sin a) - 0.35 (1 -
  // a)^2.
  const long double a = std::asin(0.7L), t = 1;
  const long double v = std::cos(a) - std::cos(t) - 0.7L * (t - a);
  const long double x =
      std::cos(a) * (t - a) - (std::sin(t) - std::sin(a)) - 0.35L * (t - a) * (t - a);
  const auto& last = csv.rows[5];
  EXPECT_EQ(to_double(last[0]), 1.0);
  EXPECT_LE(ulps_apart(to_double(last[2]), static_cast<double>(v)), 64u) << last[2];
  EXPECT_LE(ulps_apart(to_double(last[1]), static_cast<double>(x)), 64u) << last[1];
  EXPECT_LE(ulps_apart(to_double(last[3]), std::sin(1.0) - 0.7), 4u) << last[3];
}

TEST(Curve, ThirtyOverHundredthIs3001Rows) {
  const Csv csv = run_curve({"--lambda", "0.3", "--t-end", "30", "--dt", "0.01"});
  EXPECT_EQ(csv.rows.size(), 3001u);
  EXPECT_EQ(to_double(csv.rows.back()[0]), 30.0);
}

struct SeedCase {
  const char* lambda;
  const char* v0;
};

class CurveSeedCase : public ::testing::TestWithParam<SeedCase> {
 protected:
  ReferenceMotion reference() const {
    return ReferenceMotion(std::strtod(GetParam().lambda, nullptr),
                           std::strtod(GetParam().v0, nullptr), 30);
  }
};

// Near a boundary the phase of a row depends on the last bits of the event
// time; the state itself is continuous and is checked everywhere.
bool near_boundary(const ReferenceMotion& reference, double t) {
  for (const RefPhase& phase : reference.phases()) {
    if (std::fabs(static_cast<double>(phase.t_begin) - t) < 1e-9) return true;
  }
  return false;
}

TEST_P(CurveSeedCase, StatesMatchTheReference) {
  const Csv csv = run_curve(
      {"--lambda", GetParam().lambda, "--v0", GetParam().v0, "--t-end", "30", "--dt", "0.01"});
  const ReferenceMotion ref = reference();
  ASSERT_EQ(csv.rows.size(), 3001u);
  for (const auto& row : csv.rows) {
    const double t = to_double(row[0]);
    const RefState expected = ref.state(ref.phase_at(t), t);
    SCOPED_TRACE("t = " + row[0]);
    EXPECT_NEAR(to_double(row[1]), static_cast<double>(expected.x), 1e-11);
    EXPECT_NEAR(to_double(row[2]), static_cast<double>(expected.v), 1e-11);
    if (!near_boundary(ref, t)) {
      EXPECT_EQ(row[4], expected.kind);
      EXPECT_NEAR(to_double(row[3]), static_cast<double>(expected.a), 1e-11);
    }
  }
}

// --include-events: one extra row per interior phase boundary, carrying the
// new phase and its acceleration (right limit); times strictly increasing.
TEST_P(CurveSeedCase, EventRowsKeepTheKinks) {
  const Csv csv = run_curve({"--lambda", GetParam().lambda, "--v0", GetParam().v0, "--t-end", "30",
                             "--dt", "0.01", "--include-events"});
  const ReferenceMotion ref = reference();
  const std::size_t boundaries = ref.phases().size() - 1;
  ASSERT_EQ(csv.rows.size(), 3001u + boundaries);
  EXPECT_NE(csv.meta("grid").find("include_events=true"), std::string::npos);
  for (std::size_t i = 1; i < csv.rows.size(); ++i) {
    EXPECT_LT(to_double(csv.rows[i - 1][0]), to_double(csv.rows[i][0])) << "row " << i;
  }
  for (std::size_t k = 1; k < ref.phases().size(); ++k) {
    const RefPhase& next = ref.phases()[k];
    const double t_event = static_cast<double>(next.t_begin);
    bool found = false;
    for (const auto& row : csv.rows) {
      if (std::fabs(to_double(row[0]) - t_event) > 1e-11) continue;
      found = true;
      EXPECT_EQ(row[4], next.kind) << "event at " << t_event;
      const RefState right = ref.state(next, next.t_begin);
      EXPECT_NEAR(to_double(row[3]), static_cast<double>(right.a), 1e-11);
      EXPECT_NEAR(to_double(row[2]), 0.0, 1e-11);  // every boundary is a v = 0 event
    }
    EXPECT_TRUE(found) << "no row at the boundary t = " << t_event;
  }
  EXPECT_EQ(csv.rows.back()[4], ref.phases().back().kind);  // the row at T: last phase
}

INSTANTIATE_TEST_SUITE_P(Seed, CurveSeedCase,
                         ::testing::Values(SeedCase{"0.3", "0"}, SeedCase{"0.7", "0"},
                                           SeedCase{"1.01", "-1"}),
                         [](const ::testing::TestParamInfo<SeedCase>& case_info) {
                           return test_name(std::string("lambda_") + case_info.param.lambda +
                                            "_v0_" + case_info.param.v0);
                         });

}  // namespace
}  // namespace frictionref::cli_test
