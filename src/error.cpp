#include "frictionref/error.hpp"

#include <utility>

namespace frictionref {

InvalidInput::InvalidInput(std::string parameter, std::string value, std::string rule)
    : std::invalid_argument(parameter + " = " + value + "; violated: " + rule),
      parameter_(std::move(parameter)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

}  // namespace frictionref
