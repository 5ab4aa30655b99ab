// The model in one line, for figure titles.
#pragma once

#include <string>

#include "frictionref/model.hpp"

namespace frictionref::cli {

// "m=1 B=1 w=1 R=0.7 (lambda=0.7) x0=0 v0=0 t0=0", with Rs, k, c, F0 and the
// extra harmonics of a general model where they differ from their defaults.
std::string model_title(const Model& model);

}  // namespace frictionref::cli
