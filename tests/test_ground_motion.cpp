// Reading a ground-motion record (ground_motion.hpp): the three formats, the
// units and the scaling, the provenance, and a clear refusal of every bad
// file or option the record issue lists. Expected values are written by
// hand from the file texts (the samples and steps are exact in binary) or
// are published test vectors (SHA-256: FIPS 180-2, appendix B.1).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "frictionref/error.hpp"
#include "frictionref/ground_motion.hpp"
#include "frictionref/sha256.hpp"

namespace frictionref {
namespace {

using testing::expect_invalid;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

GroundMotion parse(const std::string& text, const std::string& name = "rec.csv",
                   const GroundMotionReadOptions& options = {}) {
  return parse_ground_motion(text, name, options);
}

InvalidInput refused(const std::string& text, const std::string& name = "rec.csv",
                     const GroundMotionReadOptions& options = {}) {
  return expect_invalid([&] { parse(text, name, options); });
}

// A PEER NGA-West2 .AT2 file of 7 samples (values in G, exact in binary).
const std::string kAt2 =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "Synthetic 2026, test station, 000\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n"
    "NPTS=    7, DT=   .0100 SEC\n"
    "  .5000000E-01  -.2500000E+00   .1250000E+00   .0000000E+00   .7500000E+00\n"
    " -.3750000E+00   .1000000D+01\n";

// ---------------------------------------------------------------------------
// Formats.

TEST(GroundMotionRead, PeerAt2NewHeader) {
  const GroundMotion r = parse(kAt2, "RSN1_TEST.AT2");
  EXPECT_EQ(r.format, "PEER NGA AT2");
  ASSERT_EQ(r.samples(), 7u);
  EXPECT_EQ(r.npts, 7u);
  ASSERT_TRUE(r.dt.has_value());
  EXPECT_EQ(*r.dt, 0.01);
  // t_i = i * dt as a product: t_3 = 3 * 0.01 in double, not 0.01 + 0.01 + 0.01.
  EXPECT_EQ(r.t[3], 3 * 0.01);
  EXPECT_EQ(r.t.front(), 0.0);
  EXPECT_EQ(r.units, AccelUnits::g);
  EXPECT_EQ(r.pga_as_read, 1.0);
  // Output in m/s^2 with the default gravity: a = a_g * 9.80665.
  EXPECT_EQ(r.a[0], 0.05 * 9.80665);
  EXPECT_EQ(r.a[1], -0.25 * 9.80665);
  EXPECT_EQ(r.a[6], 9.80665);
  EXPECT_EQ(r.header.size(), 4u);
  EXPECT_EQ(r.header[3], "NPTS=    7, DT=   .0100 SEC");
  EXPECT_EQ(r.scaling, "none");
  EXPECT_NO_THROW(r.validate());
}

TEST(GroundMotionRead, PeerAt2OldHeaderFoundByItsFirstLine) {
  const std::string old =
      "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\r\n"
      "SYNTHETIC 01/01/26, TEST, 090\r\n"
      "ACCELERATION TIME HISTORY IN UNITS OF G\r\n"
      " 4    0.02000    NPTS, DT\r\n"
      " 0.5 -0.5\r\n"
      " 0.25 0.0\r\n";
  const GroundMotion r = parse(old, "record.txt");  // no .AT2 extension: the first line tells
  EXPECT_EQ(r.format, "PEER NGA AT2");
  EXPECT_EQ(r.samples(), 4u);
  EXPECT_EQ(*r.dt, 0.02);
  EXPECT_EQ(r.a[2], 0.25 * 9.80665);
}

TEST(GroundMotionRead, TwoColumnTableWithHeaderCommentsBomAndCrlf) {
  const std::string text =
      "\xEF\xBB\xBF# a record\r\n"
      "time [s], accel [g]\r\n"
      "0, 0\r\n"
      "0.5, 0.25 # comment\r\n"
      "0.75, -1.5D-1\r\n";
  const GroundMotion r = parse(text);
  EXPECT_EQ(r.format, "time-acceleration table");
  EXPECT_EQ(r.t, (std::vector<double>{0, 0.5, 0.75}));
  EXPECT_EQ(r.a[1], 0.25 * 9.80665);
  EXPECT_EQ(r.a[2], -0.15 * 9.80665);
  EXPECT_FALSE(r.dt.has_value());  // non-uniform times are allowed
}

TEST(GroundMotionRead, HeaderNamesTheColumnsInAnyOrder) {
  const GroundMotion r = parse("acc t\n1 0\n2 0.5\n");
  EXPECT_EQ(r.t, (std::vector<double>{0, 0.5}));
  EXPECT_EQ(r.a[1], 2 * 9.80665);
  const GroundMotion wide = parse("station,t,a\n7,0,1\n7,1,2\n");
  EXPECT_EQ(wide.t, (std::vector<double>{0, 1}));
  EXPECT_EQ(wide.a[0], 9.80665);
}

TEST(GroundMotionRead, OneColumnWithStep) {
  GroundMotionReadOptions options;
  options.record_dt = 0.005;
  const GroundMotion r = parse("0.1\n-0.2\n0.3\n", "PET-000", options);
  EXPECT_EQ(r.format, "one column");
  EXPECT_EQ(r.t, (std::vector<double>{0, 0.005, 2 * 0.005}));
  EXPECT_EQ(*r.dt, 0.005);
}

// ---------------------------------------------------------------------------
// Units, gravity, scaling, polarity.

TEST(GroundMotionUnits, WordsRoundTrip) {
  for (AccelUnits units : {AccelUnits::g, AccelUnits::m_per_s2, AccelUnits::cm_per_s2,
                           AccelUnits::ft_per_s2, AccelUnits::in_per_s2})
    EXPECT_EQ(accel_units_from_string(to_string(units)), units);
  EXPECT_FALSE(accel_units_from_string("gal").has_value());
  EXPECT_FALSE(accel_units_from_string("G").has_value());
}

TEST(GroundMotionUnits, FileAlreadyInTheOutputUnitIsNotTouched) {
  GroundMotionReadOptions options;
  options.units = AccelUnits::m_per_s2;  // default gravity 9.80665: metres
  const GroundMotion r = parse("0 0.1\n1 -3.3\n", "rec.csv", options);
  EXPECT_EQ(r.factor, 1.0);
  EXPECT_EQ(r.a[1], -3.3);
  options.units = AccelUnits::cm_per_s2;
  options.gravity = 980.665;  // centimetres
  const GroundMotion cm = parse("0 0.1\n1 -578.22950395\n", "rec.csv", options);
  EXPECT_EQ(cm.a[1], -578.22950395);
}

TEST(GroundMotionUnits, ConversionsUseStandardGravity) {
  EXPECT_EQ(standard_gravity_in(AccelUnits::g), 1.0);
  EXPECT_EQ(standard_gravity_in(AccelUnits::m_per_s2), 9.80665);
  EXPECT_EQ(standard_gravity_in(AccelUnits::cm_per_s2), 980.665);
  // 1 ft = 0.3048 m and 1 in = 0.0254 m exactly: 32.17404855... ft/s^2, 386.0885826... in/s^2.
  EXPECT_NEAR(standard_gravity_in(AccelUnits::ft_per_s2), 32.174048556430446, 1e-13);
  EXPECT_NEAR(standard_gravity_in(AccelUnits::in_per_s2), 386.08858267716535, 1e-12);
  GroundMotionReadOptions options;
  options.units = AccelUnits::ft_per_s2;
  const GroundMotion r = parse("0 0\n1 32.174048556430446\n", "rec.csv", options);
  EXPECT_NEAR(r.a[1], 9.80665, 1e-14);  // one g in ft/s^2 is 9.80665 m/s^2
}

TEST(GroundMotionScaling, ScaleTargetPgaAndInverse) {
  GroundMotionReadOptions options;
  options.scale = 2;
  GroundMotion r = parse(kAt2, "x.AT2", options);
  EXPECT_EQ(r.a[6], 2 * 9.80665);
  EXPECT_EQ(r.scaling, "scale 2");

  options = {};
  options.target_pga = 0.5;  // PGA as read is 1 g
  r = parse(kAt2, "x.AT2", options);
  EXPECT_EQ(r.a[6], 0.5 * 9.80665);
  EXPECT_EQ(r.pga(), 0.5 * 9.80665);
  EXPECT_TRUE(contains(r.scaling, "target PGA 0.5 g")) << r.scaling;

  options.inverse = true;
  r = parse(kAt2, "x.AT2", options);
  EXPECT_EQ(r.a[6], -0.5 * 9.80665);
  EXPECT_EQ(r.a[1], 0.125 * 9.80665);
  EXPECT_TRUE(contains(r.scaling, "inverse")) << r.scaling;
}

// ---------------------------------------------------------------------------
// Provenance.

TEST(GroundMotionProvenance, Sha256OfTheBytes) {
  // FIPS 180-2, B.1: SHA-256("abc").
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const GroundMotion r = parse(kAt2, "x.AT2");
  EXPECT_EQ(r.sha256, sha256_hex(kAt2));
  EXPECT_EQ(r.file, "x.AT2");
}

TEST(GroundMotionProvenance, ReadsAFileFromDisk) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "frictionref_test_record.AT2";
  std::ofstream(path, std::ios::binary) << kAt2;
  const GroundMotion r = read_ground_motion(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(r.samples(), 7u);
  EXPECT_EQ(r.sha256, sha256_hex(kAt2));
}

// ---------------------------------------------------------------------------
// Bad input: one InvalidInput naming the file or option and the rule.

TEST(GroundMotionRefused, MissingOrUnreadableFile) {
  const InvalidInput e = expect_invalid([] { read_ground_motion("/nonexistent/dir/record.AT2"); });
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_TRUE(contains(e.rule(), "cannot be opened")) << e.what();
  const InvalidInput dir = expect_invalid([] { read_ground_motion("/"); });
  EXPECT_TRUE(contains(dir.rule(), "directory")) << dir.what();
}

TEST(GroundMotionRefused, FewerThanTwoSamples) {
  EXPECT_TRUE(contains(refused("").rule(), "is empty"));
  const InvalidInput one = refused("0 0.1\n");
  EXPECT_EQ(one.parameter(), "file");
  EXPECT_TRUE(contains(one.rule(), "1 sample; a record needs at least 2")) << one.what();
  GroundMotionReadOptions options;
  options.record_dt = 0.01;
  EXPECT_TRUE(contains(refused("0.1\n", "rec.txt", options).rule(), "at least 2"));
}

TEST(GroundMotionRefused, TimesThatDoNotIncrease) {
  const InvalidInput same = refused("0 1\n0.5 2\n0.5 3\n");
  EXPECT_EQ(same.parameter(), "rec.csv:3 column 1");
  EXPECT_TRUE(contains(same.rule(), "must increase")) << same.what();
  const InvalidInput back = refused("0 1\n0.5 2\n0.25 3\n");
  EXPECT_TRUE(contains(back.rule(), "must be > the time on line 2")) << back.what();
}

TEST(GroundMotionRefused, NonFiniteTimesOrAccelerations) {
  EXPECT_TRUE(contains(refused("0 1\nnan 2\n").rule(), "finite"));
  EXPECT_TRUE(contains(refused("0 1\n1 inf\n").rule(), "finite"));
  EXPECT_TRUE(contains(refused("0 1\n1 1e999\n").rule(), "finite"));
  std::string at2 = kAt2;
  at2.replace(at2.find(".1000000D+01"), 12, "         NaN");
  const InvalidInput e = refused(at2, "x.AT2");
  EXPECT_EQ(e.parameter(), "x.AT2:6");
  EXPECT_TRUE(contains(e.rule(), "finite")) << e.what();
}

TEST(GroundMotionRefused, At2HeaderThatDisagreesWithItsData) {
  std::string more = kAt2;
  more.replace(more.find("NPTS=    7"), 10, "NPTS=    6");
  InvalidInput e = refused(more, "x.AT2");
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_TRUE(contains(e.rule(), "more values than NPTS = 6")) << e.what();
  std::string fewer = kAt2;
  fewer.replace(fewer.find("NPTS=    7"), 10, "NPTS=    9");
  e = refused(fewer, "x.AT2");
  EXPECT_TRUE(contains(e.rule(), "has 7 values after its header, but NPTS = 9")) << e.what();
  // An absurd NPTS is refused before anything is allocated.
  std::string absurd = kAt2;
  absurd.replace(absurd.find("NPTS=    7"), 10, "NPTS=1e15 ");
  e = refused(absurd, "x.AT2");
  EXPECT_EQ(e.parameter(), "x.AT2:4 NPTS");
  EXPECT_TRUE(contains(e.rule(), "from 2 to 10^8")) << e.what();
  std::string no_dt = kAt2;
  no_dt.replace(no_dt.find("DT=   .0100"), 11, "DT=   -.010");
  EXPECT_EQ(refused(no_dt, "x.AT2").parameter(), "x.AT2:4 DT");
  std::string garbled = kAt2;
  garbled.replace(garbled.find("NPTS="), 5, "N PTS");
  EXPECT_EQ(refused(garbled, "x.AT2").parameter(), "x.AT2:4");
}

TEST(GroundMotionRefused, At2OfVelocitiesOrOtherUnits) {
  std::string velocity = kAt2;
  velocity.replace(velocity.find("ACCELERATION"), 12, "VELOCITY    ");
  GroundMotionReadOptions as_at2;
  as_at2.format = GroundMotionReadOptions::Format::peer_at2;
  EXPECT_EQ(refused(velocity, "x.VT2", as_at2).parameter(), "x.VT2:3");
  std::string cm = kAt2;
  cm.replace(cm.find("UNITS OF G"), 10, "UNITS OF CM/S/S");
  const InvalidInput e = refused(cm, "x.AT2");
  EXPECT_TRUE(contains(e.rule(), "states units 'CM/S/S'")) << e.what();
  GroundMotionReadOptions options;
  options.units = AccelUnits::cm_per_s2;
  EXPECT_EQ(refused(kAt2, "x.AT2", options).parameter(), "accel_units");
}

TEST(GroundMotionRefused, RecordDtWithTwoColumnsOrAt2) {
  GroundMotionReadOptions options;
  options.record_dt = 0.01;
  InvalidInput e = refused("0 1\n1 2\n", "rec.csv", options);
  EXPECT_EQ(e.parameter(), "record_dt");
  EXPECT_TRUE(contains(e.rule(), "has 2 columns")) << e.what();
  e = refused(kAt2, "x.AT2", options);
  EXPECT_EQ(e.parameter(), "record_dt");
  EXPECT_TRUE(contains(e.rule(), "states its step")) << e.what();
}

TEST(GroundMotionRefused, OneColumnWithoutStep) {
  const InvalidInput e = refused("0.1\n0.2\n0.3\n");
  EXPECT_TRUE(contains(e.rule(), "with the step given (--record-dt)")) << e.what();
}

TEST(GroundMotionRefused, ThreeColumnsWithoutNames) {
  const InvalidInput e = refused("0 1 2\n1 2 3\n");
  EXPECT_EQ(e.parameter(), "file");
  EXPECT_TRUE(contains(e.rule(), "has 3 columns")) << e.what();
}

TEST(GroundMotionRefused, BadOptions) {
  const auto option_refused = [](auto set) {
    GroundMotionReadOptions options;
    set(options);
    return expect_invalid([&] { options.validate(); });
  };
  EXPECT_EQ(option_refused([](auto& o) { o.record_dt = 0; }).parameter(), "record_dt");
  EXPECT_EQ(option_refused([](auto& o) { o.record_dt = NAN; }).parameter(), "record_dt");
  EXPECT_EQ(option_refused([](auto& o) { o.gravity = -9.8; }).parameter(), "gravity");
  EXPECT_EQ(option_refused([](auto& o) { o.scale = INFINITY; }).parameter(), "scale");
  EXPECT_EQ(option_refused([](auto& o) { o.scale = -1; }).parameter(), "scale");
  EXPECT_EQ(option_refused([](auto& o) { o.target_pga = 0; }).parameter(), "target_pga");
  EXPECT_EQ(option_refused([](auto& o) { o.target_pga = -0.3; }).parameter(), "target_pga");
  const InvalidInput both = option_refused([](auto& o) {
    o.scale = 2;
    o.target_pga = 0.3;
  });
  EXPECT_TRUE(contains(both.rule(), "choose one way of scaling")) << both.what();
  EXPECT_NO_THROW(GroundMotionReadOptions{}.validate());
}

TEST(GroundMotionRefused, TargetPgaOfASilentRecord) {
  GroundMotionReadOptions options;
  options.target_pga = 0.3;
  const InvalidInput e = refused("0 0\n1 0\n", "rec.csv", options);
  EXPECT_EQ(e.parameter(), "target_pga");
  EXPECT_TRUE(contains(e.rule(), "every acceleration in it is 0")) << e.what();
}

TEST(GroundMotionRefused, ScalingThatOverflows) {
  GroundMotionReadOptions options;
  options.scale = 1e300;
  EXPECT_EQ(refused("0 1e10\n1 0\n", "rec.csv", options).parameter(), "scale");
}

// Found by fuzz_ground_motion (CI, 1.6 M executions): a factor that
// underflows to 0 made every acceleration 0 without a word.
TEST(GroundMotionRefused, FactorOutOfRange) {
  GroundMotionReadOptions options;
  options.target_pga = 1e-300;
  options.gravity = 1e-30;  // x 1e-30 / 1 / 1.2: 0 in double
  InvalidInput e = refused("0 1.2\n1 0\n", "rec.csv", options);
  EXPECT_EQ(e.parameter(), "target_pga");
  EXPECT_TRUE(contains(e.rule(), "outside double's range")) << e.what();
  options = {};
  options.gravity = 5e-324;
  options.units = AccelUnits::cm_per_s2;  // 5e-324 / 980.665 = 0
  e = refused("0 1.2\n1 0\n", "rec.csv", options);
  EXPECT_EQ(e.parameter(), "gravity");
}

TEST(GroundMotionRefused, StepWhoseTimesOverflow) {
  std::string column;
  for (int i = 0; i < 4; ++i) column += "0.1\n";
  GroundMotionReadOptions options;
  options.record_dt = 5e-324;  // the smallest subnormal: i * dt is exact, the times increase
  EXPECT_NO_THROW(parse(column, "c.txt", options));
  options.record_dt = 1e308;  // 2 * dt overflows
  const InvalidInput e = refused(column, "c.txt", options);
  EXPECT_EQ(e.parameter(), "record_dt");
  EXPECT_TRUE(contains(e.rule(), "finite")) << e.what();
}

// The peak ground velocity, integrated by hand: v_g is the area under the
// piecewise-linear acceleration from rest at the first sample.
TEST(GroundMotionPeaks, PeakGroundVelocityAtTheEndsOrWhereTheAccelerationChangesSign) {
  GroundMotion r;
  // a = 3 -> -1 over [0, 1]: the sign changes at s = 3/4, where v = 3 * 3/4 / 2
  // = 9/8; at t = 1 the area is (3 - 1) / 2 = 1. The peak is inside.
  r.t = {0, 1};
  r.a = {3, -1};
  EXPECT_EQ(r.pgv(), 1.125);
  EXPECT_EQ(r.pga(), 3);
  // a = 2 -> -2 over [0, 1] (v = 1/2 at s = 1/2, 0 at 1), then -2 -> 0 over
  // [1, 3] (area -2): the peak |v| = 2 is at the last sample, and v stays
  // there after it (the acceleration is zero).
  r.t = {0, 1, 3};
  r.a = {2, -2, 0};
  EXPECT_EQ(r.pgv(), 2);
  // Samples of one sign: the largest |area so far|.
  r.t = {0, 0.5, 1.5};
  r.a = {-1, -1, 0};
  EXPECT_EQ(r.pgv(), 1);  // 0.5 + 0.5
  // Zero throughout.
  r.t = {0, 1};
  r.a = {0, 0};
  EXPECT_EQ(r.pgv(), 0);
}

// A sampled cos(w t) has the ground velocity sin(w t) / w: PGV -> 1 / w as
// the step shrinks (the trapezoidal areas are exact for the linear
// interpolant, which differs from the cosine by O(h^2)).
TEST(GroundMotionPeaks, PeakGroundVelocityOfASampledCosine) {
  const double w = 3;
  for (int per_period : {200, 2000}) {
    GroundMotion r;
    const double h = 2 * M_PI / w / per_period;
    for (int i = 0; i <= 3 * per_period; ++i) {
      r.t.push_back(i * h);
      r.a.push_back(std::cos(w * i * h));
    }
    EXPECT_NEAR(r.pgv(), 1 / w, (w * h) * (w * h) / w) << per_period;
  }
}

TEST(GroundMotionValidate, NamesTheSample) {
  GroundMotion r;
  r.t = {0, 1, 1};
  r.a = {0, 0, 0};
  EXPECT_EQ(expect_invalid([&] { r.validate(); }).parameter(), "t[2]");
  r.t = {0, 1};
  EXPECT_EQ(expect_invalid([&] { r.validate(); }).parameter(), "a");
}

}  // namespace
}  // namespace frictionref
