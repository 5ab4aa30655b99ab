// `frictionref report` through the real binary: exit codes as compare (0
// PASS, 1 FAIL with the page written, 2 bad input with no file), the verdict
// and checks compare gives, the model and provenance (SHA-256 against an
// independent value), escaping of hostile file names, and commands in the
// page that really reproduce it. The page in a browser:
// tests/report/test_report_browser.py.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "bad_input.hpp"
#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// The seed's stiff-spring model (K_f = 1e7), which compare passes
// (docs/stiff-spring.md), made by `frictionref stiff`.
fs::path stiff_candidate(const TempDir& dir, const std::string& lambda = "0.7") {
  const fs::path path = dir.path() / "stiff.csv";
  EXPECT_TRUE(succeeded(
      run_frictionref({"stiff", "--lambda", lambda, "--t-end", "30", "-o", path.string()})));
  return path;
}

// The exact curve with every velocity scaled by 1.2: off by up to 0.2 * 0.31
// B/(m w) > the default tolerance 0.02, so velocity_max fails.
fs::path scaled_candidate(const TempDir& dir) {
  const fs::path curve = dir.path() / "curve.csv";
  EXPECT_TRUE(succeeded(run_frictionref(
      {"curve", "--lambda", "0.7", "--t-end", "30", "--dt", "0.01", "-o", curve.string()})));
  std::string text = "t,v\n";
  const Csv exact = parse_csv(read_file(curve));
  for (const auto& row : exact.rows) {
    char line[96];
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", to_double(row.at(exact.column("t"))),
                  1.2 * to_double(row.at(exact.column("v"))));
    text += line;
  }
  const fs::path path = dir.path() / "scaled.csv";
  write_text(path, text);
  return path;
}

// The text of the cell after the check's name in the checks table: "PASS" or "FAIL".
std::string check_result(const std::string& page, const std::string& check) {
  const std::regex row("<td>" + check + "</td><td class=\"(PASS|FAIL)\">");
  std::smatch match;
  if (!std::regex_search(page, match, row)) return "missing";
  return match[1];
}

// The lines "<check>: PASS|FAIL ..." of compare's text report.
std::vector<std::pair<std::string, std::string>> compare_results(const std::string& out) {
  std::vector<std::pair<std::string, std::string>> results;
  const std::regex line("^([a-z_]+): (PASS|FAIL) ");
  for (const std::string& text : lines(out)) {
    std::smatch match;
    if (std::regex_search(text, match, line) && match[1] != "verdict")
      results.emplace_back(match[1], match[2]);
  }
  return results;
}

// Character references back to text (the five the page writes).
std::string unescape(std::string text) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}}) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  return text;
}

// POSIX shell words of one line: single quotes and backslash escapes (the
// page quotes a ' as '\'').
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false, quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '\'') {
        quoted = false;
      } else {
        word += c;
      }
    } else if (c == '\'') {
      quoted = in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else if (c == ' ') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

// The line of the page's reproduce block that starts with `start`.
std::string command_in_page(const std::string& page, const std::string& start) {
  const std::size_t pre = page.find("<pre id=\"commands\">");
  const std::size_t end = page.find("</pre>", pre);
  if (pre == std::string::npos || end == std::string::npos) return "";
  for (const std::string& line : lines(unescape(page.substr(pre, end - pre))))
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

// sha256sum's digest of a file: the value the page must give.
std::string sha256sum(const fs::path& path) {
  const std::string command = "sha256sum '" + path.string() + "'";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  char digest[65] = {};
  const std::size_t got = std::fread(digest, 1, 64, pipe);
  pclose(pipe);
  return std::string(digest, got);
}

// ---------------------------------------------------------------------------
// Verdicts and exit codes: as compare.

TEST(Report, StiffSpringPassesWithExitZeroAsCompare) {
  TempDir dir;
  const fs::path candidate = stiff_candidate(dir);
  const RunResult result = run_frictionref(
      {"report", "--candidate", candidate.string(), "--lambda", "0.7", "-o", "report.html"},
      dir.path());
  ASSERT_TRUE(succeeded(result));
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"report.html", "stiff.csv"}));
  const std::string page = read_file(dir.path() / "report.html");
  EXPECT_EQ(page.rfind("<!DOCTYPE html>\n", 0), 0u);
  EXPECT_TRUE(contains(page, "id=\"verdict\">PASS<"));

  const RunResult compared =
      run_frictionref({"compare", "--candidate", candidate.string(), "--lambda", "0.7"});
  ASSERT_EQ(compared.exit_code, 0);
  const auto results = compare_results(compared.out);
  ASSERT_EQ(results.size(), 7u) << compared.out;
  for (const auto& [check, verdict] : results)
    EXPECT_EQ(check_result(page, check), verdict) << check;
}

