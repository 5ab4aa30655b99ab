// Runs the real frictionref binary (fork/exec, no shell) and captures its
// stdout, stderr and exit code; plus a scratch directory per test.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frictionref::cli_test {

struct RunResult {
  int exit_code = -1;  // 128 + signal number if killed by a signal
  std::string out;
  std::string err;
};

// argv[0] is the binary; args follow. cwd: working directory of the child
// (empty: ours).
RunResult run_frictionref(const std::vector<std::string>& args,
                          const std::filesystem::path& cwd = {});

// Starts the binary without waiting (stdout and stderr to /dev/null);
// wait_exit_code() collects it: exit code, or 128 + signal number.
int spawn_frictionref(const std::vector<std::string>& args, const std::filesystem::path& cwd);
int wait_exit_code(int pid);

// A fresh empty directory, removed with its contents at scope exit.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // Names of all entries (files, directories), sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& path);

}  // namespace frictionref::cli_test
