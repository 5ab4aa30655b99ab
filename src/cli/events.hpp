// `frictionref events`: the table of stick and slip phases.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "frictionref/exact_engine.hpp"

namespace frictionref::cli {

// Streams every phase of `engine` as the events CSV (metadata, header, rows);
// memory stays flat for any horizon. Returns the engine's summary.
Summary write_events_csv(std::FILE* out, ExactEngine& engine, const std::string& command,
                         const std::vector<std::string>& extra_metadata);

}  // namespace frictionref::cli
