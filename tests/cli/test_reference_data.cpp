// The exact reference curves committed under data/reference/ are what the
// current build computes: each file's "# command:" line is run again and every
// row compared (phase names exactly, numbers to 1e-14, i.e. a few ulps of the
// O(1) values, so another libm's last-bit differences do not fail it).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

class ReferenceData : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceData, RegeneratesTheCommittedCurve) {
  const fs::path path = fs::path(FRICTIONREF_SOURCE_DIR) / "data/reference" / GetParam();
  const Csv committed = parse_csv(read_file(path));
  std::vector<std::string> args = words(committed.meta("command"));
  ASSERT_GE(args.size(), 2u);
  ASSERT_EQ(args.front(), "frictionref");
  args.erase(args.begin());

  const RunResult result = run_frictionref(args);
  ASSERT_TRUE(succeeded(result));
  const Csv fresh = parse_csv(result.out);
  EXPECT_EQ(fresh.header, committed.header);
  ASSERT_EQ(fresh.rows.size(), committed.rows.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < fresh.rows.size(); ++i) {
    ASSERT_EQ(fresh.rows[i].size(), committed.rows[i].size());
    for (std::size_t j = 0; j < fresh.rows[i].size(); ++j) {
      const std::string& a = fresh.rows[i][j];
      const std::string& b = committed.rows[i][j];
      if (a == b) continue;
      ++differing;
      if (fresh.header.substr(fresh.header.rfind(',') + 1) == "phase" &&
          j + 1 == fresh.rows[i].size()) {
        ADD_FAILURE() << "row " << i << ": phase " << a << " != " << b;
        continue;
      }
      EXPECT_NEAR(to_double(a), to_double(b), 1e-14) << "row " << i << " column " << j;
    }
  }
  RecordProperty("fields_not_bit_identical", std::to_string(differing));
}

INSTANTIATE_TEST_SUITE_P(Seed, ReferenceData,
                         ::testing::Values("seed-10.1-exact-curve.csv", "seed-10.2-exact-curve.csv",
                                           "seed-10.3-exact-curve.csv"),
                         [](const auto& test_info) {
                           return test_name(test_info.param.substr(0, test_info.param.size() - 4));
                         });

}  // namespace
}  // namespace frictionref::cli_test
