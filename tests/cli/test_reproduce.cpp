// `frictionref reproduce`: the three seed cases on disk and the summary.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "csv_reader.hpp"
#include "reference_motion.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

struct Expected {
  const char* id;
  const char* folder;
  double lambda;  // the double the binary uses, as the reference's input
  double v0;
  const char* regime;
};

const Expected seed_cases[] = {
    {"10.1", "case-10.1-lambda-0.3", 0.3, 0, "continuous"},
    {"10.2", "case-10.2-lambda-0.7", 0.7, 0, "dead-bands"},
    {"10.3", "case-10.3-lambda-1.01", 1.01, -1, "stops"},
};

// No "<name>.tmp.XXXXXX" may survive anywhere below `root`.
void expect_no_temporary_files(const fs::path& root) {
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
  }
}

// The summary's title line and its "case ..." lines (figure lines dropped).
std::vector<std::string> case_lines(const std::string& out) {
  std::vector<std::string> kept;
  for (const std::string& line : lines(out))
    if (line.rfind("  figure: ", 0) != 0) kept.push_back(line);
  return kept;
}

// The "  figure: <path>" lines of the summary.
std::vector<std::string> figure_lines(const std::string& out) {
  std::vector<std::string> figures;
  for (const std::string& line : lines(out))
    if (line.rfind("  figure: ", 0) == 0) figures.push_back(line.substr(10));
  return figures;
}

bool is_svg(const std::string& content) {
  return content.find("<svg") != std::string::npos && content.find("</svg>") != std::string::npos;
}
bool is_png(const std::string& content) {
  return content.size() > 100 && content.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

void check_results(const fs::path& dir, const RunResult& result, bool figures = true) {
  ASSERT_TRUE(succeeded(result));
  const std::vector<std::string> out = case_lines(result.out);
  ASSERT_EQ(out.size(), 4u) << result.out;  // a title line, then one line per case
  // velocity.{svg,png} per case, and residual-velocity.{svg,png} for 10.3.
  EXPECT_EQ(figure_lines(result.out).size(), figures ? 8u : 0u) << result.out;
  for (std::size_t k = 0; k < 3; ++k) {
    const Expected& seed = seed_cases[k];
    SCOPED_TRACE(seed.id);
    const fs::path folder = dir / seed.folder;
    ASSERT_TRUE(fs::is_regular_file(folder / "events.csv"));
    ASSERT_TRUE(fs::is_regular_file(folder / "curve.csv"));
    ASSERT_TRUE(fs::is_regular_file(folder / "classify.json"));
    ASSERT_TRUE(fs::is_regular_file(folder / "stiff.csv"));
    ASSERT_TRUE(fs::is_regular_file(folder / "compare.txt"));
    const ReferenceMotion reference(seed.lambda, seed.v0, 30);

    // The seed's stiff-spring run (K_f = 1e7): archived every 0.01 to T,
    // and judged PASS against the exact solution, as the seed concludes.
    const Csv stiff = parse_csv(read_file(folder / "stiff.csv"));
    EXPECT_EQ(stiff.header, "t,x,v");
    EXPECT_EQ(stiff.rows.size(), 3001u);
    EXPECT_NE(stiff.meta("stiff").find("kf=10000000"), std::string::npos);
    const std::string report = read_file(folder / "compare.txt");
    EXPECT_NE(report.find("verdict: PASS"), std::string::npos) << report;

    const bool zoom = std::string(seed.id) == "10.3";
    for (const char* name : {"velocity.svg", "velocity.png", "residual-velocity.svg",
                             "residual-velocity.png"}) {
      const bool expected = figures && (zoom || std::string(name).rfind("velocity", 0) == 0);
      EXPECT_EQ(fs::exists(folder / name), expected) << name;
      if (!expected) continue;
      const std::string content = read_file(folder / name);
      EXPECT_TRUE(std::string(name).find(".svg") != std::string::npos ? is_svg(content)
                                                                       : is_png(content))
          << name;
    }
    if (figures) {
      const std::string svg = read_file(folder / "velocity.svg");
      EXPECT_NE(svg.find(std::string("Figure ") + seed.id), std::string::npos);
      EXPECT_NE(svg.find("exact (frictionref)"), std::string::npos);
      EXPECT_NE(svg.find("v [length/time]"), std::string::npos);
    }

    const Csv events = parse_csv(read_file(folder / "events.csv"));
    EXPECT_EQ(events.header, "phase,t_begin,t_end,x_begin,x_end,v_begin,v_end");
    ASSERT_EQ(events.rows.size(), reference.phases().size());
    for (std::size_t i = 0; i < events.rows.size(); ++i) {
      EXPECT_EQ(events.rows[i][0], reference.phases()[i].kind);
      EXPECT_NEAR(to_double(events.rows[i][2]), static_cast<double>(reference.phases()[i].t_end),
                  1e-11);
    }
    EXPECT_EQ(to_double(events.rows.back()[2]), 30.0);
    EXPECT_NE(events.meta("case").find(seed.id), std::string::npos);

    const Csv curve = parse_csv(read_file(folder / "curve.csv"));
    EXPECT_EQ(curve.header, "t,x,v,a,phase");
    EXPECT_EQ(curve.rows.size(), 3001u + reference.phases().size() - 1);  // grid + event rows
    EXPECT_NE(curve.meta("grid").find("dt=0.01 include_events=true"), std::string::npos);

    const nlohmann::json json = nlohmann::json::parse(read_file(folder / "classify.json"));
    EXPECT_EQ(json.at("regime"), seed.regime);
    EXPECT_EQ(json.at("case"), seed.id);

    const auto summary = key_values(out[k + 1]);
    EXPECT_NE(out[k + 1].find(seed.id), std::string::npos) << out[k + 1];
    EXPECT_EQ(summary.at("regime"), seed.regime);
    EXPECT_EQ(to_double(summary.at("lambda")), seed.lambda);
    EXPECT_EQ(to_double(summary.at("v0")), seed.v0);
    EXPECT_EQ(summary.at("stick"), std::to_string(reference.count("stick")));
    EXPECT_EQ(summary.at("slip+"), std::to_string(reference.count("slip+")));
    EXPECT_EQ(summary.at("slip-"), std::to_string(reference.count("slip-")));
    // Stops: slips ending at v = 0 before T; reversals: those followed at once
    // by a slip the other way (no stick between).
    std::size_t stops = 0, reversals = 0;
    const auto& phases = reference.phases();
    for (std::size_t i = 0; i + 1 < phases.size(); ++i) {
      if (phases[i].kind == "stick") continue;
      ++stops;
      reversals += phases[i + 1].kind != "stick";
    }
    EXPECT_EQ(summary.at("stops"), std::to_string(stops));
    EXPECT_EQ(summary.at("reversals"), std::to_string(reversals));
    EXPECT_EQ(to_double(summary.at("t")), 30.0);
    EXPECT_NEAR(to_double(summary.at("x")), static_cast<double>(reference.phases().back().x_end),
                1e-11);
    EXPECT_NE(summary.at("dir").find(seed.folder), std::string::npos);
    EXPECT_EQ(summary.at("stiff_vs_exact"), "PASS");
  }
  expect_no_temporary_files(dir);
}

// The committed case table data/seed-cases.csv (transcribed from the seed)
// and what `reproduce` runs are the same three cases.
TEST(Reproduce, RunsExactlyTheCasesOfTheDataTable) {
  const Csv table = parse_csv(read_file(fs::path(FRICTIONREF_SOURCE_DIR) / "data/seed-cases.csv"));
  ASSERT_EQ(table.header, "case,lambda,v0,seed_says");
  ASSERT_EQ(table.rows.size(), 3u);
  TempDir dir;
  const RunResult result = run_frictionref({"reproduce", "--out", "r"}, dir.path());
  ASSERT_TRUE(succeeded(result));
  const std::vector<std::string> out = case_lines(result.out);
  ASSERT_EQ(out.size(), 4u);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::vector<std::string>& row = table.rows[k];
    SCOPED_TRACE(row[0]);
    EXPECT_EQ(row[0], seed_cases[k].id);
    EXPECT_EQ(to_double(row[1]), seed_cases[k].lambda);
    EXPECT_EQ(to_double(row[2]), seed_cases[k].v0);
    // "case 10.1: lambda=0.3 v0=0 ..."
    const std::string prefix = "case " + row[0] + ": ";
    ASSERT_EQ(out[k + 1].rfind(prefix, 0), 0u) << out[k + 1];
    const auto values = key_values(out[k + 1].substr(prefix.size()));
    EXPECT_EQ(to_double(values.at("lambda")), to_double(row[1]));
    EXPECT_EQ(to_double(values.at("v0")), to_double(row[2]));
  }
}

