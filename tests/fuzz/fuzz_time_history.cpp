// libFuzzer target: the candidate-file reader of `compare`
// (frictionref::parse_time_history, time_history.hpp), and compare() itself
// on the histories it accepts.
//
// The contract under test: parse_time_history either throws
// frictionref::InvalidInput, or returns a TimeHistory that passes validate()
// and matches the options (x present iff a displacement column was asked
// for). compare() on an accepted history either throws InvalidInput or
// returns a report that is consistent (verdict from the checks and the
// resolution, a diagnosis that agrees with the verdict, no NaN measurement,
// the history's rows and times). Any other exception, a
// sanitizer report or a hang is a finding.
//
// Input layout:
//   byte 0   time column spec:         index into kColumnSpecs
//   byte 1   velocity column spec:     index into kColumnSpecs
//   byte 2   displacement column spec: index into kColumnSpecs ("" = none)
//   byte 3   bits 0-1 the model compare() uses (compare_model); bit 2 skip compare();
//            bit 3 decimal_comma; bit 4 on_overlap = keep_last; bits 5-7 skip_rows (0-7)
//   rest     the file's bytes
// Column specs cover the three ways to choose a column: the default (""),
// by name (as in the header, case and units varied), and by number (valid,
// zero, out of range, too long), plus invalid specs (blank).
//
// While finding F2 (docs/reliability.md) is open, FRICTIONREF_FUZZ_ALLOW=
// numerical_failure (as for fuzz_engine) accepts the std::runtime_error
// compare() throws when its exact engine ends in numerical_failure; unset
// (the default, and CI), that is a finding.
//
// compare() runs only on histories of at most kMaxCompareRows rows with
// times in [-kMaxCompareTime, kMaxCompareTime], so its exact engine stays
// short (w = 1: at most ~16 forcing periods).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "frictionref/frictionref.hpp"
#include "fuzz_check.hpp"