TEST(Report, ScaledVelocityFailsWithExitOneAndThePageWritten) {
  TempDir dir;
  const fs::path candidate = scaled_candidate(dir);
  const RunResult result = run_frictionref(
      {"report", "--candidate", candidate.string(), "--lambda", "0.7", "-o", "report.html"},
      dir.path());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  const std::string page = read_file(dir.path() / "report.html");
  EXPECT_TRUE(contains(page, "id=\"verdict\">FAIL<"));
  EXPECT_EQ(check_result(page, "velocity_max"), "FAIL");
  EXPECT_TRUE(contains(page, "failed checks: velocity_max"));

  const RunResult compared =
      run_frictionref({"compare", "--candidate", candidate.string(), "--lambda", "0.7"});
  EXPECT_EQ(compared.exit_code, 1);
  for (const auto& [check, verdict] : compare_results(compared.out))
    EXPECT_EQ(check_result(page, check), verdict) << check;
}

// The exact curve every 0.5: every check passes, but the samples resolve
// nothing near the events: INCONCLUSIVE, exit 3, the page written and
// saying what is unresolved, as compare says.
TEST(Report, CoarseExactCurveIsInconclusiveWithExitThreeAndThePageWritten) {
  TempDir dir;
  const fs::path curve = dir.path() / "curve.csv";
  ASSERT_TRUE(succeeded(run_frictionref(
      {"curve", "--lambda", "0.7", "--t-end", "30", "--dt", "0.5", "-o", curve.string()})));
  const RunResult result = run_frictionref(
      {"report", "--candidate", curve.string(), "--lambda", "0.7", "-o", "report.html"},
      dir.path());
  EXPECT_EQ(result.exit_code, 3) << result.err;
  const std::string page = read_file(dir.path() / "report.html");
  EXPECT_TRUE(contains(page, "id=\"verdict\">INCONCLUSIVE<")) << page;
  EXPECT_TRUE(contains(page, "<p id=\"resolution\">Resolution: ")) << page;
  EXPECT_TRUE(contains(page, "archive at most every 0.0314159 to resolve them.")) << page;
  const RunResult compared =
      run_frictionref({"compare", "--candidate", curve.string(), "--lambda", "0.7"});
  EXPECT_EQ(compared.exit_code, 3);
}

// compare's default tolerances (docs/cli.md, compare), in each check's unit.
const std::map<std::string, std::string> default_tolerance = {
    {"velocity_max", "0.02"}, {"velocity_rms", "0.01"}, {"displacement_max", "0.02"},
    {"stop_times", "0.01"},   {"missed_stops", "0"},    {"extra_stops", "0"},
    {"creep", "0.001"},       {"regime", "0"}};

// Every check has its value and tolerance; the figures and tables are there.
TEST(Report, PageHoldsChecksFiguresAndEventTable) {
  TempDir dir;
  const fs::path candidate = stiff_candidate(dir);
  ASSERT_TRUE(succeeded(run_frictionref({"report", "--candidate", candidate.string(), "--lambda",
                                         "0.7", "--displacement-column", "x", "-o", "report.html"},
                                        dir.path())));
  const std::string page = read_file(dir.path() / "report.html");
  for (const char* check : {"velocity_max", "velocity_rms", "displacement_max", "stop_times",
                            "missed_stops", "extra_stops", "creep", "regime"}) {
    // name, result, value, tolerance (the defaults of docs/cli.md), unit, message
    const std::regex row(std::string("<td>") + check +
                         "</td><td class=\"PASS\">PASS</td><td class=\"number\">[-+.0-9e]+</td>"
                         "<td class=\"number\">([-+.0-9e]+)</td>");
    std::smatch match;
    ASSERT_TRUE(std::regex_search(page, match, row)) << check;
    EXPECT_EQ(match[1], default_tolerance.at(check)) << check;
  }
  for (const char* id :
       {"<svg id=\"figure-velocity\"", "<svg id=\"figure-error\"", "<svg id=\"figure-zoom\"",
        "<table id=\"matched-sticks\"", "Zoom on the worst stop"})
    EXPECT_TRUE(contains(page, id)) << id;
  // lambda = 0.7 from rest: 2 sticks per period over 30 time units, 10 in all
  // (docs/validation.md, case 10.2), every one matched.
  EXPECT_TRUE(contains(page,
                       "The exact motion shows 10 sticks, the candidate 10; 10 are "
                       "matched, 0 missed, 0 extra."));
  EXPECT_FALSE(contains(page, "<script"));
  // Nothing from anywhere: the only address is the SVG namespace, once per figure.
  std::size_t addresses = 0;
  for (std::size_t at = page.find("://"); at != std::string::npos; at = page.find("://", at + 1))
    ++addresses;
  EXPECT_EQ(addresses, 3u);
  EXPECT_EQ(std::regex_search(page, std::regex("xmlns=\"http://www.w3.org/2000/svg\"")), true);
}

