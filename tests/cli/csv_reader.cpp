#include "csv_reader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

namespace frictionref::cli_test {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string::size_type begin = 0;
  while (true) {
    const auto end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end - begin));
    if (end == std::string::npos) return parts;
    begin = end + 1;
  }
}

std::vector<std::string> lines(const std::string& text) {
  if (text.empty()) return {};
  EXPECT_EQ(text.back(), '\n') << "output does not end with a newline";
  std::vector<std::string> result = split(text, '\n');
  if (result.back().empty()) result.pop_back();
  return result;
}

std::size_t Csv::column(const std::string& name) const {
  const std::vector<std::string> names = split(header, ',');
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

std::string Csv::meta(const std::string& key) const {
  const std::string prefix = key + ": ";
  for (const std::string& line : metadata) {
    if (line.compare(0, prefix.size(), prefix) == 0) return line.substr(prefix.size());
  }
  return "";
}

Csv parse_csv(const std::string& text) {
  Csv csv;
  bool in_header = true;
  std::size_t columns = 0;
  for (const std::string& line : lines(text)) {
    if (in_header && line.rfind("# ", 0) == 0) {
      csv.metadata.push_back(line.substr(2));
    } else if (in_header) {
      csv.header = line;
      columns = split(line, ',').size();
      in_header = false;
    } else {
      EXPECT_NE(line.rfind('#', 0), 0u) << "comment after the header: " << line;
      csv.rows.push_back(split(line, ','));
      EXPECT_EQ(csv.rows.back().size(), columns) << line;
    }
  }
  return csv;
}

double to_double(const std::string& field) {
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || end != field.c_str() + field.size()) {
    ADD_FAILURE() << "not a number: '" << field << "'";
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value;
}

std::map<std::string, std::string> key_values(const std::string& line) {
  std::map<std::string, std::string> result;
  for (const std::string& word : split(line, ' ')) {
    const auto equals = word.find('=');
    if (equals != std::string::npos) result[word.substr(0, equals)] = word.substr(equals + 1);
  }
  return result;
}

}  // namespace frictionref::cli_test
