// Reading the tables that `sweep --shard I/N` and `map --shard I/N` write,
// and joining N of them into the table of the whole study (`frictionref
// merge`). Pure text in, text out: no file system here, so the fuzz target
// tests/fuzz/fuzz_shard_merge.cpp drives exactly what the command runs.
//
// A shard table is '# ' metadata lines, one header line, then data rows, every
// line ended by '\n'. Its metadata holds "# frictionref V", "# model: ...",
// "# command: ...", the study's line ("# sweep: ..." or "# map: ..."), the
// shard's line "# shard: I/N rows B..E of T" (or "rows none of T") and, for a
// sweep, "# regimes: ..." (counted over the file's rows).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "frictionref/shard.hpp"

namespace frictionref::cli {

// A shard file that cannot be read as one, or that does not fit with the
// others; what() is the rule, file() the file it is about.
class ShardFileError : public std::runtime_error {
 public:
  ShardFileError(std::string file, const std::string& rule)
      : std::runtime_error(rule), file_(std::move(file)) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// One shard table, as views into the text it was parsed from (which must
// outlive it).
struct ShardTable {
  std::string name;                         // for messages
  std::vector<std::string_view> metadata;   // whole lines without '\n', "# " included
  std::size_t command_line = 0;             // index in metadata of "# command: "
  std::size_t shard_line = 0;               // ... of "# shard: "
  std::size_t regimes_line = SIZE_MAX;      // ... of "# regimes: " (sweeps only)
  std::string_view header;
  std::vector<std::string_view> rows;
  Shard shard;
  std::uint64_t total = 0;  // rows of the whole study
};

// Limits: a study has at most 10^7 rows (sweep and map refuse more), a line
// at most 64 KiB (rows are under 200 bytes; the command line is the longest).
constexpr std::uint64_t max_study_rows = 10'000'000;
constexpr std::size_t max_line_bytes = 64 * 1024;

// Throws ShardFileError naming `name` if the text is not a shard table as
// above, or its row count is not the one its shard line gives.
ShardTable parse_shard_table(std::string name, std::string_view text);

// Checks that `tables` are the N shards of one study, each once (any order),
// and returns the metadata lines of the whole table (each with "# ", without
// '\n'): shard 1's, with "# command: <command>", the shard line replaced by
// "# merged: N shards (rows 1..T)" and a sweep's regimes line recounted over
// all rows. Throws ShardFileError naming the file at fault.
std::vector<std::string> merged_metadata(const std::vector<ShardTable>& tables,
                                         const std::string& command);

// The tables in shard order (1..N), for writing their rows after the metadata
// and the common header.
std::vector<const ShardTable*> in_shard_order(const std::vector<ShardTable>& tables);

}  // namespace frictionref::cli
