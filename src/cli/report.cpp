// `frictionref report`: compare's checks as a self-contained HTML page to
// attach to a validation report (report/report_page.hpp; docs/cli.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <ctime>
#include <memory>

#include "atomic_output.hpp"
#include "command.hpp"
#include "compare_run.hpp"
#include "frictionref/sha256.hpp"
#include "model_options.hpp"
#include "report/candidate_file.hpp"
#include "report/report_page.hpp"
#include "report/reproduce_commands.hpp"

namespace frictionref::cli {
namespace {

struct ReportCliOptions {
  ModelOptions model;
  CompareInputs inputs;
  OutputFileOption output;
};

// "2025-01-31 12:00:00 UTC": when the report was made (UTC, so it does not
// depend on where).
std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  char text[32] = "unknown";
  if (gmtime_r(&now, &parts) != nullptr)
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", &parts);
  return text;
}

ExitCode run_report(const ReportCliOptions& options, const Invocation& invocation) {
  // Everything typed is checked before the file is read, as by compare.
  const PreparedComparison prepared = prepare_comparison(options.inputs, options.model);
  AtomicOutput out(options.output.path(), "-o");

  // Read once: the bytes hashed are the bytes compared.
  const std::string& path = options.inputs.candidate;
  const CandidateFile file =
      translating(prepared.inputs, [&] { return read_candidate_file(path); });
  const TimeHistory history =
      translating(prepared.inputs, [&] { return parse_candidate(file, prepared.read_options); });
  const ComparisonReport report = run_comparison(prepared, history, path);

  const ReportSources sources{report,
                              history,
                              file,
                              sha256_hex(file.bytes),
                              invocation.command_line,
                              utc_now(),
                              reproduce_commands(report, options.inputs)};
  const std::string page = report_page(sources);
  if (std::fwrite(page.data(), 1, page.size(), out.stream()) != page.size())
    throw bad_input(describe_pending_output() + ": write failed");
  out.commit();
  return verdict_exit_code(report.verdict);
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto options = std::make_shared<ReportCliOptions>();
  CLI::App* command = app.add_subcommand(
      "report", "Check a time history as compare does and write a self-contained HTML report");
  options->inputs.add_to(*command, options->model);
  options->output.add_to(*command);
  command->footer(
      "Runs exactly the checks of 'frictionref compare' (same options, same verdict) and writes\n"
      "one HTML page to attach to a validation report. It holds:\n"
      "  provenance  the candidate file as given, its size and SHA-256, the columns read,\n"
      "              the frictionref version, this command line and the date (UTC);\n"
      "  model       every parameter of the model (m, B, w, R, lambda, Rs, k, c, F0, the\n"
      "              further harmonics, x0, v0, t0), its steady state and the check scales;\n"
      "  checks      the verdict, every check with its value, tolerance and unit, and the\n"
      "              options in the model's units;\n"
      "  figures     inline SVG: the exact and candidate velocities overlaid, the velocity\n"
      "              error against time with its tolerance, and a zoom on the worst stop\n"
      "              (the stop around which the candidate's velocity error is largest);\n"
      "  events      the matched, missed and extra sticks with their time errors, the regime;\n"
      "  reproduce   sha256sum, this command, the equivalent compare command, and the curve\n"
      "              and events commands for the exact reference.\n"
      "The page has no script and loads nothing (no network, fonts or style sheets): it\n"
      "renders the same offline and prints.\n"
      "Exit codes: 0 PASS, 1 FAIL, 3 INCONCLUSIVE (the samples do not resolve the exact\n"
      "motion; the report is written for all three), 2 bad input or bad file (one line on\n"
      "stderr naming the option or the file, line and column; no output file), 4 internal error.\n"
      "Examples:\n"
      "  frictionref stiff --lambda 0.7 --t-end 30 -o stiff.csv\n"
      "  frictionref report --candidate stiff.csv --lambda 0.7 -o report.html\n"
      "  frictionref report --candidate run.txt --lambda 1.01 --v0 -1 --velocity-column 3 "
      "--displacement-column 2 -o report.html\n"
      "docs/cli.md (report) describes the page; docs/cross-checking.md every check.");
  return {command,
          [options](const Invocation& invocation) { return run_report(*options, invocation); }};
}

}  // namespace frictionref::cli