// ---------------------------------------------------------------------------
// Model and provenance.

TEST(Report, ModelAndProvenance) {
  TempDir dir;
  // A candidate in other units: m = 2, B = 3, w = 1.5, R = 2.1 (lambda 0.7).
  const fs::path candidate = dir.path() / "units.csv";
  ASSERT_TRUE(succeeded(run_frictionref({"stiff", "--mass", "2", "--amplitude", "3", "--omega",
                                         "1.5", "--friction", "2.1", "--x0", "0.25", "--v0", "-0.5",
                                         "--t-end", "20", "-o", candidate.string()})));
  const RunResult result = run_frictionref(
      {"report", "--candidate", "units.csv", "--mass", "2", "--amplitude", "3", "--omega", "1.5",
       "--friction", "2.1", "--x0", "0.25", "--v0", "-0.5", "-o", "report.html"},
      dir.path());
  ASSERT_LE(result.exit_code, 1) << result.err;
  const std::string page = read_file(dir.path() / "report.html");
  for (const char* row :
       {"<td>mass</td><td>m</td><td class=\"number\">2</td>",
        "<td>force amplitude</td><td>B</td><td class=\"number\">3</td>",
        "<td>angular frequency</td><td>w</td><td class=\"number\">1.5</td>",
        "<td>sliding friction</td><td>R</td><td class=\"number\">2.1</td>",
        "<td>friction ratio</td><td>lambda = R/B</td><td class=\"number\">0.7000000000000001</td>",
        "<td>static friction (not set: equal to R)</td><td>Rs</td><td class=\"number\">2.1</td>",
        "<td>spring stiffness</td><td>k</td><td class=\"number\">0</td>",
        "<td>viscous damping</td><td>c</td><td class=\"number\">0</td>",
        "<td>constant force</td><td>F0</td><td class=\"number\">0</td>",
        "<td>further harmonics</td><td>B_i, w_i, phi_i</td><td>none</td>",
        "<td>initial position</td><td>x0</td><td class=\"number\">0.25</td>",
        "<td>initial velocity</td><td>v0</td><td class=\"number\">-0.5</td>",
        "<td>initial time</td><td>t0</td><td class=\"number\">0</td>"})
    EXPECT_TRUE(contains(page, row)) << row;
  EXPECT_TRUE(contains(page, std::string("<td>program</td><td>frictionref ") +
                                 FRICTIONREF_EXPECTED_VERSION + "</td>"));
  EXPECT_TRUE(contains(page,
                       "<code id=\"command\">frictionref report --candidate units.csv --mass 2 "
                       "--amplitude 3 --omega 1.5 --friction 2.1 --x0 0.25 --v0 -0.5 -o "
                       "report.html</code>"));
  EXPECT_TRUE(
      std::regex_search(page, std::regex("<td>date</td><td>20[0-9][0-9]-[01][0-9]-[0-3][0-9] "
                                         "[0-2][0-9]:[0-5][0-9]:[0-6][0-9] UTC</td>")));
  EXPECT_TRUE(contains(page, "<td>file name</td><td>units.csv</td>"));
  EXPECT_TRUE(contains(
      page, "<td>size</td><td>" + std::to_string(fs::file_size(candidate)) + " bytes</td>"));
  EXPECT_EQ(sha256sum(candidate).size(), 64u);
  EXPECT_TRUE(contains(page, "<code id=\"sha256\">" + sha256sum(candidate) + "</code>"));
}

