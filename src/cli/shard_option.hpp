// `--shard I/N` of the parameter-study commands (sweep, map): the option,
// its parsing, and the '# shard:' line that `frictionref merge` reads back
// (shard_files.hpp). The library side is frictionref/shard.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "frictionref/shard.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace frictionref::cli {

// Adds --shard I/N to `command`; `unit` names what is cut ("points", "lambdas").
void add_shard_option(CLI::App& command, std::string& text, const std::string& unit);

// The shard given as --shard; `plot` is the command's --plot, which a shard
// cannot draw (it holds part of the study). Throws bad_input naming --shard.
Shard parse_shard(const std::string& text, const std::string& plot);

// "shard: I/N rows B..E of T" (rows numbered from 1 in the whole study's
// table; "rows none of T" for an empty shard), the line merge checks.
std::string shard_line(const Shard& shard, std::uint64_t total);

// The command's metadata line followed by the shard's line if --shard was
// given (even 1/1, so that a batch of one shard merges like any other).
std::vector<std::string> shard_lines(std::string line, const std::optional<Shard>& shard,
                                     std::uint64_t total);

}  // namespace frictionref::cli
