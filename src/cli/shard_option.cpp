// `--shard I/N` (shard_option.hpp).
#include "shard_option.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "cli_error.hpp"
#include "frictionref/error.hpp"

namespace frictionref::cli {

void add_shard_option(CLI::App& command, std::string& text, const std::string& unit) {
  command
      .add_option("--shard", text,
                  fmt::format("compute only shard I of N: the I-th of N contiguous blocks of the "
                              "{} (1 <= I <= N <= 10^6), for batch schedulers; join the N "
                              "outputs with 'frictionref merge'",
                              unit))
      ->type_name("I/N");
}

Shard parse_shard(const std::string& text, const std::string& plot) {
  Shard shard;
  try {
    shard = Shard::parse(text, "--shard");
  } catch (const InvalidInput& error) {
    throw bad_input(fmt::format("--shard = {}: {}", text, error.rule()));
  }
  if (!plot.empty() && !shard.whole())
    throw bad_input(fmt::format("--shard = {}: a shard holds part of the study and cannot be "
                                "drawn; leave out --plot (--plot = {})",
                                text, plot));
  return shard;
}

std::string shard_line(const Shard& shard, std::uint64_t total) {
  const Shard::Range range = shard.range(total);
  if (range.size() == 0) return fmt::format("shard: {} rows none of {}", to_string(shard), total);
  return fmt::format("shard: {} rows {}..{} of {}", to_string(shard), range.begin + 1, range.end,
                     total);
}

std::vector<std::string> shard_lines(std::string line, const std::optional<Shard>& shard,
                                     std::uint64_t total) {
  std::vector<std::string> lines{std::move(line)};
  if (shard) lines.push_back(shard_line(*shard, total));
  return lines;
}

}  // namespace frictionref::cli
