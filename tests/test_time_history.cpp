// Reading another code's time history (time_history.hpp): messy but valid
// files read right, and every bad file is refused with an InvalidInput that
// names the file, line and column and the rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref {
namespace {

using testing::expect_invalid;

TimeHistory parse(const std::string& text, const TimeHistoryReadOptions& options = {}) {
  std::istringstream in(text);
  return parse_time_history(in, "run.csv", options);
}

InvalidInput refused(const std::string& text, const TimeHistoryReadOptions& options = {}) {
  return expect_invalid([&] { parse(text, options); });
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TimeHistoryReadOptions columns(std::string time, std::string velocity,
                               std::string displacement = "") {
  TimeHistoryReadOptions options;
  options.time_column = std::move(time);
  options.velocity_column = std::move(velocity);
  options.displacement_column = std::move(displacement);
  return options;
}

// ---------------------------------------------------------------------------
// Valid files.

TEST(TimeHistoryRead, CsvWithHeader) {
  const TimeHistory h = parse("t,v\n0,0\n0.5,0.25\n1,-1\n");
  EXPECT_EQ(h.t, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(h.v, (std::vector<double>{0, 0.25, -1}));
  EXPECT_FALSE(h.x.has_value());
  EXPECT_EQ(h.rows(), 3u);
  EXPECT_NO_THROW(h.validate());
  EXPECT_TRUE(contains(h.source, "run.csv")) << h.source;
  EXPECT_TRUE(contains(h.source, "time: column 1 (t)")) << h.source;
  EXPECT_TRUE(contains(h.source, "velocity: column 2 (v)")) << h.source;
  EXPECT_TRUE(contains(h.source, "3 rows on lines 2-4")) << h.source;
}

TEST(TimeHistoryRead, WhitespaceWithoutHeaderUsesColumnsOneAndTwo) {
  const TimeHistory h = parse("  0.0   1.0  9\n\t0.1\t2.0\t9\n0.2 3.0 9   \n");
  EXPECT_EQ(h.t, (std::vector<double>{0, 0.1, 0.2}));
  EXPECT_EQ(h.v, (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(contains(h.source, "time: column 1, velocity: column 2")) << h.source;
}

TEST(TimeHistoryRead, CommentsBlankLinesCrlfBomAndScientificNotation) {
  const std::string text =
      "\xEF\xBB\xBF# produced by some code\r\n"
      "\r\n"
      "# t [s], v [m/s]\r\n"
      "time,velocity   # units: SI\r\n"
      "0.0E+00, 1.5e-3\r\n"
      "   \r\n"
      "1.0e-2, -2.5E+01 # a trailing comment\r\n"
      "# a comment between rows\r\n"
      "2D-2, 0.3d0\r\n"  // Fortran exponents
      "3e-2,+4.\r\n";
  const TimeHistory h = parse(text);
  EXPECT_EQ(h.t, (std::vector<double>{0, 0.01, 0.02, 0.03}));
  EXPECT_EQ(h.v, (std::vector<double>{1.5e-3, -25, 0.3, 4}));
  EXPECT_TRUE(contains(h.source, "lines 5-10")) << h.source;
}

TEST(TimeHistoryRead, QuotedHeaderNamesWithUnits) {
  const std::string text =
      "\"Time [s]\",\"Displacement (m)\",\"Velocity (m/s)\"\n"
      "0,0,1\n"
      "1,1,2\n";
  const TimeHistory h = parse(text, columns("", "", "displacement"));
  EXPECT_EQ(h.v, (std::vector<double>{1, 2}));
  ASSERT_TRUE(h.x.has_value());
  EXPECT_EQ(*h.x, (std::vector<double>{0, 1}));
  EXPECT_TRUE(contains(h.source, "velocity: column 3 (Velocity (m/s))")) << h.source;
  // The full name, in any case, names the column too.
  EXPECT_EQ(parse(text, columns("TIME [S]", "velocity (m/s)")).v, h.v);
}

TEST(TimeHistoryRead, ColumnsByNameAndByNumber) {
  const std::string text = "step;time;x;vel;acc\n1;0;0;5;0\n2;0.1;0.5;6;0\n";  // semicolons
  const TimeHistory by_default = parse(text);
  EXPECT_EQ(by_default.t, (std::vector<double>{0, 0.1}));
  EXPECT_EQ(by_default.v, (std::vector<double>{5, 6}));
  const TimeHistory by_name = parse(text, columns("time", "acc", "x"));
  EXPECT_EQ(by_name.v, (std::vector<double>{0, 0}));
  EXPECT_EQ(*by_name.x, (std::vector<double>{0, 0.5}));
  const TimeHistory by_number = parse(text, columns("2", "4", "3"));
  EXPECT_EQ(by_number.t, by_default.t);
  EXPECT_EQ(by_number.v, by_default.v);
  EXPECT_EQ(*by_number.x, *by_name.x);
  const TimeHistory mixed = parse("0 7 1\n1 8 2\n", columns("1", "3"));
  EXPECT_EQ(mixed.v, (std::vector<double>{1, 2}));
}

TEST(TimeHistoryRead, OurOwnCurveOutputWithItsTextColumn) {
  const std::string text =
      "# frictionref 0.1.0\n"
      "# model: mass=1 amplitude=1 omega=1 friction=0.7 lambda=0.7 x0=0 v0=0 t0=0\n"
      "t,x,v,a,phase\n"
      "0,0,0,0,stick\n"
      "0.775397496610753,0,0,-2.4231918555051024e-17,slip+\n"
      "1,0.0012710858896386448,0.016618784613672437,0.14147098480789655,slip+\n";
  const TimeHistory h = parse(text, columns("", "", "x"));
  EXPECT_EQ(h.t[1], 0.775397496610753);  // 17 digits read back exactly
  EXPECT_EQ(h.v[2], 0.016618784613672437);
  EXPECT_EQ((*h.x)[2], 0.0012710858896386448);
}

TEST(TimeHistoryRead, RepeatedTimesAndEmptyUnusedFieldsAreAccepted) {
  const TimeHistory h = parse("t,v,note\n0,0,\n1,1,\n1,1,event\n2,0,\n");
  EXPECT_EQ(h.t, (std::vector<double>{0, 1, 1, 2}));
}

TEST(TimeHistoryRead, ReadsAFileByPath) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "frictionref-test-history.txt";
  {
    std::ofstream out(path);
    out << "t v\n0 0\n1 1\n";
  }
  const TimeHistory h = read_time_history(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(h.v, (std::vector<double>{0, 1}));
  EXPECT_TRUE(contains(h.source, path.string()));
}

// ---------------------------------------------------------------------------
// Bad files: file, line, column and rule.

// ---------------------------------------------------------------------------
// Files real codes write (issue 13): spreadsheet exports with ';' and decimal
// commas, headers with unit suffixes, title lines without '#', restarts.

TEST(TimeHistoryRead, SemicolonsWithDecimalCommas) {
  const TimeHistory h = parse("t;v;x\n0;0;1,5\n0,5;-0,25;2\n1;1e-3;-3,125\n", columns("", "", "x"));
  EXPECT_EQ(h.t, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(h.v, (std::vector<double>{0, -0.25, 1e-3}));
  EXPECT_EQ(*h.x, (std::vector<double>{1.5, 2, -3.125}));
  // Two commas, or a comma beside a point, is not a number.
  EXPECT_TRUE(contains(refused("t;v\n0;1,2,3\n1;1\n").rule(), "must be a number"));
  EXPECT_TRUE(contains(refused("t;v\n0;1.2,3\n1;1\n").rule(), "must be a number"));
}

TEST(TimeHistoryRead, DecimalCommaOptionBetweenBlanks) {
  TimeHistoryReadOptions options;
  options.decimal_comma = true;
  const TimeHistory h = parse("t v\n0 0,5\n1,25 -2\n", options);
  EXPECT_EQ(h.t, (std::vector<double>{0, 1.25}));
  EXPECT_EQ(h.v, (std::vector<double>{0.5, -2}));
  // Without the option the comma separates: "0 0,5" is one field "0 0" and "5".
  EXPECT_NO_THROW(parse("t,v\n0,0.5\n1.25,-2\n"));
}

TEST(TimeHistoryRead, HeaderNamesWithUnitSuffixes) {
  const TimeHistory h = parse("time_s,x_m,v_mps\n0,1,2\n1,3,4\n", columns("", "", "x"));
  EXPECT_EQ(h.t, (std::vector<double>{0, 1}));
  EXPECT_EQ(h.v, (std::vector<double>{2, 4}));
  EXPECT_EQ(*h.x, (std::vector<double>{1, 3}));
  const TimeHistory named =
      parse("T-s;Disp-mm;Velocity (m/s)\n0;1;2\n1;3;4\n", columns("t", "velocity", "disp"));
  EXPECT_EQ(named.v, (std::vector<double>{2, 4}));
  EXPECT_EQ(*named.x, (std::vector<double>{1, 3}));
  // An exact name wins over a suffix match: "v" is column 2, not "v_old".
  EXPECT_EQ(parse("t,v,v_old\n0,1,9\n1,2,9\n").v, (std::vector<double>{1, 2}));
}

TEST(TimeHistoryRead, TitleLinesBeforeTheHeaderAreSkippedWithANote) {
  const TimeHistory h =
      parse("FRICTION MODEL RUN 42\nsolver: explicit\ntime_s,v_mps\n0,0\n1,0.5\n");
  EXPECT_EQ(h.t, (std::vector<double>{0, 1}));
  ASSERT_EQ(h.notes.size(), 1u);
  EXPECT_EQ(h.notes[0],
            "skipped 2 title lines before the table (lines 1-2: 'FRICTION MODEL RUN 42', ...)");
  EXPECT_TRUE(contains(h.source, "time: column 1 (time_s)")) << h.source;
  // Without a header nothing is skipped: a line before the first row is a
  // bad row (here the header of another table shape), and is named.
  EXPECT_EQ(refused("Run 7\n0 0\n1 2\n").parameter(), "run.csv:1 column 1");
  EXPECT_EQ(refused("t;v\n0;1,2,3\n1;1\n").parameter(), "run.csv:2 column 2 (v)");
  // A plain file has no note.
  EXPECT_TRUE(parse("t,v\n0,0\n1,1\n").notes.empty());
}

TEST(TimeHistoryRead, SkipRowsSkipsLinesBeforeTheTable) {
  TimeHistoryReadOptions options;
  options.skip_rows = 2;
  // The second skipped line has numbers: only --skip-rows can say it is not a row.
  const TimeHistory h = parse("# comment\nSOLVER X\n3 4 5\nt v\n0 0\n1 1\n", options);
  EXPECT_EQ(h.t, (std::vector<double>{0, 1}));
  ASSERT_FALSE(h.notes.empty());
  EXPECT_EQ(h.notes[0], "skipped 2 lines before the table as asked (lines 2-3)");
  options.skip_rows = 9;
  const InvalidInput error = refused("t v\n0 0\n1 1\n", options);
  EXPECT_EQ(error.parameter(), "skip_rows");
  EXPECT_TRUE(contains(error.rule(), "has only 3 lines that are not comments or blank"));
}

TEST(TimeHistoryRead, RestartKeepsTheLaterSegmentWhenAsked) {
  const std::string file = "t,v,x\n0,0,0\n1,1,1\n2,2,2\n3,3,3\n1.5,5,5\n2.5,6,6\n4,7,7\n";
  // By default: an error naming the option.
  const InvalidInput error = refused(file, columns("", "", "x"));
  EXPECT_TRUE(contains(error.rule(), "times must not decrease")) << error.rule();
  EXPECT_TRUE(contains(error.rule(), "--on-overlap keep-last")) << error.rule();
  TimeHistoryReadOptions options = columns("", "", "x");
  options.on_overlap = TimeHistoryReadOptions::OnOverlap::keep_last;
  const TimeHistory h = parse(file, options);
  EXPECT_EQ(h.t, (std::vector<double>{0, 1, 1.5, 2.5, 4}));
  EXPECT_EQ(h.v, (std::vector<double>{0, 1, 5, 6, 7}));
  EXPECT_EQ(*h.x, (std::vector<double>{0, 1, 5, 6, 7}));
  ASSERT_EQ(h.notes.size(), 1u);
  EXPECT_EQ(h.notes[0],
            "time went back at line 6 (from 3 to 1.5): kept the later segment, dropped the 2 "
            "earlier rows at or after 1.5");
  // A restart to before the first row keeps only the later segment.
  TimeHistoryReadOptions keep;
  keep.on_overlap = TimeHistoryReadOptions::OnOverlap::keep_last;
  EXPECT_EQ(parse("t,v\n5,0\n6,1\n0,2\n1,3\n", keep).t, (std::vector<double>{0, 1}));
}

TEST(TimeHistoryBad, UnreadableFileAndDirectory) {
  InvalidInput e = expect_invalid([] { read_time_history("/nonexistent/run.csv"); });
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_EQ(e.value(), "/nonexistent/run.csv");
  EXPECT_TRUE(contains(e.rule(), "cannot be opened: No such file or directory")) << e.what();
  e = expect_invalid([] { read_time_history(std::filesystem::temp_directory_path().string()); });
  EXPECT_TRUE(contains(e.rule(), "directory")) << e.what();
}

TEST(TimeHistoryBad, EmptyOnlyCommentsOnlyHeader) {
  InvalidInput e = refused("");
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_EQ(e.value(), "run.csv");
  EXPECT_EQ(e.rule(), "is empty");
  EXPECT_EQ(refused("\n  \n").rule(), "is empty");
  EXPECT_TRUE(contains(refused("# nothing here\n\n").rule(), "no data rows"))
      << refused("#\n").what();
  e = refused("# c\nt,v\n");
  EXPECT_TRUE(contains(e.rule(), "no data rows after its header (line 2)")) << e.what();
}

TEST(TimeHistoryBad, NoNumbers) {
  const InvalidInput e = refused("hello world\nthis is not\na time history\n");
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_TRUE(contains(e.rule(), "contains no numbers")) << e.what();
}

TEST(TimeHistoryBad, OneColumn) {
  const InvalidInput e = refused("# c\n0.0\n0.1\n");
  EXPECT_EQ(e.parameter(), "run.csv:2");
  EXPECT_EQ(e.value(), "0.0");
  EXPECT_TRUE(contains(e.rule(), "has 1 column")) << e.what();
  EXPECT_TRUE(contains(e.rule(), "at least 2 (time and velocity)")) << e.what();
}

TEST(TimeHistoryBad, RaggedRow) {
  const InvalidInput e = refused("t,v,x\n0,0,0\n1,1\n2,2,2\n");
  EXPECT_EQ(e.parameter(), "run.csv:3");
  EXPECT_EQ(e.value(), "1,1");
  EXPECT_TRUE(contains(e.rule(), "has 2 columns, but line 1 has 3")) << e.what();
}

TEST(TimeHistoryBad, NotANumberInAColumnInUse) {
  InvalidInput e = refused("t,v\n0,0\n0.1,fast\n");
  EXPECT_EQ(e.parameter(), "run.csv:3 column 2 (v)");
  EXPECT_EQ(e.value(), "fast");
  EXPECT_EQ(e.rule(), "must be a number");
  EXPECT_EQ(std::string(e.what()), "run.csv:3 column 2 (v) = fast; violated: must be a number");
  e = refused("0 0\n0.1 1.2.3\n");
  EXPECT_EQ(e.parameter(), "run.csv:2 column 2");
  e = refused("t,v\n0,0\n0.1,\n");
  EXPECT_EQ(e.value(), "(empty)");
}

TEST(TimeHistoryBad, NanAndInfinity) {
  InvalidInput e = refused("t,v\n0,0\n0.1,nan\n");
  EXPECT_EQ(e.parameter(), "run.csv:3 column 2 (v)");
  EXPECT_EQ(e.value(), "nan");
  EXPECT_EQ(e.rule(), "must be a finite number");
  e = refused("t,v\n0,0\ninf,1\n");
  EXPECT_EQ(e.parameter(), "run.csv:3 column 1 (t)");
  e = refused("t,v\n0,0\n1,1e999\n");  // overflows to infinity
  EXPECT_EQ(e.rule(), "must be a finite number");
}

TEST(TimeHistoryBad, TimeGoesBackwards) {
  const InvalidInput e = refused("t,v\n0,0\n# c\n0.2,1\n0.1,2\n");
  EXPECT_EQ(e.parameter(), "run.csv:5 column 1 (t)");
  EXPECT_EQ(e.value(), "0.1");
  EXPECT_TRUE(contains(e.rule(), "must be >= the time on line 4 (0.2)")) << e.what();
}

TEST(TimeHistoryBad, TooFewRowsOrNoTimeSpan) {
  InvalidInput e = refused("t,v\n0,0\n");
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_TRUE(contains(e.rule(), "only 1 data row (line 2)")) << e.what();
  e = refused("t,v\n1,0\n1,2\n");
  EXPECT_TRUE(contains(e.rule(), "same time 1")) << e.what();
}

TEST(TimeHistoryBad, UnknownColumnName) {
  InvalidInput e = refused("t,x,v\n0,0,0\n1,1,1\n", columns("", "speed"));
  EXPECT_EQ(e.parameter(), "velocity_column");
  EXPECT_EQ(e.value(), "speed");
  EXPECT_TRUE(contains(e.rule(), "no such column in the header of run.csv (line 1)")) << e.what();
  EXPECT_TRUE(contains(e.rule(), "its columns: t, x, v")) << e.what();
  // No t/time column for the default.
  e = refused("a,b\n0,0\n1,1\n");
  EXPECT_EQ(e.parameter(), "time_column");
  EXPECT_TRUE(contains(e.rule(), "no such column")) << e.what();
  // A name needs a header.
  e = refused("0 0\n1 1\n", columns("time", ""));
  EXPECT_EQ(e.parameter(), "time_column");
  EXPECT_TRUE(contains(e.rule(), "no header line")) << e.what();
}

TEST(TimeHistoryBad, ColumnNumberOutOfRange) {
  InvalidInput e = refused("0 0 0\n1 1 1\n", columns("1", "4"));
  EXPECT_EQ(e.parameter(), "velocity_column");
  EXPECT_EQ(e.value(), "4");
  EXPECT_TRUE(contains(e.rule(), "from 1 to 3")) << e.what();
  e = refused("0 0\n1 1\n", columns("0", ""));
  EXPECT_EQ(e.parameter(), "time_column");
  EXPECT_TRUE(contains(e.rule(), "start at 1")) << e.what();
  e = refused("0 0\n1 1\n", columns("", "", "99999999999999999999"));
  EXPECT_EQ(e.parameter(), "displacement_column");
}

TEST(TimeHistoryBad, SameColumnTwice) {
  InvalidInput e = refused("0 0\n1 1\n", columns("1", "1"));
  EXPECT_EQ(e.parameter(), "velocity_column");
  EXPECT_TRUE(contains(e.rule(), "is the time column")) << e.what();
  e = refused("t,v\n0 ,0\n1,1\n", columns("", "", "v"));
  EXPECT_EQ(e.parameter(), "displacement_column");
  EXPECT_TRUE(contains(e.rule(), "is the velocity column")) << e.what();
}

TEST(TimeHistoryBad, ReadOptionsValidate) {
  EXPECT_NO_THROW(TimeHistoryReadOptions().validate());
  EXPECT_EQ(expect_invalid([] { columns(" ", "").validate(); }).parameter(), "time_column");
  EXPECT_EQ(expect_invalid([] { columns("", "00").validate(); }).parameter(), "velocity_column");
}

TEST(TimeHistoryValidate, RulesForInMemoryHistories) {
  TimeHistory h;
  h.t = {0, 1};
  h.v = {0, 1};
  EXPECT_NO_THROW(h.validate());
  h.x = std::vector<double>{0};
  EXPECT_EQ(expect_invalid([&] { h.validate(); }).parameter(), "x");
  h.x.reset();
  h.t = {0, 0};
  EXPECT_EQ(expect_invalid([&] { h.validate(); }).parameter(), "t");
  h.t = {0};
  h.v = {0};
  EXPECT_EQ(expect_invalid([&] { h.validate(); }).rule(), "needs at least 2 rows");
}

}  // namespace
}  // namespace frictionref