namespace {

using frictionref::InvalidInput;
using frictionref::TimeHistory;
using frictionref::TimeHistoryReadOptions;

constexpr std::size_t kMaxCompareRows = 2000;
constexpr double kMaxCompareTime = 100;

const char* const kColumnSpecs[] = {
    "",  // default
    "t",   "time",     "TIME",    " Time ", "time [s]",  "t (s)",      "v",
    "vel", "Velocity", "v (m/s)", "x",      "disp",      "phase",      "\"t\"",
    "1",   "2",        "3",       "4",      "5",         "01",         "10",
    "0",   "00",       " ",       "\t",     "123456789", "1234567890", "18446744073709551617",
    "-1",  "+2",       "t,v",     "#",      "",
    "",  // extra defaults: more weight on the common case
};
constexpr std::size_t kSpecCount = sizeof kColumnSpecs / sizeof kColumnSpecs[0];

bool allow_numerical_failure() {
  static const bool value = [] {
    const char* list = std::getenv("FRICTIONREF_FUZZ_ALLOW");
    const bool allow = list && std::string(list).find("numerical_failure") != std::string::npos;
    if (allow)
      std::fprintf(stderr, "fuzz_time_history: tolerating numerical_failure in compare()\n");
    return allow;
  }();
  return value;
}

[[noreturn]] void fail(const char* what, int line, const std::string& detail = "") {
  std::fprintf(stderr, "\nfuzz_time_history: invariant violated (fuzz_time_history.cpp:%d): %s\n",
               line, what);
  if (!detail.empty()) std::fprintf(stderr, "  %s\n", detail.c_str());
  std::fflush(stderr);
  std::abort();
}

frictionref::Model compare_model(int which) {
  frictionref::Model model;  // m = B = w = 1, the seed's cases
  switch (which) {
    case 0:
      model.friction = 0.3;  // continuous
      break;
    case 1:
      model.friction = 0.7;  // dead bands
      break;
    case 2:
      model.friction = 1.01;  // stops
      model.v0 = -1;
      break;
    default:
      model.friction = 0.55;  // dead bands near the threshold, t0 != 0
      model.t0 = 1;
      break;
  }
  return model;
}

void check_report(const TimeHistory& history, const frictionref::ComparisonReport& report) {
  FUZZ_CHECK(report.rows == history.rows());
  FUZZ_CHECK(report.t_first == history.t.front() && report.t_last == history.t.back());
  FUZZ_CHECK(report.has_displacement == history.x.has_value());
  FUZZ_CHECK(!report.checks.empty());
  bool all_passed = true;
  for (const frictionref::Check& check : report.checks) {
    FUZZ_CHECK_AT(!std::isnan(check.value), std::string(check.name()) + ": " + check.message);
    FUZZ_CHECK_AT(!std::isnan(check.tolerance), std::string(check.name()));
    FUZZ_CHECK_AT(!check.message.empty(), std::string(check.name()));
    all_passed = all_passed && check.passed;
  }
  // FAIL iff a check failed; otherwise INCONCLUSIVE iff the samples leave
  // something unresolved.
  const std::size_t unresolved = report.unresolved_phases + report.unresolved_events;
  FUZZ_CHECK((report.verdict == frictionref::Verdict::fail) == !all_passed);
  FUZZ_CHECK(report.verdict != frictionref::Verdict::inconclusive ||
             (all_passed && unresolved > 0));
  FUZZ_CHECK(report.verdict != frictionref::Verdict::pass || unresolved == 0);
  FUZZ_CHECK(report.unresolved.size() == std::min<std::size_t>(unresolved, 100));
  FUZZ_CHECK((unresolved > 0 && report.stop_time_margin > 0) == (report.resolving_step > 0));
  double previous = report.t_first;
  for (const frictionref::UnresolvedPart& part : report.unresolved) {
    FUZZ_CHECK(part.start >= previous && part.start <= part.end && part.start < report.t_last);
    FUZZ_CHECK(part.kind == frictionref::UnresolvedPart::Kind::phase ||
               part.spacing > report.stop_time_margin);
    previous = part.start;
  }
  FUZZ_CHECK(report.failed_checks().empty() == all_passed);
  // The diagnosis names nothing on PASS, the resolution on INCONCLUSIVE, a
  // defect on FAIL; with a finite value and words, first in both reports.
  using frictionref::Defect;
  const Defect defect = report.diagnosis.defect;
  FUZZ_CHECK((report.verdict == frictionref::Verdict::pass) == (defect == Defect::none));
  FUZZ_CHECK((report.verdict == frictionref::Verdict::inconclusive) ==
             (defect == Defect::unresolved));
  FUZZ_CHECK_AT(std::isfinite(report.diagnosis.value), report.diagnosis.text());
  FUZZ_CHECK(!report.diagnosis.evidence.empty());
  FUZZ_CHECK(report.brief_report().rfind("diagnosis: " + report.diagnosis.text() + "\n", 0) == 0);
  FUZZ_CHECK(!std::isnan(report.velocity_max_error) && !std::isnan(report.velocity_rms_error));
  FUZZ_CHECK(!std::isnan(report.displacement_max_error));
  for (const frictionref::StickInterval& stick : report.candidate_sticks) {
    FUZZ_CHECK(stick.first_row <= stick.last_row && stick.last_row < history.rows());
    FUZZ_CHECK(!std::isnan(stick.start) && !std::isnan(stick.end));
  }
  FUZZ_CHECK(!report.brief_report().empty());
  FUZZ_CHECK(!report.full_report().empty());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  allow_numerical_failure();  // reads FRICTIONREF_FUZZ_ALLOW once
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  TimeHistoryReadOptions options;
  options.time_column = kColumnSpecs[data[0] % kSpecCount];
  options.velocity_column = kColumnSpecs[data[1] % kSpecCount];
  options.displacement_column = kColumnSpecs[data[2] % kSpecCount];
  const int model_choice = data[3] & 3;
  const bool run_compare = (data[3] & 4) == 0;
  options.decimal_comma = (data[3] & 8) != 0;
  if ((data[3] & 16) != 0) options.on_overlap = TimeHistoryReadOptions::OnOverlap::keep_last;
  options.skip_rows = data[3] >> 5;

  std::istringstream file(std::string(reinterpret_cast<const char*>(data) + 4, size - 4));
  TimeHistory history;
  try {
    history = frictionref::parse_time_history(file, "fuzz.csv", options);
  } catch (const InvalidInput& error) {
    FUZZ_CHECK(error.what() != nullptr && *error.what() != '\0');
    FUZZ_CHECK(!error.parameter().empty() && !error.rule().empty());
    return 0;  // a clear error naming the file, line or option: fine
  }

  // Accepted: a valid history, shaped as the options asked.
  try {
    history.validate();
  } catch (const InvalidInput& error) {
    fail("an accepted history fails validate()", __LINE__, error.what());
  }
  FUZZ_CHECK(history.t.size() == history.v.size() && history.rows() >= 2);
  FUZZ_CHECK(history.x.has_value() == !options.displacement_column.empty());
  FUZZ_CHECK(!history.source.empty());

  if (!run_compare || history.rows() > kMaxCompareRows) return 0;
  if (!(history.t.front() >= -kMaxCompareTime && history.t.back() <= kMaxCompareTime)) return 0;
  const frictionref::Model model = compare_model(model_choice);
  frictionref::ComparisonReport report;
  try {
    report = frictionref::compare(model, history);
  } catch (const InvalidInput&) {
    FUZZ_CHECK(history.t.front() < model.t0);  // the only InvalidInput left for a valid history
    return 0;
  } catch (const std::runtime_error& error) {
    if (allow_numerical_failure() && std::string(error.what()).rfind("exact engine:", 0) == 0)
      return 0;
    throw;
  }
  check_report(history, report);
  return 0;
}
