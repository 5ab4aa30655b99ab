#include "frictionref/types.hpp"

#include "enum_names.hpp"

namespace frictionref {
namespace {

using detail::name_of;

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
constexpr std::array<std::pair<Regime, std::string_view>, 4> kRegimeNames{{
    {Regime::continuous, "continuous"},
    {Regime::dead_bands, "dead-bands"},
    {Regime::stops, "stops"},
    {Regime::aperiodic, "aperiodic"},
}};

}  // namespace

std::string_view to_string(PhaseKind kind) { return name_of(kPhaseNames, kind); }
std::string_view to_string(Termination termination) {
  return name_of(kTerminationNames, termination);
}
std::string_view to_string(Regime regime) { return name_of(kRegimeNames, regime); }

std::optional<PhaseKind> phase_kind_from_string(std::string_view text) {
  return detail::enum_from_name(kPhaseNames, text);
}
std::optional<Termination> termination_from_string(std::string_view text) {
  return detail::enum_from_name(kTerminationNames, text);
}
std::optional<Regime> regime_from_string(std::string_view text) {
  return detail::enum_from_name(kRegimeNames, text);
}

}  // namespace frictionref
