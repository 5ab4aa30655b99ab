// Exit codes of the frictionref command and the one exception that carries
// them from a command to main(), which prints it as one line on stderr.
#pragma once

#include <stdexcept>
#include <string>

#include "frictionref/comparison.hpp"

namespace frictionref::cli {

// Scripts depend on these values (docs/cli.md); never renumber them. (Once:
// 3 became INCONCLUSIVE and the internal error 4, as issue 13 set them.)
enum ExitCode : int {
  exit_success = 0,
  exit_compare_failed = 1,  // `compare`, `report`: the candidate failed a check (verdict FAIL)
  exit_bad_input = 2,       // bad option, value or output path: fix the command line
  exit_inconclusive = 3,    // `compare`, `report`: the samples do not resolve the exact motion
  exit_internal_error = 4,  // a broken engine invariant: please report
};

// what() is the message without the "frictionref: error: " prefix.
class CliError : public std::runtime_error {
 public:
  CliError(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

inline CliError bad_input(const std::string& message) { return CliError(exit_bad_input, message); }

// The exit code of a verdict: 0 PASS, 1 FAIL, 3 INCONCLUSIVE.
inline ExitCode verdict_exit_code(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass:
      return exit_success;
    case Verdict::fail:
      return exit_compare_failed;
    case Verdict::inconclusive:
      return exit_inconclusive;
  }
  return exit_internal_error;
}

inline CliError internal_error(const std::string& message) {
  return CliError(exit_internal_error, "internal error: " + message);
}

}  // namespace frictionref::cli
