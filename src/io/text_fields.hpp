// The lexical layer of the tolerant text readers (text_table.hpp): blanks,
// '#' comments, separators, quoted fields, numbers with a Fortran exponent or
// a decimal comma, and the header names columns answer to.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace frictionref::io {

// Shortest round-trip text of a value, for messages.
std::string text(double value);

bool is_blank(char c);
std::string_view trim(std::string_view s);
std::string lower(std::string_view s);

// The line without a '#' comment (a '#' inside double quotes is text).
std::string_view strip_comment(std::string_view line);

enum class Separator { comma, semicolon, blanks };
const char* separator_name(Separator separator);

// The fields of a line: double-quoted fields ("" is a quote inside them) or
// plain text up to the separator, trimmed.
void split(std::string_view line, Separator separator, std::vector<std::string>& fields);

// The whole field as a double (strtod, or a Fortran 'D' exponent); with
// `decimal_comma` one ',' is the decimal point ("1,5").
bool to_number(const std::string& field, double& value, bool decimal_comma = false);
std::size_t count_numbers(const std::vector<std::string>& fields, bool decimal_comma);
bool any_number(const std::vector<std::string>& fields, bool decimal_comma = false);

// The separator of a content line: ';' if there is one (then numbers may
// have a decimal comma), else ',' unless commas are decimal points, else blanks.
Separator separator_of(std::string_view line, bool decimal_comma);

// The three ways a header name answers to a wanted name, strictest first:
// as written; without a unit in brackets ("time [s]"); without a unit suffix
// after '_' or '-' ("time_s", "v_mps", "x-m"). Lower case.
std::string header_key(const std::string& name, int level);

bool only_digits(const std::string& s);

// Long lines are shortened in messages.
std::string snippet(std::string_view line);

}  // namespace frictionref::io
