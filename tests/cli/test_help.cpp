// --help and --version: exit 0, on stdout, and teaching what each command does.
#include <gtest/gtest.h>

#include <string>

#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Help, Version) {
  const RunResult result = run_frictionref({"--version"});
  ASSERT_TRUE(succeeded(result));
  EXPECT_EQ(result.out, std::string("frictionref ") + FRICTIONREF_EXPECTED_VERSION + "\n");
}

TEST(Help, App) {
  for (const char* flag : {"--help", "-h"}) {
    const RunResult result = run_frictionref({flag});
    ASSERT_TRUE(succeeded(result));
    for (const char* part : {"events", "curve", "reproduce", "classify", "stiff", "compare",
                             "convergence", "Exit codes",
                             "2 bad input", "3 compare, report: verdict", "INCONCLUSIVE", "4 internal error", "--version", "Example"}) {
      EXPECT_TRUE(contains(result.out, part)) << part;
    }
  }
}

TEST(Help, EveryCommand) {
  for (const char* command :
       {"events", "curve", "reproduce", "classify", "stiff", "compare", "convergence"}) {
    SCOPED_TRACE(command);
    const RunResult result = run_frictionref({command, "--help"});
    ASSERT_TRUE(succeeded(result));
    EXPECT_TRUE(contains(result.out, "Example")) << result.out;
    EXPECT_TRUE(contains(result.out, std::string("frictionref ") + command + " "));
    EXPECT_TRUE(contains(result.out, "Exit codes"));
    const bool has_model = std::string(command) != "reproduce";
    for (const char* option :
         {"--mass", "--amplitude", "--omega", "--friction", "--lambda", "--x0", "--v0", "--t0"}) {
      EXPECT_EQ(contains(result.out, option), has_model) << option;
    }
  }
  EXPECT_TRUE(contains(run_frictionref({"curve", "--help"}).out, "--include-events"));
  EXPECT_TRUE(contains(run_frictionref({"events", "--help"}).out, "--summary"));
  EXPECT_TRUE(contains(run_frictionref({"reproduce", "--help"}).out, "frictionref-results"));
}

// Help wins over missing required options.
TEST(Help, WithoutRequiredOptions) {
  const RunResult result = run_frictionref({"events", "--help", "--mass", "-1"});
  EXPECT_TRUE(succeeded(result));
}

}  // namespace
}  // namespace frictionref::cli_test
