#include "run_binary.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace frictionref::cli_test {
namespace {

// Reads a whole unlinked temporary file from its start.
std::string slurp(std::FILE* file) {
  std::rewind(file);
  std::string text;
  char buffer[1 << 14];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
  std::fclose(file);
  return text;
}

// fork + exec of the binary with stdout and stderr on the given descriptors.
pid_t spawn(const std::vector<std::string>& args, const std::filesystem::path& cwd, int out_fd,
            int err_fd) {
  // Everything the child needs is built before fork: no allocation after it.
  const std::string binary = FRICTIONREF_BINARY;
  std::vector<std::string> words{binary};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string dir = cwd.string();

  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    if (!dir.empty() && chdir(dir.c_str()) != 0) _exit(126);
    if (dup2(out_fd, 1) < 0 || dup2(err_fd, 2) < 0) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

}  // namespace

int wait_exit_code(int pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int spawn_frictionref(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  const int null_fd = open("/dev/null", O_WRONLY);
  if (null_fd < 0) throw std::runtime_error("cannot open /dev/null");
  const pid_t pid = spawn(args, cwd, null_fd, null_fd);
  close(null_fd);
  return pid;
}

RunResult run_frictionref(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  // Files rather than pipes: the child can write any amount without the
  // parent having to drain two pipes at once.
  std::FILE* out = std::tmpfile();
  std::FILE* err = std::tmpfile();
  if (!out || !err) throw std::runtime_error("tmpfile failed");
  const pid_t pid = spawn(args, cwd, fileno(out), fileno(err));
  RunResult result;
  result.exit_code = wait_exit_code(pid);
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

TempDir::TempDir() {
  std::string pattern =
      (std::filesystem::temp_directory_path() / "frictionref-cli-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::vector<std::string> TempDir::entries() const {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(path_)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace frictionref::cli_test
