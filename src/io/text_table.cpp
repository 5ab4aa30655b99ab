// A tolerant reader of numeric tables in text files (text_table.hpp).
#include "io/text_table.hpp"

#include <cmath>
#include <utility>

#include "frictionref/error.hpp"

namespace frictionref::io {
namespace {

// Content lines held while looking for the table's first row.
constexpr std::size_t kMaxLeadingLines = 64;

}  // namespace

TextTableReader::TextTableReader(std::istream& in, std::string name, TableShape shape)
    : in_(in), name_(std::move(name)), shape_(std::move(shape)) {}

bool TextTableReader::next_line(std::string_view& content) {
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

static std::string lines_text(std::size_t first, std::size_t last) {
  return first == last ? "line " + std::to_string(first)
                       : "lines " + std::to_string(first) + "-" + std::to_string(last);
}

void TextTableReader::find_table() {
  std::string_view content;
  std::size_t first_skipped = 0;
  for (std::size_t i = 0; i < shape_.skip_rows; ++i) {
    if (!next_line(content))
      throw InvalidInput("skip_rows", std::to_string(shape_.skip_rows),
                         name_ + " has only " + std::to_string(i) +
                             " lines that are not comments or blank; nothing is left to read");
    if (i == 0) first_skipped = line_number_;
  }
  if (shape_.skip_rows > 0)
    notes_.push_back("skipped " + std::to_string(shape_.skip_rows) + " line" +
                     (shape_.skip_rows > 1 ? "s" : "") + " before the table as asked (" +
                     lines_text(first_skipped, line_number_) + ")");
  // Read ahead to the first line with min_columns numbers: the table's first row.
  std::vector<Held> ahead;
  std::vector<std::string> fields, header;
  while (ahead.size() < kMaxLeadingLines && next_line(content)) {
    ahead.push_back({std::string(content), line_number_});
    const Separator separator = separator_of(content, shape_.decimal_comma);
    const bool decimal = shape_.decimal_comma || separator == Separator::semicolon;
    split(content, separator, fields);
    if (fields.size() < shape_.min_columns || count_numbers(fields, decimal) < shape_.min_columns)
      continue;
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
  // No row with enough numbers within reach: the first content line starts the
  // table, as it always did, and its errors say what is wrong.
  held_.assign(ahead.begin(), ahead.end());
}

std::string TextTableReader::column_label(std::size_t index) const {
  std::string label = "column " + std::to_string(index + 1);
  if (header_ && !(*header_)[index].empty()) label += " (" + (*header_)[index] + ")";
  return label;
}

std::string TextTableReader::header_names() const {
  std::string names;
  for (std::size_t i = 0; i < header_->size(); ++i) {
    if (i == 12) return names + ", ...";
    names += (i ? ", " : "") + (*header_)[i];
  }
  return names;
}

std::size_t TextTableReader::resolve(const std::string& spec, const char* field,
                                     const char* const* names, std::size_t default_number,
                                     const char* default_text) const {
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

void TextTableReader::require_some_number(const std::vector<std::string>& first_row) {
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
  throw InvalidInput(
      "file", name_,
      "contains no numbers (" + shape_.what + " needs " + shape_.numbers_needed + ")");
}

void TextTableReader::open() {
  find_table();
  std::string_view content;
  if (!next_line(content)) {
    check_stream();
    throw InvalidInput("file", name_,
                       any_text_ ? "has no data rows (only comments and blank lines)" : "is empty");
  }
  first_line_ = line_number_;
  separator_ = separator_of(content, shape_.decimal_comma);
  decimal_comma_ = shape_.decimal_comma || separator_ == Separator::semicolon;
  split(content, separator_, fields_);
  content_ = content;
  columns_ = fields_.size();
  if (columns_ < shape_.min_columns)
    throw InvalidInput(location(line_number_), snippet(content),
                       "has 1 column; " + shape_.what + " needs at least " + shape_.columns_needed +
                           ", separated by commas, semicolons, spaces or tabs");
  row_ready_ = true;
  if (!any_number(fields_, decimal_comma_)) {
    header_ = fields_;
    row_ready_ = false;
    if (next_line(content)) {
      split(content, separator_, fields_);
      content_ = content;
      require_some_number(fields_);
      row_ready_ = true;
    }
  }
}

bool TextTableReader::next_row() {
  if (row_ready_) {
    row_ready_ = false;
  } else {
    std::string_view content;
    if (!next_line(content)) return false;
    split(content, separator_, fields_);
    content_ = content;
  }
  if (fields_.size() != columns_)
    throw InvalidInput(
        location(line_number_), snippet(content_),
        "has " + std::to_string(fields_.size()) + " column" + (fields_.size() == 1 ? "" : "s") +
            ", but line " + std::to_string(first_line_) + " has " + std::to_string(columns_) +
            " (separated by " + separator_name(separator_) + "); every row needs the same number");
  return true;
}

double TextTableReader::number(std::size_t column) const {
  double value = 0;
  const std::string& field = fields_[column];
  if (!to_number(field, value, decimal_comma_))
    throw InvalidInput(location(line_number_, column), field.empty() ? "(empty)" : field,
                       "must be a number");
  if (!std::isfinite(value))
    throw InvalidInput(location(line_number_, column), field, "must be a finite number");
  return value;
}

std::optional<std::size_t> TextTableReader::find_column(const char* const* names) const {
  if (!header_) return std::nullopt;
  for (int level = 0; level < 3; ++level)
    for (const char* const* name = names; *name; ++name)
      for (std::size_t i = 0; i < columns_; ++i)
        if (header_key((*header_)[i], level) == *name) return i;
  return std::nullopt;
}

void TextTableReader::check_stream() const {
  if (in_.bad()) throw InvalidInput("file", name_, "cannot be read (input error)");
}

}  // namespace frictionref::io
