// Reading another code's time history (time_history.hpp).
//
// One pass over the lines, never holding the file: comments and blank lines
// are skipped; the table's first row is the first content line with two
// numbers or more, which fixes the separator and the number of columns; if
// the line before it splits into as many fields, none a number, it is the
// header, and the content lines before it are title lines, skipped with a
// note. Otherwise (no header, or no such row among the first
// kMaxLeadingLines) the first content line starts the table, as it always
// did. Every later content line is a row with exactly that many fields.
#include "frictionref/time_history.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"

namespace frictionref {
namespace {

std::string text(double value) { return detail::shortest_text(value); }

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The line without a '#' comment (a '#' inside double quotes is text).
std::string_view strip_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == '#' && !quoted) return line.substr(0, i);
  }
  return line;
}

enum class Separator { comma, semicolon, blanks };

const char* separator_name(Separator separator) {
  switch (separator) {
    case Separator::comma:
      return "commas";
    case Separator::semicolon:
      return "semicolons";
    case Separator::blanks:
      return "spaces or tabs";
  }
  return "";
}

// One field starting at `i`: a double-quoted field ("" is a quote inside it)
// or plain text up to the separator. Leaves `i` at the separator or the end.
std::string read_field(std::string_view line, std::size_t& i, Separator separator) {
  const auto at_end = [&](char c) {
    return separator == Separator::blanks ? is_blank(c)
                                          : c == (separator == Separator::comma ? ',' : ';');
  };
  std::string field;
  if (i < line.size() && line[i] == '"') {
    ++i;
    while (i < line.size()) {
      if (line[i] == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          field += '"';
          i += 2;
          continue;
        }
        ++i;
        break;
      }
      field += line[i++];
    }
  }
  const std::size_t rest = i;
  while (i < line.size() && !at_end(line[i])) ++i;
  field += line.substr(rest, i - rest);
  return std::string(trim(field));
}

void split(std::string_view line, Separator separator, std::vector<std::string>& fields) {
  fields.clear();
  std::size_t i = 0;
  if (separator == Separator::blanks) {
    while (true) {
      while (i < line.size() && is_blank(line[i])) ++i;
      if (i == line.size()) return;
      fields.push_back(read_field(line, i, separator));
    }
  }
  while (true) {
    while (i < line.size() && is_blank(line[i])) ++i;
    fields.push_back(read_field(line, i, separator));
    if (i == line.size()) return;
    ++i;  // the separator
  }
}

// Content lines held while looking for the table's first row.
constexpr std::size_t kMaxLeadingLines = 64;

// The whole field as a double (strtod, or a Fortran 'D' exponent); with
// `decimal_comma` one ',' is the decimal point ("1,5").
bool to_number(const std::string& field, double& value, bool decimal_comma = false) {
  if (field.empty()) return false;
  if (decimal_comma && field.find(',') != std::string::npos) {
    if (field.find('.') != std::string::npos || field.find(',') != field.rfind(',')) return false;
    std::string point = field;
    point[point.find(',')] = '.';
    return to_number(point, value, false);
  }
  char* end = nullptr;
  value = std::strtod(field.c_str(), &end);
  if (end == field.c_str() + field.size()) return true;
  const std::size_t d = field.find_first_of("dD");
  if (d == std::string::npos || d == 0 || field.find_first_of("dD", d + 1) != std::string::npos)
    return false;
  std::string fortran = field;
  fortran[d] = 'e';
  value = std::strtod(fortran.c_str(), &end);
  return end == fortran.c_str() + fortran.size() &&
         std::isdigit(static_cast<unsigned char>(field[d - 1])) != 0;
}

std::size_t count_numbers(const std::vector<std::string>& fields, bool decimal_comma) {
  double ignored = 0;
  std::size_t count = 0;
  for (const std::string& field : fields)
    if (to_number(field, ignored, decimal_comma)) ++count;
  return count;
}

bool any_number(const std::vector<std::string>& fields, bool decimal_comma = false) {
  return count_numbers(fields, decimal_comma) > 0;
}

// The separator of a content line: ';' if there is one (then numbers may
// have a decimal comma), else ',' unless commas are decimal points, else blanks.
Separator separator_of(std::string_view line, bool decimal_comma) {
  if (line.find(';') != std::string_view::npos) return Separator::semicolon;
  if (!decimal_comma && line.find(',') != std::string_view::npos) return Separator::comma;
  return Separator::blanks;
}

