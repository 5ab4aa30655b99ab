// How numbers and intervals are written in compare's messages and reports:
// six significant digits for people (the JSON keeps every digit).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "frictionref/classification.hpp"
#include "frictionref/comparison.hpp"

namespace frictionref::comparison {

std::string g(double value);                     // "%.6g"
std::string signed_g(double value);              // "+0.03", "-0.1", "0"
std::string interval(double start, double end);  // "[1.2, 3.4]"
std::string interval(const StickInterval& s);
// Up to `limit` intervals, then "and N more".
std::string interval_list(const std::vector<StickInterval>& list, std::size_t limit = 5);
// "dead-bands", or "dead-bands (by simulation)" when no closed form gave it.
std::string steady_text(Regime regime, ClassificationMethod method);

}  // namespace frictionref::comparison
