// `frictionref compare` through the real binary: exit 0 on PASS, 1 on FAIL,
// 2 on a bad file or option (one line on stderr, no output); the report's
// check lines, the JSON keys, and the --plot figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The exact curve of the dead-band seed case, written by the binary itself
// (metadata comments, a header, and a text column `phase`).
fs::path exact_curve(const TempDir& dir, const std::string& lambda = "0.7",
                     const std::string& dt = "0.01") {
  const fs::path path = dir.path() / "curve.csv";
  const RunResult made = run_frictionref(
      {"curve", "--lambda", lambda, "--t-end", "30", "--dt", dt, "-o", path.string()});
  EXPECT_TRUE(succeeded(made));
  return path;
}

// An independent stiff-spring code (friction spring K_f = 1e7 in series with a
// Coulomb slider, central differences, dt = 1e-5), archived every 0.01 as
// white-space columns "t x v" in scientific notation, under a '#' header.
std::string stiff_spring_file(double lambda, double v0) {
  const double k_f = 1e7, dt = 1e-5, friction = lambda;  // m = B = w = 1
  const std::int64_t every = 1000, steps = 3000000;      // 30 time units
  double x = 0, z = 0, f = 0;
  double v_half = v0 - 0.5 * dt * std::sin(0.0);
  std::string text = "# stiff-spring candidate, K_f = 1e7, dt = 1e-5\n#   t   x   v\n";
  char line[128];
  for (std::int64_t n = 0; n <= steps; ++n) {
    const double t = static_cast<double>(n) * dt;
    const double trial = -k_f * (x - z);
    if (std::fabs(trial) > friction) {
      f = std::copysign(friction, trial);
      z = x + f / k_f;
    } else {
      f = trial;
    }
    const double v_next = v_half + dt * (std::sin(t) + f);
    if (n % every == 0) {
      std::snprintf(line, sizeof line, "%.9e %.9e %.9e\n", static_cast<double>(n / every) * 0.01, x,
                    0.5 * (v_half + v_next));
      text += line;
    }
    x += dt * v_next;
    v_half = v_next;
  }
  return text;
}

// ---------------------------------------------------------------------------
// Verdicts and exit codes.

TEST(Compare, ExactCurvePassesWithExitZero) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const RunResult result =
      run_frictionref({"compare", "--candidate", curve.string(), "--lambda", "0.7"});
  ASSERT_TRUE(succeeded(result)) << result.out;
  const std::vector<std::string> out = lines(result.out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), "verdict: PASS");
  for (const char* check : {"velocity_max", "velocity_rms", "stop_times", "missed_stops",
                            "extra_stops", "creep", "regime"}) {
    bool found = false;
    for (const std::string& line : out)
      found = found || line.rfind(std::string(check) + ": PASS ", 0) == 0;
    EXPECT_TRUE(found) << check << "\n" << result.out;
  }
  EXPECT_FALSE(contains(result.out, "displacement_max:"));  // no displacement column given
  // The defaults are stated in the report.
  EXPECT_TRUE(contains(result.out,
                       "stick detection: |v| < 0.001 B/(m w) = 0.001 for at least "
                       "0.01 periods"));
  EXPECT_TRUE(contains(result.out, "tolerances: velocity_max 0.02 B/(m w)"));
  EXPECT_TRUE(contains(result.out, "time: column 1 (t), velocity: column 3 (v)"));
}

TEST(Compare, CoarseExactCurveWithDisplacementPasses) {
  TempDir dir;
  // 0.05 apart: below the default stop-time tolerance 0.01 periods = 0.0628.
  const fs::path curve = exact_curve(dir, "0.3", "0.05");
  const RunResult result = run_frictionref(
      {"compare", "--candidate", curve.string(), "--lambda", "0.3", "--displacement-column", "x"});
  ASSERT_TRUE(succeeded(result)) << result.out;
  EXPECT_TRUE(contains(result.out, "\ndisplacement_max: PASS ")) << result.out;
  EXPECT_TRUE(contains(result.out, "\nverdict: PASS\n"));
}