// A fixed file against a digest computed once, outside this code:
//   printf '# tiny candidate\nt,v\n0,0\n0.5,0.1\n1,0.3\n' | sha256sum
TEST(Report, Sha256OfAKnownFile) {
  TempDir dir;
  write_text(dir.path() / "tiny.csv", "# tiny candidate\nt,v\n0,0\n0.5,0.1\n1,0.3\n");
  const RunResult result = run_frictionref(
      {"report", "--candidate", "tiny.csv", "--lambda", "0.7", "-o", "report.html"}, dir.path());
  ASSERT_LE(result.exit_code, 1) << result.err;
  EXPECT_TRUE(contains(read_file(dir.path() / "report.html"),
                       "<code id=\"sha256\">bf8264d6a3e713ec5c30557f77af9468104165c3164fe186d8f3b3"
                       "9a5558b2c4</code>"));
}

// ---------------------------------------------------------------------------
// Hostile file names: text, never markup.

TEST(Report, HostileFileNameIsEscaped) {
  TempDir dir;
  const fs::path stiff = stiff_candidate(dir);
  // Markup, quotes, an ampersand, a control character and a byte that is not UTF-8.
  const std::string name = "r&d <script>alert(\"x\")<!-- 'q' \x01\xff.csv";
  fs::copy_file(stiff, dir.path() / name);
  const RunResult result = run_frictionref(
      {"report", "--candidate", name, "--lambda", "0.7", "-o", "report.html"}, dir.path());
  ASSERT_TRUE(succeeded(result));
  const std::string page = read_file(dir.path() / "report.html");
  EXPECT_FALSE(contains(page, "<script"));
  EXPECT_FALSE(contains(page, "<!--"));
  EXPECT_FALSE(contains(page, "\x01"));
  EXPECT_FALSE(contains(page, "\xff"));
  const std::string escaped =
      "r&amp;d &lt;script&gt;alert(&quot;x&quot;)&lt;!-- &#39;q&#39; \xEF\xBF\xBD\xEF\xBF\xBD.csv";
  EXPECT_TRUE(contains(page, "<td>file name</td><td>" + escaped + "</td>"));
  EXPECT_TRUE(contains(page, "<title>frictionref validation report: " + escaped));
  // The SHA-256 is of the file itself, whatever its name.
  EXPECT_TRUE(contains(page, "<code id=\"sha256\">" + sha256sum(stiff) + "</code>"));
}

// ---------------------------------------------------------------------------
// The page's commands reproduce it.

TEST(Report, CommandsInThePageReproduceTheVerdictAndTheReference) {
  TempDir dir;
  const fs::path candidate = scaled_candidate(dir);
  ASSERT_EQ(run_frictionref({"report", "--candidate", "scaled.csv", "--lambda", "0.7",
                             "--velocity-tolerance", "2e-2", "-o", "report.html"},
                            dir.path())
                .exit_code,
            1);
  const std::string page = read_file(dir.path() / "report.html");

  const std::string compare = command_in_page(page, "frictionref compare ");
  ASSERT_FALSE(compare.empty()) << page;
  std::vector<std::string> args = shell_words(compare);
  args.erase(args.begin());  // "frictionref"
  const RunResult compared = run_frictionref(args, dir.path());
  EXPECT_EQ(compared.exit_code, 1) << compare << "\n" << compared.err;
  const auto results = compare_results(compared.out);
  EXPECT_EQ(results.size(), 7u);
  for (const auto& [check, verdict] : results)
    EXPECT_EQ(check_result(page, check), verdict) << check;

  for (const char* start : {"frictionref curve ", "frictionref events "}) {
    const std::string line = command_in_page(page, start);
    ASSERT_FALSE(line.empty()) << start;
    args = shell_words(line);
    args.erase(args.begin());
    EXPECT_TRUE(succeeded(run_frictionref(args, dir.path()))) << line;
  }
  // The exact curve's last row is at the candidate's last time, 30.
  const Csv exact = parse_csv(read_file(dir.path() / "exact-curve.csv"));
  ASSERT_FALSE(exact.rows.empty());
  EXPECT_EQ(to_double(exact.rows.back().at(0)), 30.0);
  EXPECT_TRUE(fs::exists(dir.path() / "exact-events.csv"));
  EXPECT_EQ(command_in_page(page, "sha256sum "), "sha256sum scaled.csv");
}

