// `frictionref newmark`: the table and its metadata on records solved by
// hand (SLAMMER's sign convention, one-way and two-way, both polarities),
// JSON with null for a block that never stops, --method slammer against the
// independent Python transliteration of SLAMMER (tests/data/records), the
// figures, and every bad input (one line, exit 2, no file).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bad_input.hpp"
#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

const std::string kSource = FRICTIONREF_SOURCE_DIR;
const std::string kPulseTrain = kSource + "/data/records/synthetic/pulse-train.AT2";
const std::string kNonuniform = kSource + "/data/records/synthetic/nonuniform.csv";

const char* const kHeader =
    "record,yield_accel_g,pga_g,polarity,method,displacement_at_record_end,"
    "permanent_displacement,slip_episodes,max_relative_velocity";

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// a = 3 g for 0 <= t <= 2 s, KY = 1 g, in units where g = 1 (--gravity 1):
// x'' = 2 until t = 2 (x = 4, v = 4), then x'' = -1 until rest at x = 12.
TEST(Newmark, HandSolvedPulseInBothPolaritiesAndBothWays) {
  TempDir dir;
  write(dir.path() / "pulse.csv", "t,a\n0,3\n2,3\n");
  for (const char* way : {"--one-way", "--two-way"}) {
    const RunResult result = run_frictionref({"newmark", "--record", "pulse.csv", "--yield-accel",
                                              "1", "--gravity", "1", "--both-polarities", way},
                                             dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const Csv csv = parse_csv(result.out);
    EXPECT_EQ(csv.header, kHeader);
    EXPECT_NE(csv.meta("record").find("pulse.csv"), std::string::npos);
    EXPECT_NE(csv.meta("newmark").find(std::string("sliding=") + (way + 2)), std::string::npos)
        << csv.meta("newmark");
    ASSERT_EQ(csv.rows.size(), 2u);
    // Normal: downslope, 4 at the record's end, 12 at rest.
    EXPECT_EQ(csv.rows[0][0], "pulse.csv");
    EXPECT_EQ(csv.rows[0][1], "1");
    EXPECT_EQ(csv.rows[0][2], "3");
    EXPECT_EQ(csv.rows[0][3], "normal");
    EXPECT_EQ(csv.rows[0][4], "exact");
    EXPECT_EQ(csv.rows[0][5], "4");
    EXPECT_EQ(csv.rows[0][6], "12");
    EXPECT_EQ(csv.rows[0][7], "1");
    EXPECT_EQ(csv.rows[0][8], "4");
    // Inverse: upslope, which only the two-way block may do.
    EXPECT_EQ(csv.rows[1][3], "inverse");
    const bool two_way = std::string(way) == "--two-way";
    EXPECT_EQ(csv.rows[1][5], two_way ? "-4" : "0");
    EXPECT_EQ(csv.rows[1][6], two_way ? "-12" : "0");
    EXPECT_EQ(csv.rows[1][7], two_way ? "1" : "0");
  }
}

// KY = 0: the block never stops once the ground does; --scale 2 doubles
// the record: x'' = 6 for 2 s, x = 12 at the end, v = 12 for ever.
TEST(Newmark, JsonWithNullForABlockThatNeverStops) {
  TempDir dir;
  write(dir.path() / "pulse.csv", "t,a\n0,3\n2,3\n");
  const RunResult result =
      run_frictionref({"newmark", "--record", "pulse.csv", "--yield-accel", "0,1", "--gravity", "1",
                       "--scale", "2", "--json", "-o", "n.json"},
                      dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.out.empty());
  const nlohmann::json json = nlohmann::json::parse(read_file(dir.path() / "n.json"));
  ASSERT_TRUE(json.is_array());
  ASSERT_EQ(json.size(), 2u);
  for (const char* key :
       {"record", "yield_accel_g", "polarity", "method", "displacement_at_record_end",
        "permanent_displacement", "slip_episodes", "max_relative_velocity"})
    EXPECT_TRUE(json[0].contains(key)) << key;
  EXPECT_EQ(json[0]["yield_accel_g"], 0.0);
  EXPECT_EQ(json[0]["displacement_at_record_end"], 12.0);
  EXPECT_TRUE(json[0]["permanent_displacement"].is_null());
  EXPECT_EQ(json[0]["max_relative_velocity"], 12.0);
  // KY = 1: x'' = 5 for 2 s (x = 10, v = 10), then 50 further.
  EXPECT_EQ(json[1]["displacement_at_record_end"], 10.0);
  EXPECT_EQ(json[1]["permanent_displacement"], 60.0);
  EXPECT_EQ(json[1]["polarity"], "normal");
  EXPECT_EQ(json[1]["method"], "exact");
  EXPECT_EQ(json[1]["pga_g"], 6.0);
}

// SLAMMER's algorithm in the tool against the separate Python
// transliteration of its Java source, to the last bit (centimetres, as
// SLAMMER).
TEST(Newmark, SlammerMethodMatchesTheIndependentTransliteration) {
  const std::string reference = read_file(kSource + "/tests/data/records/slammer_reference.csv");
  const Csv table = parse_csv(reference);
  std::size_t checked = 0;
  for (const std::vector<std::string>& row : table.rows) {
    if (row[0] != "pulse-train.AT2") continue;
    const bool two_way = row[2] == "two-way";
    const bool inverse = row[3] == "inverse";
    std::vector<std::string> args{
        "newmark",   "--record", kPulseTrain, "--yield-accel", row[1],
        "--gravity", "980.665",  "--method",  "slammer",       two_way ? "--two-way" : "--one-way"};
    if (inverse) args.push_back("--inverse");
    const RunResult result = run_frictionref(args);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const Csv csv = parse_csv(result.out);
    ASSERT_EQ(csv.rows.size(), 1u);
    EXPECT_EQ(to_double(csv.rows[0][5]), to_double(row[4])) << row[1] << " " << row[2];
    EXPECT_EQ(csv.rows[0][7], row[5]);
    EXPECT_EQ(to_double(csv.rows[0][8]), to_double(row[6]));
    EXPECT_EQ(csv.rows[0][4], "slammer");
    ++checked;
  }
  EXPECT_GE(checked, 4u);
}

TEST(Newmark, FiguresForTheCurveAndForOneRun) {
  TempDir dir;
  RunResult result =
      run_frictionref({"newmark", "--record", kPulseTrain, "--yield-accel", "0.02,0.05,0.1",
                       "--both-polarities", "-o", "n.csv", "--plot", "curve.svg"},
                      dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(read_file(dir.path() / "curve.svg").find("<svg"), std::string::npos);
  result = run_frictionref({"newmark", "--record", kPulseTrain, "--yield-accel", "0.1", "--method",
                            "slammer", "-o", "n.csv", "--plot", "history.svg"},
                           dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string svg = read_file(dir.path() / "history.svg");
  EXPECT_NE(svg.find("SLAMMER"), std::string::npos);
  EXPECT_NE(svg.find("KY = 0.1 g"), std::string::npos);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"curve.svg", "history.svg", "n.csv"}));
}

