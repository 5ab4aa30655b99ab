#include "frictionref/types.hpp"

#include <array>
#include <utility>

namespace frictionref {
namespace {

template <class Enum, std::size_t N>
std::optional<Enum> lookup(const std::array<std::pair<Enum, std::string_view>, N>& table,
                           std::string_view text) {
  for (const auto& [value, name] : table)
    if (name == text) return value;
  return std::nullopt;
}

template <class Enum, std::size_t N>
std::string_view name_of(const std::array<std::pair<Enum, std::string_view>, N>& table,
                         Enum value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return "unknown";
}

constexpr std::array<std::pair<PhaseKind, std::string_view>, 3> kPhaseNames{{
    {PhaseKind::stick, "stick"},
    {PhaseKind::slip_forward, "slip+"},
    {PhaseKind::slip_backward, "slip-"},
}};
constexpr std::array<std::pair<Termination, std::string_view>, 3> kTerminationNames{{
    {Termination::reached_end, "reached_end"},
    {Termination::phase_limit, "phase_limit"},
    {Termination::numerical_failure, "numerical_failure"},
}};
constexpr std::array<std::pair<Regime, std::string_view>, 3> kRegimeNames{{
    {Regime::continuous, "continuous"},
    {Regime::dead_bands, "dead-bands"},
    {Regime::stops, "stops"},
}};

}  // namespace

std::string_view to_string(PhaseKind kind) { return name_of(kPhaseNames, kind); }
std::string_view to_string(Termination termination) {
  return name_of(kTerminationNames, termination);
}
std::string_view to_string(Regime regime) { return name_of(kRegimeNames, regime); }

std::optional<PhaseKind> phase_kind_from_string(std::string_view text) {
  return lookup(kPhaseNames, text);
}
std::optional<Termination> termination_from_string(std::string_view text) {
  return lookup(kTerminationNames, text);
}
std::optional<Regime> regime_from_string(std::string_view text) {
  return lookup(kRegimeNames, text);
}

}  // namespace frictionref
