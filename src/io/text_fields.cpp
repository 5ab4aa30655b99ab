// The lexical layer of the tolerant text readers (text_fields.hpp).
#include "io/text_fields.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "frictionref/detail/number_text.hpp"

namespace frictionref::io {
std::string text(double value) { return frictionref::detail::shortest_text(value); }

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
static std::string read_field(std::string_view line, std::size_t& i, Separator separator) {
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

// The whole field as a double (strtod, or a Fortran 'D' exponent); with
// `decimal_comma` one ',' is the decimal point ("1,5").
bool to_number(const std::string& field, double& value, bool decimal_comma) {
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

bool any_number(const std::vector<std::string>& fields, bool decimal_comma) {
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
static std::string without_unit(const std::string& name) {
  std::string base = name;
  const std::size_t open = base.find_first_of("[(");
  if (open != std::string::npos && open > 0) base = std::string(trim(base.substr(0, open)));
  return base;
}

// ... and without a unit suffix after '_' or '-' ("time_s" -> "time",
// "v_mps" -> "v", "x-m" -> "x").
static std::string without_suffix(const std::string& name) {
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

}  // namespace frictionref::io