// The penalty model (stiff) carries the record too: a = -3 for 0 <= t <= 2
// (--gravity 1), R = 1: exact stop at t = 6, x = 12 (as events says).
TEST(Records, StiffSpringAndEventsOnAHandSolvedRecord) {
  TempDir dir;
  write(dir.path() / "pulse.csv", "t,a\n0,-3\n2,-3\n");
  RunResult result = run_frictionref({"events", "--ground-accel", "pulse.csv", "--gravity", "1",
                                      "--yield-accel", "1", "--t-end", "10"},
                                     dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  Csv csv = parse_csv(result.out);
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0][0], "slip+");
  EXPECT_EQ(csv.rows[0][2], "6");
  EXPECT_EQ(csv.rows[0][4], "12");
  // The penalty model's error shrinks as its step does (about as 1 / sqrt(kf)):
  // 4.5e-3 at kf = 1e6, 4.5e-4 at 1e8.
  double previous = 1;
  for (const char* kf : {"1e6", "1e8"}) {
    result = run_frictionref({"stiff", "--ground-accel", "pulse.csv", "--gravity", "1",
                              "--yield-accel", "1", "--t-end", "10", "--kf", kf},
                             dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    csv = parse_csv(result.out);
    ASSERT_FALSE(csv.rows.empty());
    const double error = std::fabs(to_double(csv.rows.back()[1]) - 12.0);
    EXPECT_LT(error, previous / 5) << "kf " << kf;
    EXPECT_LT(error, 1e-2) << "kf " << kf;
    previous = error;
  }
}

// Commands that need what a record does not have refuse it, naming it.
class RecordRefused : public ::testing::TestWithParam<BadInput> {};

