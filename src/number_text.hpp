// The shortest decimal text that reads back to the same double (std::to_chars),
// for values quoted in error messages and reports.
#pragma once

#include <charconv>
#include <string>

namespace frictionref::detail {

inline std::string shortest_text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

}  // namespace frictionref::detail
