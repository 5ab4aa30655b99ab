// Reading and joining shard tables (shard_files.hpp).
#include "shard_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>
#include <system_error>

#include "frictionref/error.hpp"
#include "sweep_summary.hpp"

namespace frictionref::cli {
namespace {

constexpr std::size_t max_metadata_lines = 64;
constexpr std::string_view what_it_should_be =
    "not a table written by 'frictionref sweep --shard' or 'frictionref map --shard'";

bool starts_with(std::string_view text, std::string_view start) {
  return text.substr(0, start.size()) == start;
}

// A whole decimal number (digits only) no larger than `max`.
std::optional<std::uint64_t> whole_number(std::string_view text, std::uint64_t max) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end || value > max) return std::nullopt;
  return value;
}

std::size_t fields(std::string_view line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

// "shard: I/N rows B..E of T" or "shard: I/N rows none of T" (after "# ").
void read_shard_line(ShardTable& table, std::string_view line) {
  const auto bad = [&](const std::string& why) {
    return ShardFileError(table.name, fmt::format("its line '# {}' {}", line, why));
  };
  const std::string_view rule = "must read 'shard: I/N rows B..E of T'";
  std::string_view rest = line.substr(std::string_view("shard: ").size());
  const std::size_t space = rest.find(' ');
  if (space == std::string_view::npos) throw bad(std::string(rule));
  try {
    table.shard = Shard::parse(rest.substr(0, space), "shard");
  } catch (const InvalidInput& error) {
    throw bad(error.rule());
  }
  rest = rest.substr(space + 1);
  if (!starts_with(rest, "rows ")) throw bad(std::string(rule));
  rest = rest.substr(5);
  const std::size_t of = rest.find(" of ");
  if (of == std::string_view::npos) throw bad(std::string(rule));
  const auto total = whole_number(rest.substr(of + 4), max_study_rows);
  if (!total || *total == 0) throw bad("must end with the study's rows, 1 to 10^7");
  table.total = *total;
  const Shard::Range range = table.shard.range(table.total);
  const std::string_view rows = rest.substr(0, of);
  const std::string expected =
      range.size() == 0 ? std::string("none") : fmt::format("{}..{}", range.begin + 1, range.end);
  if (rows != expected)
    throw bad(fmt::format("gives rows {} where shard {} of {} rows is rows {}", rows,
                          to_string(table.shard), table.total, expected));
}

// The value of "key=" in a metadata line (up to the next space).
std::optional<std::uint64_t> field_value(std::string_view line, std::string_view key) {
  const std::size_t at = line.find(fmt::format(" {}=", key));
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view value = line.substr(at + key.size() + 2);
  value = value.substr(0, value.find(' '));
  return whole_number(value, UINT64_MAX);
}

// Column `name` of the header, if it has one.
std::optional<std::size_t> column(std::string_view header, std::string_view name) {
  std::size_t index = 0, begin = 0;
  for (;;) {
    const std::size_t comma = header.find(',', begin);
    if (header.substr(begin, comma == std::string_view::npos ? comma : comma - begin) == name)
      return index;
    if (comma == std::string_view::npos) return std::nullopt;
    begin = comma + 1;
    ++index;
  }
}

std::string_view field(std::string_view row, std::size_t index) {
  std::size_t begin = 0;
  for (std::size_t i = 0; i < index; ++i) begin = row.find(',', begin) + 1;
  return row.substr(begin, row.find(',', begin) - begin);
}

// A sweep's '# regimes:' line recounted over the rows of every table.
std::string recount_regimes(const std::vector<ShardTable>& tables, const ShardTable& first) {
  const std::string_view line = first.metadata[first.regimes_line].substr(2);
  const auto bad = [&](const std::string& why) { return ShardFileError(first.name, why); };
  const auto rule = regimes_rule(line);
  if (!rule) throw bad(fmt::format("its line '# {}' is not a sweep's regimes line", line));
  std::optional<std::uint64_t> periods;
  for (std::string_view meta : first.metadata)
    if (starts_with(meta, "# sweep: ")) periods = field_value(meta, "periods");
  if (!periods || *periods == 0 || *periods > SweepOptions::max_periods)
    throw bad("has a '# regimes:' line but no '# sweep: ... periods=P' line with P from 1 to 10^6");
  const auto simulated = column(first.header, "regime_simulated");
  const auto threshold = column(first.header, "regime_threshold");
  if (!simulated || !threshold)
    throw bad("has a '# regimes:' line but no regime_simulated and regime_threshold columns");
  RegimeCounts counts;
  for (const ShardTable& table : tables) {
    for (std::string_view row : table.rows) {
      const std::string_view s = field(row, *simulated), t = field(row, *threshold);
      ++counts.rows;
      if (t != "n/a") {
        ++counts.known;
        counts.differ += s != t;
      }
    }
  }
  return "# " + regimes_line(*rule, counts, *periods);
}

}  // namespace

