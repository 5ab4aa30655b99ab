// Runs a callable that must reject its input and hands back the InvalidInput,
// so a test can check which parameter and rule it named.
#pragma once

#include <gtest/gtest.h>

#include <exception>

#include "frictionref/error.hpp"

namespace frictionref::testing {

// Fails the test if `validate` throws nothing, or something other than InvalidInput.
template <class F>
InvalidInput expect_invalid(F&& validate) {
  try {
    validate();
  } catch (const InvalidInput& error) {
    return error;
  } catch (const std::exception& other) {
    ADD_FAILURE() << "threw something other than InvalidInput: " << other.what();
    return InvalidInput("<wrong exception>", "", "");
  }
  ADD_FAILURE() << "did not throw";
  return InvalidInput("<no exception>", "", "");
}

}  // namespace frictionref::testing
