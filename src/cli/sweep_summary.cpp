// The '# regimes:' line of a sweep table (sweep_summary.hpp).
#include "sweep_summary.hpp"

#include <fmt/format.h>

namespace frictionref::cli {

namespace {
constexpr std::string_view lambda_star_start = "regimes: simulated and threshold differ at ";
constexpr std::string_view den_hartog_start = "regimes: Den Hartog's closed form gives the regime";
constexpr std::string_view none_start = "regimes: no closed form gives the regime";
}  // namespace

std::string regimes_line(SweepThreshold rule, const RegimeCounts& counts, std::uint64_t periods) {
  switch (rule) {
    case SweepThreshold::lambda_star:
      return fmt::format(
          "{}{} of {} lambdas (expected only for 0 < lambda - lambda* <= {:.3g}, dead bands "
          "shorter than the engine's time resolution)",
          lambda_star_start, counts.differ, counts.rows, sweep_unresolved_distance(periods));
    case SweepThreshold::den_hartog:
      return fmt::format(
          "{} (continuous: its non-stop solution exists and is stable) at {} of {} lambdas, n/a "
          "at the others; simulated and threshold differ at {} of the {}",
          den_hartog_start, counts.known, counts.rows, counts.differ, counts.known);
    case SweepThreshold::none:
      break;
  }
  return fmt::format("{} of this model (regime_threshold is n/a); regime_simulated is the "
                     "simulation's alone",
                     none_start);
}

std::optional<SweepThreshold> regimes_rule(std::string_view line) {
  const auto starts = [&](std::string_view start) { return line.substr(0, start.size()) == start; };
  if (starts(lambda_star_start)) return SweepThreshold::lambda_star;
  if (starts(den_hartog_start)) return SweepThreshold::den_hartog;
  if (starts(none_start)) return SweepThreshold::none;
  return std::nullopt;
}

}  // namespace frictionref::cli
