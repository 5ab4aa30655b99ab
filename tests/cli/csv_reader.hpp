// Reads what the binary printed: '#' metadata lines, a header, rows; numbers
// with strtod (the round trip under test).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace frictionref::cli_test {

std::vector<std::string> split(const std::string& text, char separator);
// Lines without their '\n'; a missing final newline is an error (EXPECT).
std::vector<std::string> lines(const std::string& text);

struct Csv {
  std::vector<std::string> metadata;  // comment lines without "# "
  std::string header;
  std::vector<std::vector<std::string>> rows;
  // The metadata line "<key>: ..." without the key, or "" if missing.
  std::string meta(const std::string& key) const;
  // Index of the header column `name`; a test failure (and 0) if absent.
  std::size_t column(const std::string& name) const;
};

// Comment lines must all come before the header, every row must have as many
// fields as the header (checked with gtest EXPECTs).
Csv parse_csv(const std::string& text);

// strtod of the whole field; a test failure (and NaN) otherwise.
double to_double(const std::string& field);

// "a=1 b=x" -> {a: "1", b: "x"}
std::map<std::string, std::string> key_values(const std::string& line);

}  // namespace frictionref::cli_test
