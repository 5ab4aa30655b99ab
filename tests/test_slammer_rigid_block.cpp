// SLAMMER's rigid-block algorithm (slammer_rigid_block.hpp) against a second,
// independent transliteration of its Java source in Python
// (tests/reference/slammer_reference.py, whose output is
// tests/data/records/slammer_reference.csv): the same samples must give the
// same displacement to the last bit, for both polarities (SLAMMER skips
// exact zero samples only with the normal one), one-way and two-way.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/slammer_rigid_block.hpp"

namespace frictionref {
namespace {

using testing::expect_invalid;

const std::string kSource = FRICTIONREF_SOURCE_DIR;

GroundMotion record_in_cm(const std::string& name, bool inverse) {
  GroundMotionReadOptions options;
  options.gravity = 980.665;  // centimetres, SLAMMER's unit
  options.inverse = inverse;
  return read_ground_motion(kSource + "/data/records/synthetic/" + name, options);
}

struct ReferenceRow {
  std::string record;
  double yield_accel_g;
  bool two_way;
  bool inverse;
  double displacement;
  std::size_t slip_episodes;
  double max_relative_velocity;
  std::size_t skipped_zero_samples;
};

std::vector<ReferenceRow> reference_rows() {
  std::ifstream in(kSource + "/tests/data/records/slammer_reference.csv");
  EXPECT_TRUE(in.good()) << "cannot open slammer_reference.csv";
  std::vector<ReferenceRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("record,", 0) == 0) continue;
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    if (f.size() != 8) {
      ADD_FAILURE() << "bad reference line: " << line;
      continue;
    }
    rows.push_back({f[0], std::stod(f[1]), f[2] == "two-way", f[3] == "inverse", std::stod(f[4]),
                    std::stoul(f[5]), std::stod(f[6]), std::stoul(f[7])});
  }
  return rows;
}

TEST(SlammerRigidBlock, AgreesToTheBitWithTheReferenceTransliteration) {
  const std::vector<ReferenceRow> rows = reference_rows();
  ASSERT_EQ(rows.size(), 40u);
  for (const ReferenceRow& row : rows) {
    SCOPED_TRACE(row.record + " KY " + std::to_string(row.yield_accel_g) +
                 (row.two_way ? " two-way" : " one-way") + (row.inverse ? " inverse" : " normal"));
    SlammerOptions options;
    options.yield_accel_g = row.yield_accel_g;
    options.two_way = row.two_way;
    options.inverse = row.inverse;
    const SlammerResult result =
        slammer_rigid_block(record_in_cm(row.record, row.inverse), options);
    EXPECT_EQ(result.displacement, row.displacement);
    EXPECT_EQ(result.slip_episodes, row.slip_episodes);
    EXPECT_EQ(result.max_relative_velocity, row.max_relative_velocity);
    EXPECT_EQ(result.skipped_zero_samples, row.skipped_zero_samples);
  }
}

TEST(SlammerRigidBlock, HistoryEndsAtTheDisplacement) {
  SlammerOptions options;
  options.keep_history = true;
  const GroundMotion record = record_in_cm("pulse-train.AT2", false);
  const SlammerResult result = slammer_rigid_block(record, options);
  ASSERT_EQ(result.displacement_history.size(), record.samples());
  EXPECT_EQ(result.displacement_history.back(), result.displacement);
  // One-way: the displacement never decreases.
  for (std::size_t i = 1; i < result.displacement_history.size(); ++i)
    ASSERT_GE(result.displacement_history[i], result.displacement_history[i - 1]) << i;
}

TEST(SlammerRigidBlock, RefusesATableOfTimesAndBadOptions) {
  GroundMotionReadOptions read;
  const GroundMotion table =
      read_ground_motion(kSource + "/data/records/synthetic/nonuniform.csv", read);
  const InvalidInput e = expect_invalid([&] { slammer_rigid_block(table, {}); });
  EXPECT_EQ(e.parameter(), "record");
  SlammerOptions bad;
  bad.yield_accel_g = -0.1;
  EXPECT_EQ(expect_invalid([&] {
              slammer_rigid_block(record_in_cm("pulse-train.AT2", false), bad);
            }).parameter(),
            "yield_accel");
}

}  // namespace
}  // namespace frictionref