// 0.1 apart: the exact curve itself passes every check, but events fall
// between samples further apart than the stop-time tolerance: the samples
// could hide a defect there, so the verdict is INCONCLUSIVE (exit 3), and the
// report says what is unresolved and the archive step that resolves it.
TEST(Compare, ExactCurveSampledTooCoarselyIsInconclusive) {
  TempDir dir;
  const fs::path curve = exact_curve(dir, "0.3", "0.1");
  const RunResult result = run_frictionref(
      {"compare", "--candidate", curve.string(), "--lambda", "0.3", "--displacement-column", "x"});
  EXPECT_EQ(result.exit_code, 3) << result.out << result.err;
  EXPECT_FALSE(contains(result.out, ": FAIL ")) << result.out;
  EXPECT_TRUE(contains(result.out, "\nresolution: ")) << result.out;
  EXPECT_TRUE(contains(result.out,
                       "exact events lie between samples further apart than that "
                       "tolerance 0.0628319: start of slip+ at t = 0.304693 (samples 0.1 "
                       "apart), start of slip- at t = 4.42603"))
      << result.out;
  EXPECT_TRUE(contains(result.out,
                       "\nverdict: INCONCLUSIVE (the samples do not resolve the exact motion: "
                       "archive at most every 0.0314159 to resolve them)\n"))
      << result.out;
  const RunResult json =
      run_frictionref({"compare", "--candidate", curve.string(), "--lambda", "0.3", "--json"});
  EXPECT_EQ(json.exit_code, 3);
  EXPECT_TRUE(contains(json.out, R"("verdict": "INCONCLUSIVE")")) << json.out;
  EXPECT_TRUE(contains(json.out, R"("resolved": false)")) << json.out;
}

TEST(Compare, StiffSpringSeedCasesPass) {
  TempDir dir;
  const struct {
    const char* lambda;
    const char* v0;
    double v0_value;
  } cases[] = {{"0.3", "0", 0}, {"0.7", "0", 0}, {"1.01", "-1", -1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.lambda);
    const fs::path file = dir.path() / "stiff.txt";
    write_text(file, stiff_spring_file(std::atof(c.lambda), c.v0_value));
    // No header: column 1 is time, column 3 velocity, column 2 displacement.
    const RunResult result =
        run_frictionref({"compare", "--candidate", file.string(), "--lambda", c.lambda, "--v0",
                         c.v0, "--velocity-column", "3", "--displacement-column", "2"});
    EXPECT_TRUE(succeeded(result)) << result.out << result.err;
    EXPECT_TRUE(contains(result.out, "\nverdict: PASS\n")) << result.out;
  }
}

// The exact curve rewritten in the shapes real codes write (issue 13): a
// title line without '#', a header with unit suffixes, ';' between columns
// and decimal commas; and a restart that writes the overlap again.
std::string exact_rows(const fs::path& curve, const char* separator, bool decimal_comma,
                       double from = 0, double to = 1e300) {
  std::string text;
  const Csv exact = parse_csv(read_file(curve));
  for (const auto& row : exact.rows) {
    const double t = to_double(row.at(exact.column("t")));
    if (t < from || t > to) continue;
    std::string line = row.at(exact.column("t")) + separator + row.at(exact.column("x")) +
                       separator + row.at(exact.column("v"));
    if (decimal_comma)
      for (char& c : line)
        if (c == '.') c = ',';
    text += line + "\n";
  }
  return text;
}

