// Exit codes of the frictionref command and the one exception that carries
// them from a command to main(), which prints it as one line on stderr.
#pragma once

#include <stdexcept>
#include <string>

namespace frictionref::cli {

// Scripts depend on these values (docs/cli.md); never renumber them.
enum ExitCode : int {
  exit_success = 0,
  exit_compare_failed = 1,  // `compare`: the candidate failed a check (verdict FAIL)
  exit_bad_input = 2,       // bad option, value or output path: fix the command line
  exit_internal_error = 3,  // a broken engine invariant: please report
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

inline CliError internal_error(const std::string& message) {
  return CliError(exit_internal_error, "internal error: " + message);
}

}  // namespace frictionref::cli
