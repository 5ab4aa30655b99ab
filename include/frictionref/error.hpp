// The one exception type for bad user input.
// Broken internal invariants are asserts; running out of phases is a
// Termination status, not an exception.
#pragma once

#include <stdexcept>
#include <string>

namespace frictionref {

// Thrown by every validate(): names the parameter, the offending value and the
// rule it broke, e.g. parameter "mass", value "-1", rule "must be > 0".
// what() is "mass = -1; violated: must be > 0".
class InvalidInput : public std::invalid_argument {
 public:
  InvalidInput(std::string parameter, std::string value, std::string rule);

  const std::string& parameter() const { return parameter_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string parameter_;
  std::string value_;
  std::string rule_;
};

}  // namespace frictionref
