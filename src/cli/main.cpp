// frictionref: the command-line program. Parses with CLI11, runs the chosen
// command, and turns every failure into one line on stderr and an exit code
// (cli_error.hpp; docs/cli.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <system_error>
#include <vector>

#include "atomic_output.hpp"
#include "cli_error.hpp"
#include "command.hpp"
#include "csv_format.hpp"
#include "frictionref/error.hpp"
#include "frictionref/version.hpp"

namespace frictionref::cli {

namespace {

constexpr const char* usage =
    "usage: frictionref "
    "{events|curve|classify|reproduce|stiff|compare|report|convergence|sweep|map|merge|newmark} "
    "[options] (see frictionref --help)";

// Scripts read stderr line by line: whatever the message, it is one line.
int report(ExitCode code, std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  std::fflush(stdout);
  fmt::print(stderr, "frictionref: error: {}\n", message);
  return code;
}

// CLI11 calls an unknown command an unexpected argument; say what it is.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc,
                                char** argv) {
  const bool no_command = app.get_subcommands().empty();
  if (no_command && dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    for (int i = 1; i < argc; ++i) {
      if (argv[i][0] != '-') return fmt::format("unknown command '{}'; {}", argv[i], usage);
    }
  }
  return error.what();
}

int run(int argc, char** argv) {
  CLI::App app(
      "frictionref: the exact motion of a mass m with Coulomb friction, a spring k and a\n"
      "damper c, driven by F(t) = F0 + B sin(w t) + sum B_i sin(w_i t + phi_i):\n"
      "  m x'' + c x' + k x = F(t) - R sign(v) while sliding (friction R);\n"
      "  at rest while |F(t) - k x| <= Rs (static friction Rs >= R, default R).\n"
      "The seed's model is k = c = F0 = 0, one harmonic, Rs = R: lambda = R / B decides its\n"
      "steady state. Each phase is solved in closed form and every stop, reversal and\n"
      "breakaway is found exactly: no time step, no tolerance.",
      "frictionref");
  app.set_version_flag("--version", std::string("frictionref ") + version,
                       "print 'frictionref <version>' and exit");
  app.require_subcommand(0, 1);
  app.footer(
      "Units: any consistent set (force = mass * length / time^2); w in rad per time unit.\n"
      "Defaults: --mass 1 --amplitude 1 --omega 1 --x0 0 --v0 0 --t0 0; exactly one of\n"
      "--friction R or --lambda L (R = L * B) is required.\n"
      "Output goes to stdout, or with -o FILE atomically to FILE; numbers are printed in the\n"
      "shortest form that reads back to the same double.\n"
      "Exit codes: 0 success; 1 compare, report: verdict FAIL; 3 compare, report: verdict\n"
      "INCONCLUSIVE (the samples do not resolve the exact motion); 2 bad input or unwritable "
      "output\n"
      "(one line on stderr naming the option, no output file); 4 internal error (please report).\n"
      "Examples:\n"
      "  frictionref classify --lambda 0.7\n"
      "  frictionref events --lambda 0.3 --t-end 30 -o events.csv\n"
      "  frictionref curve --lambda 0.7 --t-end 30 --dt 0.01 --include-events\n"
      "  frictionref reproduce --out results\n"
      "  frictionref stiff --lambda 0.7 --t-end 30 --kf 1e7 -o stiff.csv\n"
      "  frictionref compare --lambda 0.7 --candidate stiff.csv --plot compare.svg\n"
      "  frictionref report --lambda 0.7 --candidate stiff.csv -o report.html\n"
      "  frictionref convergence --lambda 0.7 --format markdown\n"
      "  frictionref sweep --lambda-from 0 --lambda-to 1.2 --points 1201 --plot sweep.svg\n"
      "  frictionref newmark --record data/records/synthetic/pulse-train.AT2 --yield-accel "
      "0.05,0.1,0.2\n"
      "'frictionref <command> --help' explains each command; docs/cli.md has the formats.");

  const std::vector<Command> commands{
      add_events_command(app),   add_curve_command(app),       add_reproduce_command(app),
      add_classify_command(app), add_stiff_command(app),       add_compare_command(app),
      add_report_command(app),   add_convergence_command(app), add_sweep_command(app),
      add_map_command(app),      add_merge_command(app),       add_newmark_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& help_or_version) {
    return app.exit(help_or_version);
  } catch (const CLI::ParseError& error) {
    return report(exit_bad_input, parse_error_message(app, error, argc, argv));
  }

  const Invocation invocation{command_line(argc, argv)};
  for (const Command& command : commands) {
    if (command.app->parsed()) return command.run(invocation);
  }
  return report(exit_bad_input, std::string("a command is required; ") + usage);
}

}  // namespace
}  // namespace frictionref::cli

int main(int argc, char** argv) {
  using namespace frictionref::cli;
  try {
    return run(argc, argv);
  } catch (const CliError& error) {
    return report(error.code(), error.what());
  } catch (const std::system_error& error) {
    // A write that failed mid-stream (disk full, I/O error): the output's
    // temporary file is already gone (unwound); say which output it was.
    return report(exit_bad_input,
                  describe_pending_output() + ": write failed: " + error.code().message());
  } catch (const frictionref::InvalidInput& error) {
    // Commands translate these to option names; this is the safety net.
    return report(exit_bad_input, error.what());
  } catch (const std::exception& error) {
    return report(exit_internal_error, std::string("internal error: ") + error.what());
  }
}
