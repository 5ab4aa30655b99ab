// `frictionref compare` on files written like third-party codes write them
// (tests/data/candidates/, made by its committed generator make_candidates.py
// with an independent stick-slip integrator): the verdict, the exit code and
// the defect named in the report's first line, for each defect and file shape.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_binary.hpp"

namespace frictionref::cli_test {
namespace {

std::string candidate(const std::string& name) {
  return std::string(FRICTIONREF_SOURCE_DIR) + "/tests/data/candidates/" + name;
}

// The first line of the text report after the '#' comment lines.
std::string first_report_line(const std::string& out) {
  std::size_t at = 0;
  while (at < out.size() && out[at] == '#') at = out.find('\n', at) + 1;
  return out.substr(at, out.find('\n', at) - at);
}

RunResult compare(const std::string& file, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"compare", "--candidate", candidate(file)};
  if (more.empty()) more = {"--lambda", "0.7"};
  args.insert(args.end(), more.begin(), more.end());
  return run_frictionref(args);
}

TEST(CompareCandidates, AccurateRunAndEveryFileShapePass) {
  for (const std::vector<std::string>& run :
       {std::vector<std::string>{"accurate.csv"},
        {"shape_semicolon_decimal_comma.csv"},
        {"shape_unit_suffixes.csv"},
        {"shape_title_lines.csv"},
        {"shape_restart_overlap.csv", "--on-overlap", "keep-last"}}) {
    std::vector<std::string> more = {"--lambda", "0.7", "--displacement-column", "2"};
    more.insert(more.end(), run.begin() + 1, run.end());
    const RunResult r = compare(run[0], more);
    EXPECT_EQ(r.exit_code, 0) << run[0] << "\n" << r.out << r.err;
    EXPECT_EQ(first_report_line(r.out).rfind("diagnosis: no defect: ", 0), 0u) << r.out;
  }
}

TEST(CompareCandidates, RestartWithoutKeepLastIsRefusedNamingTheOption) {
  const RunResult r = compare("shape_restart_overlap.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("--on-overlap keep-last"), std::string::npos) << r.err;
}

TEST(CompareCandidates, ShiftedRunIsATimeShiftOf003) {
  const RunResult r = compare("shifted.csv", {"--lambda", "0.7", "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["diagnosis"]["defect"], "time_shift");
  EXPECT_NEAR(json["diagnosis"]["value"].get<double>(), 0.03, 1e-6);
  const RunResult text = compare("shifted.csv");
  EXPECT_EQ(first_report_line(text.out).rfind(
                "diagnosis: time shift: the candidate runs late by 0.03 ", 0),
            0u)
      << text.out;
}

TEST(CompareCandidates, TanhRegularisedRunIsCreep) {
  const RunResult r = compare("tanh.csv", {"--lambda", "1.01"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(
      first_report_line(r.out).rfind("diagnosis: creep: the candidate moves at up to 0.0026", 0),
      0u)
      << r.out;
}

// Breakaways tested only at the archive times 0, 5, ..., 30: never PASS, and
// the defect named is the missed breakaway.
TEST(CompareCandidates, CoarseArchiveThatMissesBreakawaysIsAMissedBreakaway) {
  const RunResult r = compare("coarse_missed_breakaways.csv");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(first_report_line(r.out).rfind("diagnosis: missed breakaway: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("\nresolution: "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace frictionref::cli_test
