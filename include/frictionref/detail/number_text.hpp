// Numbers as text for error messages and reports: the shortest decimal text
// that reads back to the same double (std::to_chars), and max_digits10
// digits for every other scalar type. The one number formatter of the
// library (the CLI's CSV/JSON writers use fmt's shortest form, the same text).
#pragma once

#include <charconv>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

namespace frictionref::detail {

inline std::string shortest_text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

template <class T>
std::string to_text(const T& value) {
  if constexpr (std::is_same_v<T, double>) {
    return shortest_text(value);
  } else {
    std::ostringstream text;
    text.precision(std::numeric_limits<T>::max_digits10);
    text << value;
    return text.str();
  }
}

}  // namespace frictionref::detail