// ---------------------------------------------------------------------------
// Help and bad input.

TEST(Report, HelpTeaches) {
  const RunResult result = run_frictionref({"report", "--help"});
  ASSERT_TRUE(succeeded(result));
  for (const char* part : {"frictionref report ", "--candidate", "--mass", "--lambda",
                           "--velocity-tolerance", "--displacement-column", "-o", "SHA-256",
                           "zoom on the worst stop", "Exit codes", "1 FAIL", "Example"})
    EXPECT_TRUE(contains(result.out, part)) << part;
  EXPECT_TRUE(contains(run_frictionref({"--help"}).out, "report"));
}

class ReportBadInput : public ::testing::TestWithParam<BadInput> {};

// Candidate files live outside the directory the command runs in, so that
// "no file left behind" means exactly that.
const TempDir& candidates() {
  static const TempDir dir;
  static const bool written = [] {
    write_text(dir.path() / "good.csv", "t,v\n0,0\n0.5,0.1\n1,0.3\n");
    write_text(dir.path() / "empty.csv", "");
    write_text(dir.path() / "bad-row.csv", "t,v\n0,0\n0.5,abc\n");
    write_text(dir.path() / "backwards.csv", "t,v\n0,0\n0.5,0.1\n0.2,0\n");
    return true;
  }();
  (void)written;
  return dir;
}

std::string candidate(const std::string& name) { return (candidates().path() / name).string(); }

std::vector<BadInput> bad_inputs() {
  const auto report = [](std::vector<std::string> args) { return writing("report", args); };
  return {
      {report({"--lambda", "0.7"}), "--candidate", "required"},
      {report({"--candidate", candidate("missing.csv"), "--lambda", "0.7"}), "--candidate",
       "cannot be opened: No such file or directory"},
      {report({"--candidate", candidates().path().string(), "--lambda", "0.7"}), "--candidate",
       "is a directory"},
      {report({"--candidate", candidate("empty.csv"), "--lambda", "0.7"}), "empty.csv", ""},
      {report({"--candidate", candidate("bad-row.csv"), "--lambda", "0.7"}), "bad-row.csv:3",
       "abc"},
      {report({"--candidate", candidate("backwards.csv"), "--lambda", "0.7"}), "backwards.csv:4",
       "must not decrease"},
      {report({"--candidate", candidate("good.csv")}), "--friction", "required"},
      {report(
           {"--candidate", candidate("good.csv"), "--lambda", "0.7", "--velocity-tolerance", "-1"}),
       "--velocity-tolerance = -1", ">= 0"},
      {report(
           {"--candidate", candidate("good.csv"), "--lambda", "0.7", "--max-missed-stops", "1.5"}),
       "--max-missed-stops = 1.5", "whole number"},
      {report({"--candidate", candidate("good.csv"), "--friction", "0.7", "--amplitude", "0"}),
       "--amplitude = 0", "must be > 0"},
      {report({"--candidate", candidate("good.csv"), "--lambda", "0.7", "--t0", "0.25"}),
       "--candidate", "before --t0 = 0.25"},
      {report(
           {"--candidate", candidate("good.csv"), "--lambda", "0.7", "--velocity-column", "speed"}),
       "--velocity-column = speed", "no such column"},
      {report({"--candidate", candidate("good.csv"), "--lambda", "0.7", "--json"}), "--json", ""},
      {report({"--candidate", candidate("good.csv"), "--lambda", "0.7", "--mass", "-1"}),
       "--mass = -1", "must be > 0"},
  };
}

TEST_P(ReportBadInput, ExitTwoOneLineNoFile) { expect_rejected(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Report, ReportBadInput, ::testing::ValuesIn(bad_inputs()), bad_input_name);

// A bad file leaves an existing report as it was.
TEST(Report, BadFileKeepsAnExistingReport) {
  TempDir dir;
  write_text(dir.path() / "report.html", "previous");
  write_text(dir.path() / "bad.csv", "t,v\n0,0\n0.5,abc\n");
  const RunResult result = run_frictionref(
      {"report", "--candidate", "bad.csv", "--lambda", "0.7", "-o", "report.html"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(read_file(dir.path() / "report.html"), "previous");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"bad.csv", "report.html"}));
}

}  // namespace
}  // namespace frictionref::cli_test
