// Where a command writes: standard output, or a file that appears only when
// complete (an existing device or pipe, e.g. /dev/stdout, is written directly). The file is written as "<path>.tmp.XXXXXX" in the same directory
// (same file system, so the final rename is atomic) and renamed over <path> by
// commit(); on any error, or without commit(), the temporary file is removed,
// so no partial output file ever exists.
#pragma once

#include <cstdio>
#include <optional>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace frictionref::cli {

// "-o = out.csv" for the file output opened last that is not committed yet
// ("standard output" if none): what a write error thrown mid-stream (fmt
// throws std::system_error when the disk fills) is reported against.
std::string describe_pending_output();

// The "-o FILE" option that every writing command takes: absent means stdout.
class OutputFileOption {
 public:
  void add_to(CLI::App& command);
  // The path if -o was given.
  std::optional<std::string> path() const;

 private:
  std::string path_;
  CLI::Option* option_ = nullptr;
};

class AtomicOutput {
 public:
  // No path: standard output. `option` names the path in error messages ("-o").
  // Throws bad input if the temporary file cannot be created.
  AtomicOutput(std::optional<std::string> path, std::string option);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::FILE* stream() const { return file_; }
  // The file being written, for a child process (gnuplot) that writes the
  // output by name: the temporary file, or the target itself when it is a
  // device or pipe. Empty for standard output.
  const std::string& write_path() const { return direct_ ? *path_ : temp_path_; }

  // Flushes, syncs and renames into place (or flushes stdout); throws bad
  // input naming the option on any write error.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  void discard();

  std::optional<std::string> path_;
  std::string option_;
  std::string target_;  // the file replaced on commit: the path, or where its symlink points
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  int guard_slot_ = -1;  // signal-handler slot that removes temp_path_
  bool direct_ = false;  // the target is a device or pipe: written in place, no rename
};

}  // namespace frictionref::cli
