// The model's JSON object (frictionref/model_json.hpp), as a value the
// library's other JSON writers embed.
#pragma once

#include <nlohmann/json.hpp>

#include "frictionref/model.hpp"

namespace frictionref::detail {

nlohmann::ordered_json model_json(const Model& model);

}  // namespace frictionref::detail