TEST(Reproduce, NoFiguresWritesTheTablesOnly) {
  TempDir cwd;
  const RunResult result = run_frictionref({"reproduce", "--out", "r", "--no-figures"}, cwd.path());
  check_results(cwd.path() / "r", result, /*figures=*/false);
}

TEST(Reproduce, DefaultFolderInTheWorkingDirectory) {
  TempDir cwd;
  const RunResult result = run_frictionref({"reproduce"}, cwd.path());
  check_results(cwd.path() / "frictionref-results", result);
  EXPECT_EQ(cwd.entries(), std::vector<std::string>{"frictionref-results"});
}

TEST(Reproduce, OutCreatesNestedFolders) {
  TempDir cwd;
  const RunResult result = run_frictionref({"reproduce", "--out", "a/b"}, cwd.path());
  check_results(cwd.path() / "a" / "b", result);
}

TEST(Reproduce, RunningTwiceReplacesTheFiles) {
  TempDir cwd;
  ASSERT_TRUE(succeeded(run_frictionref({"reproduce", "--out", "r"}, cwd.path())));
  const RunResult again = run_frictionref({"reproduce", "--out", "r"}, cwd.path());
  check_results(cwd.path() / "r", again);
}

TEST(Reproduce, UnwritableOutIsBadInput) {
  TempDir cwd;
  { std::ofstream(cwd.path() / "file") << "x"; }  // a file where a folder must go
  const RunResult result = run_frictionref({"reproduce", "--out", "file"}, cwd.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("--out"), std::string::npos) << result.err;
  EXPECT_EQ(cwd.entries(), std::vector<std::string>{"file"});
}

}  // namespace
}  // namespace frictionref::cli_test
