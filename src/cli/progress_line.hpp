// The progress line of the long-running commands (sweep, map, newmark):
// "frictionref sweep: 41234/100000 lambdas (41%), 4 s so far, about 6 s left",
// rewritten in place on a terminal, and only once the run has taken longer
// than the delay (1 s; FRICTIONREF_PROGRESS_DELAY seconds if set, for tests).
// Never written to a file or pipe. The line is blanked out when the run ends,
// or when an error unwinds past it.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace frictionref::cli {

class ProgressLine {
 public:
  // command: "sweep"; items: what is counted, "lambdas".
  ProgressLine(std::string command, std::string items);
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(std::size_t done, std::size_t total);
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  std::string command_, items_;
  Clock::time_point start_;
  bool enabled_;
  double delay_ = 1.0;
  std::size_t shown_ = 0;  // length of the line on screen, 0 if none
};

}  // namespace frictionref::cli