TEST(Compare, SpreadsheetExportWithTitleUnitsAndDecimalCommasPasses) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const fs::path file = dir.path() / "run42.csv";
  write_text(file, "FRICTION MODEL RUN 42\ntime_s;x_m;v_mps\n" + exact_rows(curve, ";", true));
  const RunResult result = run_frictionref(
      {"compare", "--candidate", file.string(), "--lambda", "0.7", "--displacement-column", "x"});
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_TRUE(contains(result.out,
                       "time: column 1 (time_s), velocity: column 3 (v_mps), "
                       "displacement: column 2 (x_m)"))
      << result.out;
  EXPECT_TRUE(contains(result.out,
                       "\nnote: skipped 1 title line before the table (line 1: "
                       "'FRICTION MODEL RUN 42')\n"))
      << result.out;
  EXPECT_TRUE(contains(result.out, "\nverdict: PASS\n"));
  // Blanks with decimal commas need --decimal-comma.
  const fs::path blanks = dir.path() / "blanks.txt";
  write_text(blanks, exact_rows(curve, " ", true));
  EXPECT_EQ(run_frictionref({"compare", "--candidate", blanks.string(), "--lambda", "0.7",
                             "--velocity-column", "3", "--decimal-comma"})
                .exit_code,
            0);
  // --skip-rows N skips lines the reader cannot tell from rows.
  const fs::path numbered = dir.path() / "numbered.csv";
  write_text(numbered, "RUN 42 OF 50\nt,x,v\n" + exact_rows(curve, ",", false));
  EXPECT_EQ(run_frictionref({"compare", "--candidate", numbered.string(), "--lambda", "0.7",
                             "--skip-rows", "1"})
                .exit_code,
            0);
}

TEST(Compare, RestartIsAnErrorNamingKeepLastWhichKeepsTheLaterSegment) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const fs::path file = dir.path() / "restarted.csv";
  // Written up to t = 20, restarted from a checkpoint at t = 15.
  write_text(file,
             "t,x,v\n" + exact_rows(curve, ",", false, 0, 20) + exact_rows(curve, ",", false, 15));
  const RunResult refused =
      run_frictionref({"compare", "--candidate", file.string(), "--lambda", "0.7"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(refused.out.empty());
  EXPECT_TRUE(contains(refused.err, "must not decrease")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "--on-overlap keep-last")) << refused.err;
  const RunResult kept = run_frictionref(
      {"compare", "--candidate", file.string(), "--lambda", "0.7", "--on-overlap", "keep-last"});
  EXPECT_EQ(kept.exit_code, 0) << kept.out << kept.err;
  EXPECT_TRUE(contains(kept.out,
                       "): kept the later segment, dropped the 501 earlier rows at or "
                       "after 15\n"))
      << kept.out;
  EXPECT_TRUE(contains(kept.out, "\nverdict: PASS\n"));
  const RunResult bad = run_frictionref(
      {"compare", "--candidate", file.string(), "--lambda", "0.7", "--on-overlap", "first"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "frictionref: error: --on-overlap = first: must be error or keep-last\n");
}

TEST(Compare, WrongModelFailsWithExitOneAndNamesTheChecks) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const RunResult result =
      run_frictionref({"compare", "--candidate", curve.string(), "--lambda", "0.75"});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  const std::vector<std::string> out = lines(result.out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back().rfind("verdict: FAIL (checks velocity_max", 0), 0u) << out.back();
  EXPECT_TRUE(contains(result.out, "\nvelocity_max: FAIL max |v - v_exact| = ")) << result.out;
  EXPECT_TRUE(contains(result.out, " at t = ")) << result.out;
}

TEST(Compare, ScaledVelocityFails) {
  TempDir dir;
  // The exact dead-band motion with every velocity 10 % too large.
  const Csv exact = parse_csv(read_file(exact_curve(dir)));
  std::string text = "time,velocity\n";
  for (const auto& row : exact.rows)
    text += row[0] + "," + std::to_string(to_double(row[2]) * 1.1) + "\n";
  write_text(dir.path() / "scaled.csv", text);
  const RunResult result =
      run_frictionref({"compare", "--candidate", "scaled.csv", "--lambda", "0.7"}, dir.path());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.out, "\nvelocity_max: FAIL ")) << result.out;
  EXPECT_TRUE(contains(result.out, "\nstop_times: PASS ")) << result.out;
  EXPECT_TRUE(contains(result.out, "\nregime: PASS ")) << result.out;
}

TEST(Compare, LooserToleranceOptionsTurnFailIntoPass) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const std::vector<std::string> base{"compare", "--candidate", curve.string(), "--lambda", "0.71"};
  EXPECT_EQ(run_frictionref(base).exit_code, 1);
  const RunResult loose = run_frictionref(
      with(base, {"--velocity-tolerance", "0.05", "--velocity-rms-tolerance", "0.05"}));
  EXPECT_TRUE(succeeded(loose)) << loose.out;
  EXPECT_TRUE(contains(loose.out, "tolerances: velocity_max 0.05 B/(m w)")) << loose.out;
}

