// Small assertions shared by the CLI tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "run_binary.hpp"

namespace frictionref::cli_test {

// Distance in units in the last place between two finite doubles.
inline std::uint64_t ulps_apart(double a, double b) {
  std::int64_t ia, ib;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  // Map the sign-magnitude bit patterns onto one monotone integer line.
  if (ia < 0) ia = INT64_MIN - ia;
  if (ib < 0) ib = INT64_MIN - ib;
  return ia > ib ? static_cast<std::uint64_t>(ia - ib) : static_cast<std::uint64_t>(ib - ia);
}

// A gtest name from free text: letters and digits kept, the rest '_'.
inline std::string test_name(const std::string& text) {
  std::string name;
  for (const char c : text) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    name += keep ? c : '_';
  }
  return name;
}

// The binary succeeded quietly.
inline ::testing::AssertionResult succeeded(const RunResult& result) {
  if (result.exit_code == 0 && result.err.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "exit code " << result.exit_code << ", stderr: " << result.err;
}

}  // namespace frictionref::cli_test
