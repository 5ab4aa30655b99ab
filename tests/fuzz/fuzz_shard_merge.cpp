// libFuzzer target: the reader of shard tables and the merge of `frictionref
// merge` (src/cli/shard_files.hpp), exactly the code the command runs on the
// files' bytes.
//
// The contract under test: parse_shard_table either throws ShardFileError or
// returns a table whose row count is its shard's block of the study;
// merged_metadata on the accepted tables either throws ShardFileError or
// returns the whole study's '#' lines (version and model first, the merge's
// command, one '# merged: N shards (rows 1..T)' line), and then the tables
// are the shards 1..N once each whose rows add up to T. Any other exception,
// a sanitizer report or a hang is a finding.
//
// Input layout: the bytes are cut at every 0xFF byte into up to 16 files
// (0xFF never occurs in a table we write). The seed corpus holds real
// shard sets of sweep and map (tests/fuzz/tools/make_shard_seeds.sh).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.hpp"
#include "shard_files.hpp"

namespace {

using frictionref::cli::ShardFileError;
using frictionref::cli::ShardTable;

constexpr std::size_t kMaxFiles = 16;

[[noreturn]] void fail(const char* what, int line) {
  std::fprintf(stderr, "fuzz_shard_merge: invariant violated (fuzz_shard_merge.cpp:%d): %s\n",
               line, what);
  std::abort();
}

bool starts_with(const std::string& text, std::string_view start) {
  return std::string_view(text).substr(0, start.size()) == start;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::vector<std::string_view> files;
  std::size_t begin = 0;
  while (files.size() < kMaxFiles) {
    const std::size_t cut = bytes.find('\xff', begin);
    files.push_back(bytes.substr(begin, cut == std::string_view::npos ? cut : cut - begin));
    if (cut == std::string_view::npos) break;
    begin = cut + 1;
  }

  std::vector<ShardTable> tables;
  try {
    for (std::size_t i = 0; i < files.size(); ++i) {
      ShardTable table = frictionref::cli::parse_shard_table("f" + std::to_string(i), files[i]);
      FUZZ_CHECK(table.total >= 1);
      FUZZ_CHECK(table.shard.index >= 1 && table.shard.index <= table.shard.count);
      FUZZ_CHECK(table.rows.size() == table.shard.range(table.total).size());
      FUZZ_CHECK(table.metadata.size() >= 3);
      tables.push_back(std::move(table));
    }
  } catch (const ShardFileError&) {
    return 0;
  }

  std::vector<std::string> lines;
  try {
    lines = frictionref::cli::merged_metadata(tables, "frictionref merge fuzz");
  } catch (const ShardFileError&) {
    return 0;
  }
  FUZZ_CHECK(lines.size() >= 3);
  FUZZ_CHECK(starts_with(lines[0], "# frictionref "));
  FUZZ_CHECK(starts_with(lines[1], "# model: "));
  std::size_t commands = 0, merged = 0;
  for (const std::string& line : lines) {
    FUZZ_CHECK(starts_with(line, "# "));
    FUZZ_CHECK(line.find('\n') == std::string::npos);
    commands += line == "# command: frictionref merge fuzz";
    merged += starts_with(line, "# merged: ");
  }
  FUZZ_CHECK(commands == 1 && merged == 1);
  const auto ordered = frictionref::cli::in_shard_order(tables);
  FUZZ_CHECK(ordered.size() == ordered.front()->shard.count);
  std::uint64_t rows = 0;
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    FUZZ_CHECK(ordered[i]->shard.index == i + 1);
    FUZZ_CHECK(ordered[i]->header == ordered.front()->header);
    rows += ordered[i]->rows.size();
  }
  FUZZ_CHECK(rows == ordered.front()->total);
  return 0;
}