TEST(Compare, ReportToFile) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const RunResult result = run_frictionref(
      {"compare", "--candidate", "curve.csv", "--lambda", "0.7", "-o", "report.txt"}, dir.path());
  ASSERT_TRUE(succeeded(result));
  EXPECT_TRUE(result.out.empty());
  EXPECT_TRUE(contains(read_file(dir.path() / "report.txt"), "\nverdict: PASS\n"));
}

// ---------------------------------------------------------------------------
// JSON.

TEST(Compare, JsonKeys) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const RunResult result = run_frictionref({"compare", "--candidate", curve.string(), "--lambda",
                                            "0.7", "--json", "--displacement-column", "x"});
  ASSERT_TRUE(succeeded(result));
  const nlohmann::json json = nlohmann::json::parse(result.out);
  for (const char* key : {"verdict", "failed_checks", "checks", "candidate", "model", "options",
                          "scales", "velocity_error", "displacement_error", "sticks", "creep",
                          "regime", "notes", "version", "command"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  EXPECT_EQ(json.at("verdict"), "PASS");
  EXPECT_TRUE(json.at("failed_checks").empty());
  std::vector<std::string> names;
  for (const auto& check : json.at("checks")) {
    for (const char* key : {"name", "passed", "value", "tolerance", "message"})
      EXPECT_TRUE(check.contains(key)) << key;
    names.push_back(check.at("name"));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"velocity_max", "velocity_rms", "displacement_max",
                                             "stop_times", "missed_stops", "extra_stops", "creep",
                                             "regime"}));
  const auto& options = json.at("options");
  EXPECT_EQ(options.at("stick_threshold").get<double>(), 1e-3);
  EXPECT_EQ(options.at("min_stick_duration").get<double>(), 0.01);
  EXPECT_EQ(options.at("velocity_max_tolerance").get<double>(), 0.02);
  EXPECT_EQ(options.at("stop_time_tolerance").get<double>(), 0.01);
  EXPECT_EQ(options.at("max_missed_stops").get<int>(), 0);
  for (const char* key : {"max", "max_relative", "max_time", "rms", "rms_relative"})
    EXPECT_TRUE(json.at("velocity_error").contains(key)) << key;
  for (const char* key : {"exact_phases", "exact", "candidate", "matched", "missed", "extra"})
    EXPECT_TRUE(json.at("sticks").contains(key)) << key;
  ASSERT_EQ(json.at("sticks").at("matched").size(), 10u);
  const auto& first = json.at("sticks").at("matched").at(1);
  for (const char* key :
       {"number", "exact", "candidate", "start_error", "end_error", "exact_phase"})
    EXPECT_TRUE(first.contains(key)) << key;
  EXPECT_NEAR(first.at("exact_phase").at("start").get<double>(), 3.2198057244983143, 1e-12);
  EXPECT_EQ(json.at("regime").at("candidate"), "dead-bands");
  EXPECT_EQ(json.at("regime").at("steady_state"), "dead-bands");
  EXPECT_EQ(json.at("model").at("friction").get<double>(), 0.7);
}

TEST(Compare, JsonOnFail) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const RunResult result =
      run_frictionref({"compare", "--candidate", curve.string(), "--lambda", "0.75", "--json"});
  EXPECT_EQ(result.exit_code, 1);
  const nlohmann::json json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("verdict"), "FAIL");
  ASSERT_FALSE(json.at("failed_checks").empty());
  EXPECT_EQ(json.at("failed_checks").at(0), "velocity_max");
  EXPECT_TRUE(json.at("displacement_error").is_null());
}

// ---------------------------------------------------------------------------
// Figures.

