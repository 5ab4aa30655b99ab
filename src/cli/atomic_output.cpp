#include "atomic_output.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <signal.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <vector>

#include "cli_error.hpp"

namespace frictionref::cli {
namespace {

constexpr std::size_t buffer_bytes = 1 << 16;  // rows are short; fewer write calls

// Ctrl-C or kill during a long run must not leave a temporary file behind:
// the handler removes every pending one (unlink is async-signal-safe) and then
// dies of the same signal as it would have without us. A command has at most
// a few outputs open at once (a table and its figure).
constexpr int max_pending = 8;
char pending_temp[max_pending][4096];
volatile std::sig_atomic_t pending_used[max_pending] = {};

extern "C" void remove_pending_temp(int signal_number) {
  for (int i = 0; i < max_pending; ++i)
    if (pending_used[i]) unlink(pending_temp[i]);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// Returns the slot that guards `path`, or -1 if none is free (then the file
// is still removed on every normal exit path, just not on a signal).
int guard_temp_file(const std::string& path) {
  static const bool installed = [] {
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
      // A signal the caller ignores (nohup, background jobs) stays ignored.
      if (std::signal(signal_number, remove_pending_temp) == SIG_IGN) {
        std::signal(signal_number, SIG_IGN);
      }
    }
    return true;
  }();
  (void)installed;
  if (path.size() >= sizeof pending_temp[0]) return -1;
  for (int i = 0; i < max_pending; ++i) {
    if (pending_used[i]) continue;
    std::memcpy(pending_temp[i], path.c_str(), path.size() + 1);
    pending_used[i] = 1;
    return i;
  }
  return -1;
}

void unguard_temp_file(int slot) {
  if (slot >= 0) pending_used[slot] = 0;
}

// mkstemp makes the file 0600; give the result the permissions any newly
// created file would get (0666 less the umask).
void set_default_permissions(int fd) {
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
}

std::string pending_output;  // describe_pending_output()

}  // namespace

std::string describe_pending_output() {
  return pending_output.empty() ? std::string("standard output") : pending_output;
}

AtomicOutput::AtomicOutput(std::optional<std::string> path, std::string option)
    : path_(std::move(path)), option_(std::move(option)) {
  if (!path_) {
    file_ = stdout;
    std::setvbuf(file_, nullptr, _IOFBF, buffer_bytes);
    return;
  }
  if (path_->empty()) fail("must not be empty");
  pending_output = option_ + " = " + *path_;
  namespace fs = std::filesystem;
  std::error_code ignored;
  if (fs::is_directory(*path_, ignored)) fail("is a directory");
  // A symbolic link stays a link: the file it points to is what gets
  // replaced. A link into something that is no file (/dev/stdout to a pipe)
  // and any existing device or pipe (/dev/null, /dev/full, a FIFO) cannot be
  // replaced by a rename, and must not be: those are written in place.
  // Names of an open descriptor (/dev/stdout, /dev/fd/3, /proc/self/fd/1)
  // mean that descriptor, whatever file it happens to be: also in place.
  const auto descriptor_alias = [](const std::string& name) {
    return name.rfind("/proc/self/fd/", 0) == 0 || name.rfind("/dev/fd/", 0) == 0 ||
           name == "/dev/stdout" || name == "/dev/stderr";
  };
  std::string target = *path_;
  const bool link = fs::is_symlink(fs::symlink_status(*path_, ignored));
  bool in_place = descriptor_alias(*path_);
  if (link) {
    in_place |= descriptor_alias(fs::read_symlink(*path_, ignored).string());
    std::error_code unresolved;
    const fs::path resolved = fs::canonical(*path_, unresolved);
    if (unresolved) in_place = true;  // a link to something that is no file
    else target = resolved.string();
  }
  const auto status = fs::status(target, ignored);
  if (in_place || (fs::exists(status) && !fs::is_regular_file(status))) {
    direct_ = true;
    file_ = std::fopen(path_->c_str(), "w");
    if (!file_) fail(fmt::format("cannot open for writing: {}", std::strerror(errno)));
    std::setvbuf(file_, nullptr, _IOFBF, buffer_bytes);
    return;
  }
  target_ = target;

  std::vector<char> name(target_.begin(), target_.end());
  const std::string suffix = ".tmp.XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  // Creating the file and registering it for removal on a signal is one step
  // for the signals we clean up after: one arriving in between would
  // otherwise leave the new file behind.
  sigset_t cleanup_signals, previous;
  sigemptyset(&cleanup_signals);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&cleanup_signals, signal_number);
  sigprocmask(SIG_BLOCK, &cleanup_signals, &previous);
  const int fd = mkstemp(name.data());
  const int create_error = errno;
  if (fd >= 0) {
    temp_path_ = name.data();
    guard_slot_ = guard_temp_file(temp_path_);
  }
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  if (fd < 0) fail(fmt::format("cannot create a file there: {}", std::strerror(create_error)));
  set_default_permissions(fd);
  file_ = fdopen(fd, "w");
  if (!file_) {
    const int error = errno;
    close(fd);
    discard();
    fail(fmt::format("cannot open for writing: {}", std::strerror(error)));
  }
  std::setvbuf(file_, nullptr, _IOFBF, buffer_bytes);
}

AtomicOutput::~AtomicOutput() { discard(); }

void AtomicOutput::discard() {
  if (!path_) return;
  if (direct_) {
    if (file_) std::fclose(file_);
    file_ = nullptr;
    return;
  }
  if (file_) std::fclose(file_);
  file_ = nullptr;
  if (!temp_path_.empty()) std::remove(temp_path_.c_str());
  temp_path_.clear();
  unguard_temp_file(guard_slot_);
  guard_slot_ = -1;
}

void AtomicOutput::commit() {
  if (direct_) {
    const bool written = std::fflush(file_) == 0 && !std::ferror(file_);
    const int error = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!written || !closed) fail(fmt::format("write failed: {}", std::strerror(error)));
    pending_output.clear();
    return;
  }
  if (!path_) {
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
      throw bad_input(fmt::format("writing to standard output failed: {}", std::strerror(errno)));
    }
    return;
  }
  // fsync before rename: after a crash the name shows the old file or the
  // complete new one, never a truncated one.
  const bool written = std::fflush(file_) == 0 && !std::ferror(file_) && fsync(fileno(file_)) == 0;
  const int write_error = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!written || !closed) {
    discard();
    fail(fmt::format("write failed: {}", std::strerror(written ? errno : write_error)));
  }
  if (std::rename(temp_path_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    discard();
    fail(fmt::format("cannot rename the finished file into place: {}", std::strerror(error)));
  }
  temp_path_.clear();
  unguard_temp_file(guard_slot_);
  guard_slot_ = -1;
  pending_output.clear();
}

void AtomicOutput::fail(const std::string& what) const {
  throw bad_input(fmt::format("{} = {}: {}", option_, *path_, what));
}

void OutputFileOption::add_to(CLI::App& command) {
  option_ = command
                .add_option("-o", path_,
                            "write to FILE (atomically: complete or not at all) instead of stdout")
                ->type_name("FILE");
}

std::optional<std::string> OutputFileOption::path() const {
  if (option_ == nullptr || option_->count() == 0) return std::nullopt;
  return path_;
}

}  // namespace frictionref::cli
