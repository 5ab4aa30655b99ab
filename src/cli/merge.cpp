// `frictionref merge`: joins the tables of `sweep --shard I/N` or
// `map --shard I/N` (shard_files.hpp) into the table of the whole study:
// the same rows, in the same order, as the study run unsharded.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "atomic_output.hpp"
#include "command.hpp"
#include "shard_files.hpp"

namespace frictionref::cli {
namespace {

// The shards are held in memory while they are checked; a 10^7-row study
// is under 1.5 GB of text. More than this is not a study's output.
constexpr std::uintmax_t max_total_bytes = 2ull << 30;

struct MergeCliOptions {
  std::vector<std::string> files;
  OutputFileOption output;
};

std::string read_shard_file(const std::string& path, std::uintmax_t& total_bytes) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw bad_input(fmt::format("{}: cannot be read ({})", path, std::strerror(errno)));
  if (!S_ISREG(info.st_mode)) throw bad_input(fmt::format("{}: not a regular file", path));
  total_bytes += static_cast<std::uintmax_t>(info.st_size);
  if (total_bytes > max_total_bytes)
    throw bad_input(fmt::format("{}: the shard files given hold more than 2 GiB, more than any "
                                "study's output (10^7 rows)",
                                path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad_input(fmt::format("{}: cannot be read ({})", path, std::strerror(errno)));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw bad_input(fmt::format("{}: cannot be read (input error)", path));
  return text;
}

CliError merge_error(const ShardFileError& error) {
  if (error.file().empty()) return bad_input(error.what());
  return bad_input(fmt::format("{}: {}", error.file(), error.what()));
}

void run_merge(const MergeCliOptions& options, const Invocation& invocation) {
  std::uintmax_t total_bytes = 0;
  std::vector<std::string> texts;
  texts.reserve(options.files.size());
  for (const std::string& path : options.files) texts.push_back(read_shard_file(path, total_bytes));
  std::vector<ShardTable> tables;
  std::vector<std::string> metadata;
  try {
    for (std::size_t i = 0; i < texts.size(); ++i)
      tables.push_back(parse_shard_table(options.files[i], texts[i]));
    metadata = merged_metadata(tables, invocation.command_line);
  } catch (const ShardFileError& error) {
    throw merge_error(error);
  }
  AtomicOutput out(options.output.path(), "-o");
  std::FILE* stream = out.stream();
  for (const std::string& line : metadata) fmt::print(stream, "{}\n", line);
  fmt::print(stream, "{}\n", tables.front().header);
  for (const ShardTable* table : in_shard_order(tables))
    for (std::string_view row : table->rows) fmt::print(stream, "{}\n", row);
  out.commit();
}

}  // namespace

Command add_merge_command(CLI::App& app) {
  auto options = std::make_shared<MergeCliOptions>();
  CLI::App* command = app.add_subcommand(
      "merge", "Join the N shard files of a sharded sweep or map into the whole study's table");
  command->add_option("files", options->files, "the shard files, in any order (each shard once)")
      ->required()
      ->type_name("FILE...");
  options->output.add_to(*command);
  command->footer(
      "The files are the outputs of one 'frictionref sweep ... --shard I/N' or 'frictionref\n"
      "map ... --shard I/N' for I = 1..N (the same options otherwise). merge checks that they\n"
      "are the N shards of one study (same version, model, study line and header; every\n"
      "shard once; each complete, with the rows its '# shard:' line gives) and writes the\n"
      "whole study's table: the rows of shards 1..N in order, which are the rows the study\n"
      "gives unsharded, character for character. Its '#' lines are shard 1's, with the merge's\n"
      "own '# command:', '# merged: N shards (rows 1..T)' in place of '# shard:', and a sweep's\n"
      "'# regimes:' counts recounted over all rows.\n"
      "Exit codes: 0 ok, 2 a file unreadable, not a shard table, incomplete, or not of the\n"
      "same study as the others, or a shard missing or given twice (one line on stderr naming\n"
      "the file, no output file).\n"
      "Example (a SLURM array job with 8 tasks, then the merge):\n"
      "  frictionref map --x lambda:0:1.2:241 --y frequency-ratio:0.1:3:146 --stiffness 1 \\\n"
      "      --shard ${SLURM_ARRAY_TASK_ID}/8 -o map-${SLURM_ARRAY_TASK_ID}.csv\n"
      "  frictionref merge map-*.csv -o map.csv");
  return {command, [options](const Invocation& invocation) {
            run_merge(*options, invocation);
            return exit_success;
          }};
}

}  // namespace frictionref::cli
