// `frictionref curve`: the exact state on a uniform time grid.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "frictionref/sampling.hpp"

namespace frictionref::cli {

// "grid: t0=0 t_end=30 dt=0.01 include_events=true grid_rows=3001"
std::string grid_metadata(const Model& model, const GridOptions& grid);

// Streams every row of `sampler` as the curve CSV (metadata, header, rows);
// memory stays flat for any horizon. Returns the engine's summary.
Summary write_curve_csv(std::FILE* out, const Model& model, UniformSampler& sampler,
                        const std::string& command, const std::vector<std::string>& extra_metadata);

}  // namespace frictionref::cli
