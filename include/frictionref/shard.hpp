// Shards of a parameter study (sweep, map): the study's N grid points are cut
// into `count` contiguous blocks, and shard `index` (1-based, as in
// `--shard I/N`) computes only its block. Each point is computed by itself,
// so the concatenation of the N shards' rows, in shard order, is the rows of
// the unsharded study, bit for bit; any batch scheduler (SLURM array jobs,
// Dask) can run the shards independently (docs/cli.md, "Sharding").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace frictionref {

struct Shard {
  std::uint64_t index = 1;  // 1..count
  std::uint64_t count = 1;  // 1..max_count; more shards than points leaves some empty

  static constexpr std::uint64_t max_count = 1'000'000;

  // The block [begin, end) of `total` points: begin = floor((index - 1) total / count),
  // end = floor(index total / count), exactly. Blocks
  // differ in size by at most one point and cover 0..total once.
  struct Range {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
  };
  Range range(std::size_t total) const;

  bool whole() const { return count == 1; }

  // Throws InvalidInput naming `parameter` ("shard") and the rule.
  void validate(const std::string& parameter = "shard") const;
  // "I/N", whole numbers in decimal, 1 <= I <= N <= 10^6; throws InvalidInput
  // naming `parameter`.
  static Shard parse(std::string_view text, const std::string& parameter = "shard");
};

// "I/N"
std::string to_string(const Shard& shard);

}  // namespace frictionref