TEST(Compare, PlotSvgAndPng) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  for (const char* name : {"compare.svg", "compare.png"}) {
    SCOPED_TRACE(name);
    const RunResult result = run_frictionref(
        {"compare", "--candidate", "curve.csv", "--lambda", "0.7", "--plot", name}, dir.path());
    ASSERT_TRUE(succeeded(result)) << result.err;
    EXPECT_TRUE(contains(result.out, "verdict: PASS"));
    const std::string figure = read_file(dir.path() / name);
    ASSERT_GT(figure.size(), 1000u);
    if (std::string(name).find(".svg") != std::string::npos) {
      EXPECT_TRUE(figure.rfind("<?xml", 0) == 0 || figure.rfind("<svg", 0) == 0);
      EXPECT_TRUE(contains(figure, "</svg>"));
      EXPECT_TRUE(contains(figure, "v - v_exact [length/time]"));
      EXPECT_TRUE(contains(figure, "t [time]"));
    } else {
      EXPECT_EQ(figure.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    }
  }
  // Nothing else was left behind (no temporary files).
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"compare.png", "compare.svg", "curve.csv"}));
}

// ---------------------------------------------------------------------------
// Bad input: exit 2, one line on stderr, nothing on stdout, no files.

struct BadFile {
  const char* name;
  std::string content;  // written to "run.csv"; "<none>" for a missing file
  std::vector<std::string> extra;
  std::vector<std::string> message_parts;
};

std::ostream& operator<<(std::ostream& out, const BadFile& bad) { return out << bad.name; }

class CompareBadFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(CompareBadFile, ExitTwoWithOneClearLineAndNoOutput) {
  const BadFile& bad = GetParam();
  TempDir dir;
  if (bad.content != "<none>") write_text(dir.path() / "run.csv", bad.content);
  const RunResult result = run_frictionref(with({"compare", "--candidate", "run.csv", "--lambda",
                                                 "0.7", "-o", "report.txt", "--plot", "figure.svg"},
                                                bad.extra),
                                           dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(result.out.empty()) << result.out;
  const std::vector<std::string> err = lines(result.err);
  ASSERT_EQ(err.size(), 1u) << result.err;
  EXPECT_EQ(err[0].rfind("frictionref: error: ", 0), 0u) << err[0];
  for (const std::string& part : bad.message_parts)
    EXPECT_TRUE(contains(err[0], part)) << "'" << part << "' not in: " << err[0];
  // No report, no figure, no temporary file.
  const std::vector<std::string> expected =
      bad.content == "<none>" ? std::vector<std::string>{} : std::vector<std::string>{"run.csv"};
  EXPECT_EQ(dir.entries(), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Files, CompareBadFile,
    ::testing::Values(
        BadFile{"NoNumbers",
                "time,velocity\nstart,stop\nend,end\n",
                {},
                {"--candidate = run.csv", "contains no numbers"}},
        BadFile{"OneColumn", "# t only\n0\n0.1\n0.2\n", {}, {"run.csv:2", "has 1 column"}},
        BadFile{"NonMonotoneTime",
                "t,v\n0,0\n0.2,0\n0.1,0\n",
                {},
                {"run.csv:4 column 1 (t) = 0.1", "must be >= the time on line 3 (0.2)"}},
        BadFile{"NaN",
                "t v\n0 0\n0.1 nan\n",
                {},
                {"run.csv:3 column 2 (v) = nan", "must be a finite number"}},
        BadFile{"Ragged", "0,0,0\n1,1\n", {}, {"run.csv:2", "has 2 columns, but line 1 has 3"}},
        BadFile{"NotANumber",
                "t,v\n0,0\n1,fast\n",
                {},
                {"run.csv:3 column 2 (v) = fast: must be a number"}},
        BadFile{"UnknownColumnName",
                "t,x,v\n0,0,0\n1,1,1\n",
                {"--velocity-column", "speed"},
                {"--velocity-column = speed", "no such column", "t, x, v"}},
        BadFile{"ColumnOutOfRange",
                "0 0\n1 1\n",
                {"--velocity-column", "9"},
                {"--velocity-column = 9", "from 1 to 2"}},
        BadFile{"NoDefaultTimeColumn",
                "a,b\n0,0\n1,1\n",
                {},
                {"--time-column = (default: t or time)", "no such column"}},
        BadFile{"Empty", "", {}, {"--candidate = run.csv: is empty"}},
        BadFile{"OnlyHeader", "t,v\n", {}, {"--candidate = run.csv", "no data rows"}},
        BadFile{"Missing", "<none>", {}, {"--candidate = run.csv", "No such file or directory"}},
        BadFile{"StartsBeforeT0",
                "t,v\n0,0\n1,0\n",
                {"--t0", "0.5"},
                {"--candidate = run.csv", "before --t0 = 0.5"}}),
    [](const ::testing::TestParamInfo<BadFile>& param) { return std::string(param.param.name); });

TEST(Compare, BadOptions) {
  TempDir dir;
  const fs::path curve = exact_curve(dir);
  const std::vector<std::string> base{"compare", "--candidate", curve.string(), "--lambda", "0.7"};
  const struct {
    std::vector<std::string> extra;
    std::string message;
  } cases[] = {
      {{"--velocity-tolerance", "-1"}, "--velocity-tolerance = -1: must be >= 0"},
      {{"--stick-threshold", "0"}, "--stick-threshold = 0: must be > 0"},
      {{"--stop-time-tolerance", "nan"}, "--stop-time-tolerance = nan: must be a finite number"},
      {{"--regime-window", "abc"}, "--regime-window = abc: must be a number"},
      {{"--max-missed-stops", "-1"}, "--max-missed-stops = -1: must be a whole number >= 0"},
      {{"--max-extra-stops", "1.5"}, "--max-extra-stops = 1.5: must be a whole number >= 0"},
      {{"--time-column", "0"}, "--time-column = 0: column numbers start at 1"},
      {{"--plot", "figure.pdf"}, "--plot = figure.pdf: must end in .svg or .png"},
      {{"--amplitude", "0", "--friction", "0.5"}, "--amplitude = 0: must be > 0 to compare"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.message);
    std::vector<std::string> args = base;
    if (c.extra.front() == "--amplitude") args = {"compare", "--candidate", curve.string()};
    const RunResult result = run_frictionref(with(args, c.extra));
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_TRUE(result.out.empty());
    EXPECT_EQ(result.err.rfind("frictionref: error: " + c.message, 0), 0u) << result.err;
    EXPECT_EQ(lines(result.err).size(), 1u) << result.err;
  }
  // --candidate is required.
  const RunResult missing = run_frictionref({"compare", "--lambda", "0.7"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_TRUE(contains(missing.err, "--candidate")) << missing.err;
}

// ---------------------------------------------------------------------------
// Help states the defaults.

TEST(Compare, HelpStatesDefaultsAndExitCodes) {
  const RunResult result = run_frictionref({"compare", "--help"});
  ASSERT_TRUE(succeeded(result));
  for (const char* part : {"frictionref compare ",
                           "--candidate",
                           "--time-column",
                           "--velocity-column",
                           "--displacement-column",
                           "--stick-threshold",
                           "--min-stick-duration",
                           "--velocity-tolerance",
                           "--velocity-rms-tolerance",
                           "--stop-time-tolerance",
                           "--max-missed-stops",
                           "--max-extra-stops",
                           "--displacement-tolerance",
                           "--regime-window",
                           "--json",
                           "--plot",
                           "--lambda",
                           "Exit codes",
                           "0 PASS, 1 FAIL, 3 INCONCLUSIVE, 2 bad input",
                           "4 internal error",
                           "resolve the exact motion",
                           "Example"}) {
    EXPECT_TRUE(contains(result.out, part)) << part;
  }
  // Defaults, as CLI11 prints them.
  for (const char* value :
       {"--stick-threshold S=0.001", "--min-stick-duration D=0.01", "--velocity-tolerance E=0.02",
        "--velocity-rms-tolerance E=0.01", "--stop-time-tolerance E=0.01", "--max-missed-stops N=0",
        "--max-extra-stops N=0", "--displacement-tolerance E=0.02", "--regime-window P=2"})
    EXPECT_TRUE(contains(result.out, value)) << value << "\n" << result.out;
}

}  // namespace
}  // namespace frictionref::cli_test