// A header name as compared: lower case; and without a trailing unit in
// brackets or parentheses ("time [s]" -> "time").
std::string without_unit(const std::string& name) {
  std::string base = name;
  const std::size_t open = base.find_first_of("[(");
  if (open != std::string::npos && open > 0) base = std::string(trim(base.substr(0, open)));
  return base;
}

// ... and without a unit suffix after '_' or '-' ("time_s" -> "time",
// "v_mps" -> "v", "x-m" -> "x").
std::string without_suffix(const std::string& name) {
  const std::string base = without_unit(name);
  const std::size_t cut = base.find_first_of("_-");
  if (cut == std::string::npos || cut == 0) return base;
  return std::string(trim(base.substr(0, cut)));
}

// The three ways a header name answers to a wanted name, strictest first.
std::string header_key(const std::string& name, int level) {
  if (level == 0) return lower(name);
  if (level == 1) return lower(without_unit(name));
  return lower(without_suffix(name));
}

bool only_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Long lines are shortened in messages.
std::string snippet(std::string_view line) {
  line = trim(line);
  if (line.size() <= 60) return std::string(line);
  return std::string(line.substr(0, 57)) + "...";
}

class Reader {
 public:
  Reader(std::istream& in, std::string name, const TimeHistoryReadOptions& options)
      : in_(in), name_(std::move(name)), options_(options) {}

  TimeHistory read();

 private:
  // The next content line (comments and blanks removed), false at the end;
  // held lines first.
  bool next_line(std::string_view& content);
  // Skips skip_rows lines, then finds the table's first row and header
  // (skipping title lines with a note); leaves the first row next to read.
  void find_table();
  std::size_t resolve(const std::string& spec, const char* field, const char* const* names,
                      std::size_t default_number, const char* default_text) const;
  std::string column_label(std::size_t index) const;
  std::string location(std::size_t line) const { return name_ + ":" + std::to_string(line); }
  std::string location(std::size_t line, std::size_t column) const {
    return location(line) + " " + column_label(column);
  }
  std::string header_names() const;
  // Throws "contains no numbers" unless the first row or a later line has one.
  void require_some_number(const std::vector<std::string>& first_row);

  std::istream& in_;
  std::string name_;
  TimeHistoryReadOptions options_;
  std::string raw_;
  std::size_t line_number_ = 0;  // of the current line
  std::size_t stream_line_ = 0;  // lines taken from the stream
  bool any_text_ = false;        // a non-blank byte was seen
  Separator separator_ = Separator::comma;
  std::size_t columns_ = 0;
  std::size_t first_line_ = 0;  // line of the first content line
  std::optional<std::vector<std::string>> header_;
  bool decimal_comma_ = false;
  struct Held {
    std::string content;
    std::size_t line;
  };
  std::deque<Held> held_;  // content lines read ahead, to be read again
  std::vector<std::string> notes_;
};

