// Another code's time history (t, v and optionally x), read from a text file,
// to be checked against the exact solution (comparison.hpp).
//
// Accepted files: comma-, semicolon- or white-space-separated columns (the
// first content line decides), with or without one header line, '#' comments
// (whole lines or the end of a line), blank lines, Windows (CRLF) line ends, a
// UTF-8 byte-order mark, double-quoted fields ("time [s]"), and numbers in any
// form strtod reads (1e-3, 1.5E+02, 0x1p-3) or with a Fortran exponent
// (1.5D+02). Columns that are not used may hold text (e.g. our own curve's
// `phase` column). Every error is an InvalidInput naming the file, line and
// column, the offending text and the rule (docs/cross-checking.md).
#pragma once

#include <cstddef>
#include <fstream>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace frictionref {

// One record: the candidate's own times and values, in the model's units.
struct TimeHistory {
  std::vector<double> t;                 // times [time]; finite, non-decreasing
  std::vector<double> v;                 // velocity at each time [length/time]; finite
  std::optional<std::vector<double>> x;  // position at each time [length], if one was read
  std::string source;  // where it came from, for reports: file, columns used, rows, lines
  std::vector<std::string> notes;  // what the reader did that a reader of the report should
                                   // know: title lines skipped, restarts resolved

  std::size_t rows() const { return t.size(); }

  // Throws InvalidInput naming the field ("t[7]", "v", ...), the value and the
  // rule: equal lengths, at least 2 rows, finite values, t non-decreasing,
  // t.back() > t.front().
  void validate() const;
};

// Which columns hold what, and how the file is spelled. A column is named by
// its header text (compared case-insensitively, quotes and surrounding blanks
// removed; "time [s]" or "v (m/s)" also answer to "time" and "v", and a unit
// suffix after '_' or '-' too: "time_s", "v_mps", "x-m") or by its 1-based
// number; text made only of digits is always a number.
struct TimeHistoryReadOptions {
  std::string time_column;          // "" = the header's t or time, else column 1
  std::string velocity_column;      // "" = the header's v, vel or velocity, else column 2
  std::string displacement_column;  // "" = none read; else a name or number as above

  // Numbers with a decimal comma ("1,5"). Always so when the columns are
  // separated by ';' (the spreadsheet export of comma-decimal locales);
  // with this set also between blanks (then ',' never separates columns).
  bool decimal_comma = false;

  // Lines to skip before the table (header or first row), on top of the
  // comments and blank lines. Without it, text lines before the header (a
  // title without '#') are skipped anyway when the table's shape shows them:
  // see read_time_history.
  std::size_t skip_rows = 0;

  // When time goes back (a restart from a checkpoint writes the overlap
  // again): error (the default: a clear message naming keep-last), or
  // keep_last: the later segment counts, earlier rows at or after its first
  // time are dropped, and a note says so.
  enum class OnOverlap { error, keep_last };
  OnOverlap on_overlap = OnOverlap::error;

  // Throws InvalidInput naming the field (e.g. "time_column") if a number is 0
  // or the text is only blanks.
  void validate() const;
};

// Reads `path` ("-" reads standard input). The table's first row is the
// first line with at least two numbers; when the line before it has as many
// fields and no number, it is the header, and content lines before the
// header are title lines, skipped with a note. Throws InvalidInput: parameter
// "file" for a file that cannot be read, is empty or has no data rows;
// "<path>:<line>" or "<path>:<line> column <n> (<name>)" for a bad line or
// value; "time_column" / "velocity_column" / "displacement_column" for a
// column that does not exist.
TimeHistory read_time_history(const std::string& path, const TimeHistoryReadOptions& options = {});

// Opens the file `path` for read_time_history (and for readers that keep the
// bytes, as `report` does): throws InvalidInput, parameter "file", for an
// empty name, a directory, or a file the system will not open (its reason).
// "-" is not handled here: the caller reads standard input.
std::ifstream open_time_history_file(const std::string& path);

// The same from a stream; `name` stands for the file in messages and in
// TimeHistory::source.
TimeHistory parse_time_history(std::istream& in, const std::string& name,
                               const TimeHistoryReadOptions& options = {});

}  // namespace frictionref