ShardTable parse_shard_table(std::string name, std::string_view text) {
  ShardTable table;
  table.name = std::move(name);
  const auto bad = [&](const std::string& why) { return ShardFileError(table.name, why); };
  if (text.empty()) throw bad(fmt::format("is empty: {}", what_it_should_be));
  if (text.back() != '\n')
    throw bad("does not end with a newline: it is incomplete (cut off, or still being written)");

  std::size_t begin = 0;
  bool header_seen = false;
  std::optional<std::size_t> shard_line;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);  // found: the text ends with one
    const std::string_view line = text.substr(begin, end - begin);
    const std::size_t number = table.metadata.size() + header_seen + table.rows.size() + 1;
    begin = end + 1;
    if (line.size() > max_line_bytes)
      throw bad(fmt::format("line {} is longer than 64 KiB: {}", number, what_it_should_be));
    if (!header_seen && !line.empty() && line.front() == '#') {
      if (!starts_with(line, "# "))
        throw bad(fmt::format("line {} starts with '#' but not '# ': {}", number,
                              what_it_should_be));
      if (table.metadata.size() == max_metadata_lines)
        throw bad(fmt::format("has more than {} '#' lines: {}", max_metadata_lines,
                              what_it_should_be));
      const std::size_t index = table.metadata.size();
      if (starts_with(line, "# merged: "))
        throw bad("is a merged table (it has a '# merged:' line), not a shard");
      if (index != 2 && starts_with(line, "# command: "))
        throw bad(fmt::format("line {} is a second '# command:' line", number));
      if (starts_with(line, "# shard: ")) {
        if (shard_line) throw bad("has two '# shard:' lines");
        shard_line = index;
      } else if (starts_with(line, "# regimes: ")) {
        if (table.regimes_line != SIZE_MAX) throw bad("has two '# regimes:' lines");
        table.regimes_line = index;
      }
      table.metadata.push_back(line);
      continue;
    }
    if (!header_seen) {
      if (line.empty()) throw bad(fmt::format("line {} is empty where the header should be", number));
      table.header = line;
      header_seen = true;
      continue;
    }
    if (table.rows.size() == max_study_rows)
      throw bad("has more than 10^7 rows, more than any study");
    if (line.empty() || line.front() == '#' || fields(line) != fields(table.header))
      throw bad(fmt::format("line {} is not a row of {} fields like its header", number,
                            fields(table.header)));
    table.rows.push_back(line);
  }
  if (!header_seen) throw bad(fmt::format("has no header line: {}", what_it_should_be));
  const auto& m = table.metadata;
  if (m.size() < 3 || !starts_with(m[0], "# frictionref ") || !starts_with(m[1], "# model: ") ||
      !starts_with(m[2], "# command: "))
    throw bad(fmt::format("does not begin with '# frictionref', '# model:' and '# command:' lines: "
                          "{}",
                          what_it_should_be));
  table.command_line = 2;
  if (!shard_line)
    throw bad("has no '# shard:' line: it was not written with --shard I/N (a whole study "
              "needs no merge)");
  table.shard_line = *shard_line;
  read_shard_line(table, m[*shard_line].substr(2));
  const std::size_t expected = table.shard.range(table.total).size();
  if (table.rows.size() != expected)
    throw bad(fmt::format("holds {} rows where its shard line gives {}: incomplete or edited",
                          table.rows.size(), expected));
  return table;
}

std::vector<const ShardTable*> in_shard_order(const std::vector<ShardTable>& tables) {
  std::vector<const ShardTable*> ordered;
  for (const ShardTable& table : tables) ordered.push_back(&table);
  std::sort(ordered.begin(), ordered.end(), [](const ShardTable* a, const ShardTable* b) {
    return a->shard.index < b->shard.index;
  });
  return ordered;
}

std::vector<std::string> merged_metadata(const std::vector<ShardTable>& tables,
                                         const std::string& command) {
  if (tables.empty()) throw ShardFileError("", "no shard files given");
  const std::vector<const ShardTable*> ordered = in_shard_order(tables);
  const ShardTable& first = *ordered.front();
  const std::uint64_t count = first.shard.count;
  // The lines that must be the same in every shard: all but command, shard, regimes.
  const auto common = [](const ShardTable& table) {
    std::vector<std::string_view> lines;
    for (std::size_t i = 0; i < table.metadata.size(); ++i)
      if (i != table.command_line && i != table.shard_line && i != table.regimes_line)
        lines.push_back(table.metadata[i]);
    return lines;
  };
  const std::vector<std::string_view> first_common = common(first);
  for (const ShardTable* table : ordered) {
    if (table->shard.count != count || table->total != first.total)
      throw ShardFileError(table->name,
                           fmt::format("is shard {} of a study of {} rows, but {} is shard {} of "
                                       "{} rows: not shards of one study",
                                       to_string(table->shard), table->total, first.name,
                                       to_string(first.shard), first.total));
    if (common(*table) != first_common || (table->regimes_line == SIZE_MAX) !=
                                              (first.regimes_line == SIZE_MAX))
      throw ShardFileError(table->name,
                           fmt::format("its '#' lines (version, model, study) differ from {}'s: "
                                       "not shards of one study",
                                       first.name));
    if (table->header != first.header)
      throw ShardFileError(table->name,
                           fmt::format("its header differs from {}'s", first.name));
  }
  for (std::size_t i = 1; i < ordered.size(); ++i)
    if (ordered[i]->shard.index == ordered[i - 1]->shard.index)
      throw ShardFileError(ordered[i]->name,
                           fmt::format("is shard {}, and so is {}: give each shard once",
                                       to_string(ordered[i]->shard), ordered[i - 1]->name));
  if (ordered.size() != count) {
    // Distinct indices 1..count, fewer than count of them: name the first gap.
    std::uint64_t missing = 1;
    while (missing <= ordered.size() && ordered[missing - 1]->shard.index == missing) ++missing;
    throw ShardFileError("", fmt::format("shard {}/{} is missing: {} of the {} shards given",
                                         missing, count, ordered.size(), count));
  }

  std::vector<std::string> lines;
  for (std::size_t i = 0; i < first.metadata.size(); ++i) {
    if (i == first.command_line)
      lines.push_back("# command: " + command);
    else if (i == first.shard_line)
      lines.push_back(fmt::format("# merged: {} shards (rows 1..{})", count, first.total));
    else if (i == first.regimes_line)
      lines.push_back(recount_regimes(tables, first));
    else
      lines.emplace_back(first.metadata[i]);
  }
  return lines;
}

}  // namespace frictionref::cli