TEST_P(RecordRefused, OneLineExit2NoFile) { expect_rejected(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    Records, RecordRefused,
    ::testing::Values(
        BadInput{{"classify", "--ground-accel", kPulseTrain, "--yield-accel", "0.1"},
                 "--ground-accel",
                 "no steady state"},
        BadInput{writing("sweep", {"--ground-accel", kPulseTrain, "--lambda-from", "0",
                                   "--lambda-to", "1", "--points", "3"}),
                 "--ground-accel", "not taken by sweep"},
        BadInput{writing("map", {"--ground-accel", kPulseTrain, "--x", "lambda:0:1:3", "--y",
                                 "omega:1:2:3"}),
                 "--ground-accel", "not taken by map"},
        BadInput{writing("stiff", {"--ground-accel", kPulseTrain, "--yield-accel", "0.1",
                                   "--one-way", "--t-end", "1"}),
                 "--one-way", "no one-way slider"},
        BadInput{writing("events", {"--one-way", "--friction", "0.1", "--t-end", "1"}), "--one-way",
                 "--ground-accel"},
        BadInput{writing("events", {"--ground-accel", kPulseTrain, "--yield-accel", "0.1",
                                    "--friction", "1", "--t-end", "1"}),
                 "--yield-accel", ""}),
    bad_input_name);

class NewmarkBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(NewmarkBadInput, OneLineExit2NoFile) { expect_rejected(GetParam()); }

const std::string kRecord = kPulseTrain;

INSTANTIATE_TEST_SUITE_P(
    Newmark, NewmarkBadInput,
    ::testing::Values(
        BadInput{writing("newmark", {"--yield-accel", "0.1"}), "--record", "required"},
        BadInput{writing("newmark", {"--record", kRecord}), "--yield-accel", "required"},
        BadInput{writing("newmark", {"--record", "missing.AT2", "--yield-accel", "0.1"}),
                 "--record = missing.AT2", ""},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "-0.1"}),
                 "--yield-accel = -0.1", ">= 0"},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "0.1,nan"}),
                 "--yield-accel = nan", "finite"},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "0.1,abc"}),
                 "--yield-accel", "number"},
        BadInput{
            writing("newmark", {"--record", kRecord, "--yield-accel", "0", "--method", "slammer"}),
            "--yield-accel = 0", "slammer"},
        BadInput{writing("newmark",
                         {"--record", kRecord, "--yield-accel", "0.1", "--method", "newmark"}),
                 "--method = newmark", "exact or slammer"},
        BadInput{writing("newmark",
                         {"--record", kNonuniform, "--yield-accel", "0.1", "--method", "slammer"}),
                 "--record", "uniform step"},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--scale", "2",
                                     "--target-pga", "0.3"}),
                 "--target-pga", "--scale"},
        BadInput{
            writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--target-pga", "0"}),
            "--target-pga = 0", "> 0"},
        BadInput{writing("newmark",
                         {"--record", kNonuniform, "--yield-accel", "0.1", "--record-dt", "0.01"}),
                 "--record-dt", ""},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--accel-units",
                                     "furlongs"}),
                 "--accel-units = furlongs", "g, m/s2"},
        BadInput{
            writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--gravity", "-9.8"}),
            "--gravity = -9.8", "> 0"},
        BadInput{writing("newmark",
                         {"--record", kRecord, "--yield-accel", "0.1", "--one-way", "--two-way"}),
                 "--one-way", "excludes"},
        BadInput{writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--inverse",
                                     "--both-polarities"}),
                 "--inverse", "excludes"},
        BadInput{
            writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--threads", "0"}),
            "--threads = 0", "whole number"},
        BadInput{
            writing("newmark", {"--record", kRecord, "--yield-accel", "0.1", "--plot", "n.pdf"}),
            "--plot", ".svg"}),
    bad_input_name);

// Files that are not records: one line naming the file, exit 2, no output.
TEST(Newmark, BadRecordFiles) {
  const std::vector<std::pair<std::string, std::string>> files{
      {"one.csv", "t,a\n0,1\n"},
      {"backwards.csv", "t,a\n0,1\n1,2\n0.5,3\n"},
      {"nan.csv", "t,a\n0,1\n1,nan\n"},
      {"short.AT2",
       "PEER NGA\ntitle\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  5, DT= 0.0100 SEC\n"
       "0.1 0.2 0.3\n"},
      {"empty.csv", ""}};
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    TempDir dir;
    write(dir.path() / name, text);
    const RunResult result = run_frictionref(
        {"newmark", "--record", name, "--yield-accel", "0.1", "-o", "out.csv"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
    EXPECT_NE(result.err.find(name), std::string::npos) << result.err;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
  }
}

}  // namespace
}  // namespace frictionref::cli_test
