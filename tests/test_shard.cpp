// Shards of a parameter study (frictionref/shard.hpp): the blocks cover the
// study once, in order, within one point of each other in size; the text
// form is strict; a sharded map computes the same points as the whole map.
#include "frictionref/shard.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/parameter_map.hpp"

namespace frictionref {
namespace {

// Against the definition floor(i total / count), evaluated here in 128 bits.
std::size_t edge(std::uint64_t i, std::size_t total, std::uint64_t count) {
  __extension__ using wide = unsigned __int128;
  return static_cast<std::size_t>(static_cast<wide>(i) * total / count);
}

TEST(Shard, BlocksCoverTheStudyOnceInOrderAndDifferByAtMostOne) {
  const std::size_t max = std::numeric_limits<std::size_t>::max();
  for (const std::size_t total : std::vector<std::size_t>{1, 2, 3, 7, 25, 1000, 10'000'019,
                                                          max / 3, max - 1, max}) {
    // Every shard for small counts: the blocks follow each other from 0 to total.
    for (const std::uint64_t count : std::vector<std::uint64_t>{1, 2, 3, 4, 7, 64}) {
      std::size_t next = 0, smallest = max, largest = 0;
      for (std::uint64_t i = 1; i <= count; ++i) {
        const Shard::Range r = Shard{i, count}.range(total);
        ASSERT_EQ(r.begin, next) << total << " " << i << "/" << count;
        ASSERT_EQ(r.end, edge(i, total, count)) << total << " " << i << "/" << count;
        next = r.end;
        smallest = std::min(smallest, r.size());
        largest = std::max(largest, r.size());
      }
      EXPECT_EQ(next, total);
      EXPECT_LE(largest - smallest, 1u) << total << " in " << count;
    }
    // Large counts: both edges of some shards against the definition.
    for (const std::uint64_t count : std::vector<std::uint64_t>{999'983, 1'000'000}) {
      for (const std::uint64_t i : {std::uint64_t{1}, std::uint64_t{2}, count / 3, count - 1, count}) {
        const Shard::Range r = Shard{i, count}.range(total);
        EXPECT_EQ(r.begin, edge(i - 1, total, count)) << total << " " << i << "/" << count;
        EXPECT_EQ(r.end, edge(i, total, count)) << total << " " << i << "/" << count;
      }
    }
  }
}

TEST(Shard, ParsesIOfN) {
  const Shard s = Shard::parse("3/8");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(to_string(s), "3/8");
  EXPECT_EQ(to_string(Shard::parse("1000000/1000000")), "1000000/1000000");
  EXPECT_TRUE(Shard::parse("1/1").whole());
}

TEST(Shard, RefusesAnythingElse) {
  for (const char* text : {"", "/", "3", "3/", "/8", "0/8", "9/8", "1/0", "0/0", "-1/8", "+1/8",
                           "1 /8", "1/8 ", " 1/8", "1/8/2", "1.0/8", "0x1/8", "1/1000001",
                           "18446744073709551617/2", "1e3/2000", "a/b"}) {
    EXPECT_EQ(testing::expect_invalid([&] { Shard::parse(text); }).parameter(), "shard") << text;
  }
  EXPECT_EQ(testing::expect_invalid([] { Shard{0, 4}.validate(); }).parameter(), "shard");
  EXPECT_EQ(testing::expect_invalid([] { Shard{5, 4}.validate(); }).parameter(), "shard");
  EXPECT_EQ(testing::expect_invalid([] { Shard{1, 0}.validate(); }).parameter(), "shard");
  EXPECT_EQ(testing::expect_invalid([] { Shard{1, Shard::max_count + 1}.validate(); }).parameter(), "shard");
}

TEST(ShardedMap, ShardsAreTheWholeMapsPointsInOrder) {
  Model base;
  base.stiffness = 1;
  const MapAxis x{MapParameter::lambda, 0.05, 0.65, 4};
  const MapAxis y{MapParameter::frequency_ratio, 0.5, 2.5, 3};
  MapOptions options;
  options.classify.max_periods = 40;
  const std::vector<MapPoint> whole = parameter_map(base, x, y, options);
  ASSERT_EQ(whole.size(), 12u);
  for (const std::uint64_t count : {1u, 5u, 12u, 13u}) {
    std::vector<MapPoint> joined;
    for (std::uint64_t i = 1; i <= count; ++i) {
      options.shard = Shard{i, count};
      const std::vector<MapPoint> part = parameter_map(base, x, y, options);
      EXPECT_EQ(part.size(), options.shard.range(12).size());
      joined.insert(joined.end(), part.begin(), part.end());
    }
    ASSERT_EQ(joined.size(), whole.size()) << count;
    for (std::size_t k = 0; k < whole.size(); ++k) {
      EXPECT_EQ(joined[k].x, whole[k].x);
      EXPECT_EQ(joined[k].y, whole[k].y);
      EXPECT_EQ(joined[k].regime, whole[k].regime);
      EXPECT_EQ(joined[k].stops_per_period, whole[k].stops_per_period);
      EXPECT_EQ(joined[k].reversals_per_period, whole[k].reversals_per_period);
      EXPECT_EQ(joined[k].multiplicity, whole[k].multiplicity);
      EXPECT_EQ(joined[k].stuck_fraction, whole[k].stuck_fraction);
      EXPECT_EQ(joined[k].transient_periods, whole[k].transient_periods);
    }
  }
  options.shard = Shard{3, 2};
  EXPECT_EQ(testing::expect_invalid([&] { parameter_map(base, x, y, options); }).parameter(),
            "shard");
}

}  // namespace
}  // namespace frictionref
