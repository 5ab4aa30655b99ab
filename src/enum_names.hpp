// The one enum <-> name table helper of the library: each enum's names are a
// constexpr array of {value, name} pairs, read both ways by these two
// functions (pattern: Ceres Solver types.cc).
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace frictionref::detail {

template <class Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

template <class Enum, std::size_t N>
std::optional<Enum> enum_from_name(const EnumNames<Enum, N>& table, std::string_view text) {
  for (const auto& [value, name] : table)
    if (name == text) return value;
  return std::nullopt;
}

template <class Enum, std::size_t N>
std::string_view name_of(const EnumNames<Enum, N>& table, Enum value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return "unknown";
}

}  // namespace frictionref::detail
