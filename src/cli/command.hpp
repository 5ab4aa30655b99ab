// What every command file hands to main(): its CLI11 subcommand and the
// function to run when the user chose it (dispatch after parsing, so CLI11's
// own errors are all raised before any command starts working).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "cli_error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/types.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace frictionref::cli {

// Facts about this run that outputs record.
struct Invocation {
  std::string command_line;  // argv, shell-quoted, for "# command:"
};

// run() returns the exit code: exit_success, or exit_compare_failed for a
// FAIL verdict; errors are thrown as CliError.
struct Command {
  CLI::App* app = nullptr;
  std::function<ExitCode(const Invocation&)> run;
};

// Larger outputs need --force: a typo in --t-end or --dt must not fill the disk
// or run for days.
constexpr std::uint64_t max_rows_without_force = 1'000'000'000;

// The engine stops early only on a broken invariant (we never set max_phases):
// an internal error, raised before the output is committed.
inline void require_reached_end(const Summary& summary) {
  if (summary.termination != Termination::reached_end) {
    throw internal_error(std::string(to_string(summary.termination)) + ": " + summary.message);
  }
}

Command add_events_command(CLI::App& app);
Command add_curve_command(CLI::App& app);
Command add_reproduce_command(CLI::App& app);
Command add_classify_command(CLI::App& app);
Command add_stiff_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_convergence_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_map_command(CLI::App& app);
Command add_merge_command(CLI::App& app);
Command add_newmark_command(CLI::App& app);

}  // namespace frictionref::cli
