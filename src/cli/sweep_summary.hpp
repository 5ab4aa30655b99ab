// The '# regimes:' line of a sweep table: how often the simulated regime and
// the closed form's differ. `sweep` writes it for its rows and `merge`
// recomputes it from the joined rows of a sharded sweep, so both go through
// this one function.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "frictionref/sweep.hpp"

namespace frictionref::cli {

struct RegimeCounts {
  std::size_t rows = 0;
  std::size_t known = 0;   // rows whose regime_threshold is not n/a
  std::size_t differ = 0;  // ... and differs from regime_simulated
};

// "regimes: ..." without the leading "# ".
std::string regimes_line(SweepThreshold rule, const RegimeCounts& counts, std::uint64_t periods);

// The rule a regimes line was written for (each rule words it differently).
std::optional<SweepThreshold> regimes_rule(std::string_view line);

}  // namespace frictionref::cli
