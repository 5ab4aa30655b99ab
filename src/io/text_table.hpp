// A tolerant reader of numeric tables in text files: the layer shared by the
// readers of another code's time history (time_history.hpp) and of a ground
// motion record (ground_motion.hpp), so both accept the same files.
//
// One pass over the lines, never holding the file: comments and blank lines
// are skipped; the table's first row is the first content line with at least
// `min_columns` numbers, which fixes the separator and the number of columns;
// if the line before it splits into as many fields, none a number, it is the
// header, and the content lines before it are title lines, skipped with a
// note. Otherwise (no header, or no such row among the first 64 content
// lines) the first content line starts the table. Every later content line is
// a row with exactly that many fields. Every error is an InvalidInput naming
// the file, line and column, the offending text and the rule.
#pragma once

#include <cstddef>
#include <deque>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/text_fields.hpp"

namespace frictionref::io {

// What the table is, for its rules and messages.
struct TableShape {
  std::size_t min_columns = 2;  // 1 or 2
  // "a time history": "has 1 column; a time history needs at least 2 (time
  // and velocity)"; "contains no numbers (a time history needs rows of
  // numbers: time, velocity, ...)".
  std::string what = "a time history";
  std::string columns_needed = "2 (time and velocity)";
  std::string numbers_needed = "rows of numbers: time, velocity, ...";
  bool decimal_comma = false;  // as TimeHistoryReadOptions::decimal_comma
  std::size_t skip_rows = 0;   // as TimeHistoryReadOptions::skip_rows
};

class TextTableReader {
 public:
  TextTableReader(std::istream& in, std::string name, TableShape shape);

  // Skips skip_rows lines, finds the header and the first row (skipping
  // title lines with a note). Throws InvalidInput "file" for an unreadable
  // or empty file or one with only comments, and "<name>:<line>" for a first
  // row with too few columns.
  void open();

  // The next data row, false after the last (the first call gives the first
  // row). Throws for a row whose number of fields differs from the first's.
  bool next_row();
  const std::vector<std::string>& fields() const { return fields_; }
  std::size_t line() const { return line_number_; }
  // The value in `column` of the current row; throws "must be a number" or
  // "must be a finite number" naming the line and column.
  double number(std::size_t column) const;

  // The column that `spec` names: a header name (case-insensitive, units
  // removed, see header_key) or a 1-based number; "" = the first header name
  // among `names` (a null-terminated list), or column `default_number` when
  // there is no header. `field` names the option in messages.
  std::size_t resolve(const std::string& spec, const char* field, const char* const* names,
                      std::size_t default_number, const char* default_text) const;

  // The first header name among `names` (null-terminated), if there is a
  // header and it has one.
  std::optional<std::size_t> find_column(const char* const* names) const;

  std::size_t columns() const { return columns_; }
  bool has_header() const { return header_.has_value(); }
  std::size_t first_line() const { return first_line_; }  // header or first row
  std::string column_label(std::size_t index) const;      // "column 2 (v)"
  std::string location(std::size_t line) const { return name_ + ":" + std::to_string(line); }
  std::string location(std::size_t line, std::size_t column) const {
    return location(line) + " " + column_label(column);
  }
  const std::string& name() const { return name_; }
  Separator separator() const { return separator_; }
  // Throws "cannot be read (input error)" if the stream failed.
  void check_stream() const;

  std::vector<std::string>& notes() { return notes_; }

 private:
  bool next_line(std::string_view& content);
  void find_table();
  std::string header_names() const;
  void require_some_number(const std::vector<std::string>& first_row);

  std::istream& in_;
  std::string name_;
  TableShape shape_;
  std::string raw_;
  std::size_t line_number_ = 0;  // of the current line
  std::size_t stream_line_ = 0;  // lines taken from the stream
  bool any_text_ = false;        // a non-blank byte was seen
  Separator separator_ = Separator::comma;
  std::size_t columns_ = 0;
  std::size_t first_line_ = 0;
  std::optional<std::vector<std::string>> header_;
  bool decimal_comma_ = false;
  struct Held {
    std::string content;
    std::size_t line;
  };
  std::deque<Held> held_;  // content lines read ahead, to be read again
  std::vector<std::string> fields_;
  std::string_view content_;  // the current row's text (into raw_)
  bool row_ready_ = false;    // fields_ holds the first row, not yet returned
  std::vector<std::string> notes_;
};

}  // namespace frictionref::io