bool Reader::next_line(std::string_view& content) {
  if (!held_.empty()) {
    raw_ = std::move(held_.front().content);
    line_number_ = held_.front().line;
    held_.pop_front();
    content = raw_;
    return true;
  }
  while (std::getline(in_, raw_)) {
    line_number_ = ++stream_line_;
    std::string_view line = raw_;
    if (stream_line_ == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    if (!trim(line).empty()) any_text_ = true;
    content = trim(strip_comment(line));
    if (!content.empty()) return true;
  }
  return false;
}

std::string lines_text(std::size_t first, std::size_t last) {
  return first == last ? "line " + std::to_string(first)
                       : "lines " + std::to_string(first) + "-" + std::to_string(last);
}

void Reader::find_table() {
  std::string_view content;
  std::size_t first_skipped = 0;
  for (std::size_t i = 0; i < options_.skip_rows; ++i) {
    if (!next_line(content))
      throw InvalidInput("skip_rows", std::to_string(options_.skip_rows),
                         name_ + " has only " + std::to_string(i) +
                             " lines that are not comments or blank; nothing is left to read");
    if (i == 0) first_skipped = line_number_;
  }
  if (options_.skip_rows > 0)
    notes_.push_back("skipped " + std::to_string(options_.skip_rows) + " line" +
                     (options_.skip_rows > 1 ? "s" : "") + " before the table as asked (" +
                     lines_text(first_skipped, line_number_) + ")");
  // Read ahead to the first line with two numbers: the table's first row.
  std::vector<Held> ahead;
  std::vector<std::string> fields, header;
  while (ahead.size() < kMaxLeadingLines && next_line(content)) {
    ahead.push_back({std::string(content), line_number_});
    const Separator separator = separator_of(content, options_.decimal_comma);
    const bool decimal = options_.decimal_comma || separator == Separator::semicolon;
    split(content, separator, fields);
    if (fields.size() < 2 || count_numbers(fields, decimal) < 2) continue;
    // Lines before the header are title lines; without a header nothing is
    // skipped (a line before the first row is then a bad row, and says so).
    std::size_t start = ahead.size() - 1;
    if (start > 0) {
      split(ahead[start - 1].content, separator, header);
      if (header.size() == fields.size() && !any_number(header, decimal))
        --start;
      else
        start = 0;
    }
    if (start > 0)
      notes_.push_back("skipped " + std::to_string(start) + " title line" + (start > 1 ? "s" : "") +
                       " before the table (" +
                       lines_text(ahead.front().line, ahead[start - 1].line) + ": '" +
                       snippet(ahead.front().content) + "'" + (start > 1 ? ", ..." : "") + ")");
    held_.assign(ahead.begin() + static_cast<std::ptrdiff_t>(start), ahead.end());
    return;
  }
  // No row with two numbers within reach: the first content line starts the
  // table, as it always did, and its errors say what is wrong.
  held_.assign(ahead.begin(), ahead.end());
}

std::string Reader::column_label(std::size_t index) const {
  std::string label = "column " + std::to_string(index + 1);
  if (header_ && !(*header_)[index].empty()) label += " (" + (*header_)[index] + ")";
  return label;
}

std::string Reader::header_names() const {
  std::string names;
  for (std::size_t i = 0; i < header_->size(); ++i) {
    if (i == 12) return names + ", ...";
    names += (i ? ", " : "") + (*header_)[i];
  }
  return names;
}

std::size_t Reader::resolve(const std::string& spec, const char* field, const char* const* names,
                            std::size_t default_number, const char* default_text) const {
  const std::string where =
      header_ ? "the header of " + name_ + " (line " + std::to_string(first_line_) + ")" : name_;
  if (spec.empty()) {
    if (!header_) return default_number - 1;
    for (int level = 0; level < 3; ++level)
      for (const char* const* name = names; *name; ++name)
        for (std::size_t i = 0; i < columns_; ++i)
          if (header_key((*header_)[i], level) == *name) return i;
    throw InvalidInput(field, std::string("(default: ") + default_text + ")",
                       where + " has no such column (its columns: " + header_names() +
                           "); name the column or give its number");
  }
  if (only_digits(spec)) {
    const std::size_t number = spec.size() > 9 ? 0 : std::stoul(spec);
    if (number < 1 || number > columns_)
      throw InvalidInput(field, spec,
                         "must be a column number from 1 to " + std::to_string(columns_) + " (" +
                             name_ + " has " + std::to_string(columns_) + " columns)");
    return number - 1;
  }
  if (!header_)
    throw InvalidInput(field, spec,
                       name_ + " has no header line to find a column name in (line " +
                           std::to_string(first_line_) + " is numbers); give the column's number");
  const std::string wanted = lower(trim(spec));
  std::vector<std::size_t> found;
  for (int level = 0; level < 3 && found.empty(); ++level)
    for (std::size_t i = 0; i < columns_; ++i)
      if (header_key((*header_)[i], level) == wanted) found.push_back(i);
  if (found.empty())
    throw InvalidInput(field, spec,
                       "no such column in " + where + " (its columns: " + header_names() + ")");
  if (found.size() > 1)
    throw InvalidInput(field, spec,
                       "names columns " + std::to_string(found[0] + 1) + " and " +
                           std::to_string(found[1] + 1) + " of " + where +
                           "; give the column's number");
  return found.front();
}

void Reader::require_some_number(const std::vector<std::string>& first_row) {
  if (any_number(first_row, decimal_comma_)) return;
  // Neither the header nor the first row has a number: is there any at all?
  // (Reads on with its own buffer: the first row stays as it is.)
  std::string line;
  std::vector<std::string> fields;
  for (const Held& held : held_) {
    split(held.content, separator_, fields);
    if (any_number(fields, decimal_comma_)) return;
  }
  while (std::getline(in_, line)) {
    split(trim(strip_comment(line)), separator_, fields);
    if (any_number(fields, decimal_comma_)) return;
  }
  throw InvalidInput("file", name_,
                     "contains no numbers (a time history needs rows of numbers: time, "
                     "velocity, ...)");
}

TimeHistory Reader::read() {
  find_table();
  std::string_view content;
  if (!next_line(content)) {
    if (in_.bad()) throw InvalidInput("file", name_, "cannot be read (input error)");
    throw InvalidInput("file", name_,
                       any_text_ ? "has no data rows (only comments and blank lines)" : "is empty");
  }
  first_line_ = line_number_;
  separator_ = separator_of(content, options_.decimal_comma);
  decimal_comma_ = options_.decimal_comma || separator_ == Separator::semicolon;
  std::vector<std::string> fields;
  split(content, separator_, fields);
  columns_ = fields.size();
  if (columns_ < 2)
    throw InvalidInput(location(line_number_), snippet(content),
                       "has 1 column; a time history needs at least 2 (time and velocity), "
                       "separated by commas, semicolons, spaces or tabs");
  const bool first_is_header = !any_number(fields, decimal_comma_);
  bool have_row = true;
  if (first_is_header) {
    header_ = fields;
    have_row = next_line(content);
    if (have_row) {
      split(content, separator_, fields);
      require_some_number(fields);
    }
  }

  static const char* const time_names[] = {"t", "time", nullptr};
  static const char* const velocity_names[] = {"v", "vel", "velocity", nullptr};
  const std::size_t time = resolve(options_.time_column, "time_column", time_names, 1, "t or time");
  const std::size_t velocity =
      resolve(options_.velocity_column, "velocity_column", velocity_names, 2, "v, vel or velocity");
  if (velocity == time)
    throw InvalidInput("velocity_column",
                       options_.velocity_column.empty() ? "(default)" : options_.velocity_column,
                       "is the time column (" + column_label(time) + "); choose another");
  std::optional<std::size_t> displacement;
  if (!options_.displacement_column.empty()) {
    displacement = resolve(options_.displacement_column, "displacement_column", nullptr, 0, "");
    if (*displacement == time || *displacement == velocity)
      throw InvalidInput("displacement_column", options_.displacement_column,
                         "is the " + std::string(*displacement == time ? "time" : "velocity") +
                             " column (" + column_label(*displacement) + "); choose another");
  }

  TimeHistory history;
  if (displacement) history.x.emplace();
  std::size_t restarts = 0;
  std::size_t first_row_line = 0;
  std::size_t previous_line = 0;
  bool split_already = true;  // the first row was split above
  while (have_row) {
    if (first_row_line == 0) first_row_line = line_number_;
    if (!split_already) split(content, separator_, fields);
    split_already = false;
    if (fields.size() != columns_)
      throw InvalidInput(location(line_number_), snippet(content),
                         "has " + std::to_string(fields.size()) + " column" +
                             (fields.size() == 1 ? "" : "s") + ", but line " +
                             std::to_string(first_line_) + " has " + std::to_string(columns_) +
                             " (separated by " + separator_name(separator_) +
                             "); every row needs the same number");
    const auto value = [&](std::size_t column) {
      double number = 0;
      if (!to_number(fields[column], number, decimal_comma_))
        throw InvalidInput(location(line_number_, column),
                           fields[column].empty() ? "(empty)" : fields[column], "must be a number");
      if (!std::isfinite(number))
        throw InvalidInput(location(line_number_, column), fields[column],
                           "must be a finite number");
      return number;
    };
    const double t = value(time);
    if (!history.t.empty() && t < history.t.back()) {
      if (options_.on_overlap == TimeHistoryReadOptions::OnOverlap::error)
        throw InvalidInput(
            location(line_number_, time), fields[time],
            "must be >= the time on line " + std::to_string(previous_line) + " (" +
                text(history.t.back()) +
                "): times must not decrease; if the run restarted from a checkpoint and "
                "wrote the overlap again, --on-overlap keep-last (on_overlap = "
                "keep_last) keeps the later segment");
      // A restart: the later segment counts from its first time on.
      const double from = history.t.back();
      std::size_t dropped = 0;
      while (!history.t.empty() && history.t.back() >= t) {
        history.t.pop_back();
        history.v.pop_back();
        if (history.x) history.x->pop_back();
        ++dropped;
      }
      ++restarts;
      if (restarts <= 5)
        notes_.push_back("time went back at line " + std::to_string(line_number_) + " (from " +
                         text(from) + " to " + text(t) + "): kept the later segment, dropped the " +
                         std::to_string(dropped) + " earlier row" + (dropped > 1 ? "s" : "") +
                         " at or after " + text(t));
    }
    history.t.push_back(t);
    history.v.push_back(value(velocity));
    if (displacement) history.x->push_back(value(*displacement));
    previous_line = line_number_;
    have_row = next_line(content);
  }
  if (in_.bad()) throw InvalidInput("file", name_, "cannot be read (input error)");

  if (history.t.empty())
    throw InvalidInput(
        "file", name_,
        "has no data rows after its header (line " + std::to_string(first_line_) + ")");
  if (history.t.size() == 1)
    throw InvalidInput("file", name_,
                       "has only 1 data row (line " + std::to_string(first_row_line) +
                           "); a time history needs at least 2");
  if (!(history.t.back() > history.t.front()))
    throw InvalidInput("file", name_,
                       "every row has the same time " + text(history.t.front()) + " (" +
                           column_label(time) + "); the times must span an interval");

  if (restarts > 5)
    notes_.push_back("time went back " + std::to_string(restarts) +
                     " times in all; each time the later segment was kept");
  history.notes = notes_;
  history.source = name_ + " [time: " + column_label(time) +
                   ", velocity: " + column_label(velocity) +
                   (displacement ? ", displacement: " + column_label(*displacement) : "") + "; " +
                   std::to_string(history.t.size()) + " rows on lines " +
                   std::to_string(first_row_line) + "-" + std::to_string(previous_line) + "]";
  return history;
}

}  // namespace

