// libFuzzer target: the ground-motion record reader
// (frictionref::parse_ground_motion, ground_motion.hpp) on arbitrary bytes
// and options.
//
// The contract under test: parse_ground_motion either throws
// frictionref::InvalidInput with a parameter and a rule, or returns a record
// that passes validate() and agrees with itself and the options:
//   - t and a have npts >= 2 finite values, t increasing;
//   - a file with a step (AT2, one column) has t[i] == i * dt exactly;
//   - the SHA-256 is that of the bytes; the factor is finite and non-zero,
//     negative exactly when the polarity is inverse; every a is the factor
//     times a value of magnitude at most pga_as_read;
//   - the format is one of the three, and an AT2 has its four header lines.
// Any other exception, a sanitizer report or a hang is a finding.
//
// Input layout:
//   byte 0   bits 0-1 format (automatic, peer_at2, table, automatic);
//            bit 2 record_dt given; bit 3 units given; bit 4 inverse;
//            bits 5-6 scaling (none, scale, target PGA, both)
//   byte 1   bits 0-2 units; bits 3-5 file name; bits 6-7 gravity
//   byte 2   record_dt, index into kSteps
//   byte 3   scale / target PGA, index into kFactors
//   rest     the file's bytes
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "frictionref/frictionref.hpp"
#include "fuzz_check.hpp"

namespace {

using frictionref::AccelUnits;
using frictionref::GroundMotion;
using frictionref::GroundMotionReadOptions;
using frictionref::InvalidInput;

const double kSteps[] = {0.01, 0.005, 0.02, 1e-3,     5e-324, 1e-310, 1e308, 1e300,
                         0,    -0.01, NAN,  INFINITY, 0.1,    1,      3.5,   2e-9};
const double kFactors[] = {1,        2,   0.5,    1e300, 1e-300, 0,    -1,  NAN,
                           INFINITY, 0.3, 1e-320, 7,     1e10,   0.01, 1.5, 1e308};
const char* const kNames[] = {"rec.csv", "x.AT2", "x.at2", "PET-000",
                              "rec.txt", "a.VT2", "AT2",   ".AT2"};
const double kGravity[] = {9.80665, 980.665, 32.174048556430446, 1};

template <class T, std::size_t N>
constexpr std::size_t count(const T (&)[N]) {
  return N;
}

[[noreturn]] void fail(const char* what, int line, const std::string& detail = "") {
  std::fprintf(stderr, "\nfuzz_ground_motion: invariant violated (fuzz_ground_motion.cpp:%d): %s\n",
               line, what);
  if (!detail.empty()) std::fprintf(stderr, "  %s\n", detail.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  GroundMotionReadOptions options;
  const int format = data[0] & 3;
  options.format = format == 1   ? GroundMotionReadOptions::Format::peer_at2
                   : format == 2 ? GroundMotionReadOptions::Format::table
                                 : GroundMotionReadOptions::Format::automatic;
  if (data[0] & 4) options.record_dt = kSteps[data[2] % count(kSteps)];
  if (data[0] & 8) options.units = static_cast<AccelUnits>((data[1] & 7) % 5);
  options.inverse = (data[0] & 16) != 0;
  const int scaling = (data[0] >> 5) & 3;
  const double factor = kFactors[data[3] % count(kFactors)];
  if (scaling & 1) options.scale = factor;
  if (scaling & 2) options.target_pga = factor;
  const std::string name = kNames[(data[1] >> 3) & 7];
  options.gravity = kGravity[data[1] >> 6];

  const std::string bytes(reinterpret_cast<const char*>(data) + 4, size - 4);
  GroundMotion record;
  try {
    record = frictionref::parse_ground_motion(bytes, name, options);
  } catch (const InvalidInput& error) {
    FUZZ_CHECK(error.what() != nullptr && *error.what() != '\0');
    FUZZ_CHECK(!error.parameter().empty() && !error.rule().empty());
    return 0;  // a clear error naming the file, line or option: fine
  }

  try {
    record.validate();
  } catch (const InvalidInput& error) {
    fail("an accepted record fails validate()", __LINE__, error.what());
  }
  FUZZ_CHECK(record.npts == record.t.size() && record.a.size() == record.t.size());
  FUZZ_CHECK(record.npts >= 2);
  FUZZ_CHECK(record.sha256 == frictionref::sha256_hex(bytes));
  FUZZ_CHECK(record.file == name);
  FUZZ_CHECK(std::isfinite(record.factor) && record.factor != 0);
  FUZZ_CHECK((record.factor < 0) == options.inverse);
  FUZZ_CHECK(std::isfinite(record.pga_as_read) && record.pga_as_read >= 0);
  for (double a : record.a)
    FUZZ_CHECK_AT(std::fabs(a) <= std::fabs(record.factor) * record.pga_as_read,
                  "a = " + std::to_string(a));
  FUZZ_CHECK(record.format == "PEER NGA AT2" || record.format == "time-acceleration table" ||
             record.format == "one column");
  if (record.format == "PEER NGA AT2") FUZZ_CHECK(record.header.size() == 4);
  if (record.format == "one column") FUZZ_CHECK(options.record_dt.has_value());
  if (record.format == "time-acceleration table") FUZZ_CHECK(!record.dt.has_value());
  if (record.dt)
    for (std::size_t i = 0; i < record.npts; ++i)
      FUZZ_CHECK_AT(record.t[i] == static_cast<double>(i) * *record.dt, "i = " + std::to_string(i));
  return 0;
}
