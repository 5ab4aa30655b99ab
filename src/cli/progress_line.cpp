#include "progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <utility>

namespace frictionref::cli {

ProgressLine::ProgressLine(std::string command, std::string items)
    : command_(std::move(command)),
      items_(std::move(items)),
      start_(Clock::now()),
      enabled_(isatty(STDERR_FILENO) == 1) {
  if (const char* delay = std::getenv("FRICTIONREF_PROGRESS_DELAY")) {
    char* end = nullptr;
    const double seconds = std::strtod(delay, &end);
    if (end != delay && seconds >= 0) delay_ = seconds;
  }
}

void ProgressLine::update(std::size_t done, std::size_t total) {
  if (!enabled_ || done >= total) return;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (elapsed < delay_) return;
  std::string line = fmt::format("frictionref {}: {}/{} {} ({}%), {:.0f} s so far", command_, done,
                                 total, items_, done * 100 / total, elapsed);
  if (done > 0)
    line += fmt::format(", about {:.0f} s left",
                        elapsed * static_cast<double>(total - done) / static_cast<double>(done));
  const std::size_t width = line.size();
  if (line.size() < shown_) line.append(shown_ - line.size(), ' ');
  fmt::print(stderr, "\r{}", line);
  std::fflush(stderr);
  shown_ = width;
}

void ProgressLine::clear() {
  if (shown_ == 0) return;
  fmt::print(stderr, "\r{}\r", std::string(shown_, ' '));
  std::fflush(stderr);
  shown_ = 0;
}

}  // namespace frictionref::cli