void TimeHistory::validate() const {
  const std::size_t n = t.size();
  if (v.size() != n)
    throw InvalidInput("v", std::to_string(v.size()) + " values",
                       "must have as many values as t (" + std::to_string(n) + ")");
  if (x && x->size() != n)
    throw InvalidInput("x", std::to_string(x->size()) + " values",
                       "must have as many values as t (" + std::to_string(n) + ")");
  if (n < 2) throw InvalidInput("t", std::to_string(n) + " values", "needs at least 2 rows");
  const auto finite = [](const char* name, const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw InvalidInput(std::string(name) + "[" + std::to_string(i) + "]", text(values[i]),
                           "must be a finite number");
  };
  finite("t", t);
  finite("v", v);
  if (x) finite("x", *x);
  for (std::size_t i = 1; i < n; ++i)
    if (t[i] < t[i - 1])
      throw InvalidInput("t[" + std::to_string(i) + "]", text(t[i]),
                         "must be >= t[" + std::to_string(i - 1) + "] = " + text(t[i - 1]) +
                             ": times must not decrease");
  if (!(t.back() > t.front()))
    throw InvalidInput("t", text(t.front()) + " ... " + text(t.back()),
                       "must span an interval (last time > first time)");
}

void TimeHistoryReadOptions::validate() const {
  const auto check = [](const char* name, const std::string& spec) {
    if (!spec.empty() && trim(spec).empty())
      throw InvalidInput(name, "'" + spec + "'", "must be a column name or a 1-based number");
    if (only_digits(spec) && spec.find_first_not_of('0') == std::string::npos)
      throw InvalidInput(name, spec, "column numbers start at 1");
  };
  check("time_column", time_column);
  check("velocity_column", velocity_column);
  check("displacement_column", displacement_column);
}

TimeHistory parse_time_history(std::istream& in, const std::string& name,
                               const TimeHistoryReadOptions& options) {
  options.validate();
  return Reader(in, name, options).read();
}

std::ifstream open_time_history_file(const std::string& path) {
  if (path.empty()) throw InvalidInput("file", "''", "must be a file name");
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InvalidInput("file", path, "is a directory, not a file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int code = errno;
    throw InvalidInput(
        "file", path,
        std::string("cannot be opened: ") + (code ? std::strerror(code) : "unknown error"));
  }
  return in;
}

TimeHistory read_time_history(const std::string& path, const TimeHistoryReadOptions& options) {
  options.validate();
  if (path == "-") return parse_time_history(std::cin, "standard input", options);
  std::ifstream in = open_time_history_file(path);
  return parse_time_history(in, path, options);
}

}  // namespace frictionref
