// compare's report as JSON: the document `frictionref compare --json` writes
// and the dict `frictionref.compare()` returns in Python (docs/cli.md,
// docs/cross-checking.md list every key). Numbers are written in their
// shortest form that reads back exactly; NaN (a matched stick with no exact
// stick phase) is written as null.
#pragma once

#include <string>
#include <string_view>

#include "frictionref/comparison.hpp"

namespace frictionref {

// Indented by two spaces, without a final newline. With a command line, the
// document ends with "command": command_line.
std::string comparison_json(const ComparisonReport& report, std::string_view command_line = {});

}  // namespace frictionref
