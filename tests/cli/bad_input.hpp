// Bad command lines and the one check they all get: exit code 2, nothing on
// stdout, exactly one "frictionref: error: ..." line on stderr naming the
// option as typed and the rule, and no output file (nor temporary) left.
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {

struct BadInput {
  std::vector<std::string> args;
  std::string names;  // must appear in the message: the option, as typed
  std::string rule;   // and this (part of the rule), if not empty
};

inline std::ostream& operator<<(std::ostream& out, const BadInput& bad) {
  for (const std::string& arg : bad.args) out << "'" << arg << "' ";
  return out;
}

// `command args... -o out.csv`: a command that would write a file.
inline std::vector<std::string> writing(const std::string& command,
                                        std::vector<std::string> args) {
  args.insert(args.begin(), command);
  args.insert(args.end(), {"-o", "out.csv"});
  return args;
}

inline void expect_rejected(const BadInput& bad) {
  TempDir dir;
  const RunResult result = run_frictionref(bad.args, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(result.out.empty()) << result.out;
  ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_EQ(result.err.rfind("frictionref: error: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find(bad.names), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(bad.rule), std::string::npos) << result.err;
  EXPECT_TRUE(dir.entries().empty()) << "left behind: " << dir.entries().front();
}

// "12_events_lambda_0_3_t_end_10_mass_1": index (unique) and the arguments.
inline std::string bad_input_name(const ::testing::TestParamInfo<BadInput>& info) {
  std::string text = std::to_string(info.index);
  for (const std::string& arg : info.param.args) {
    if (arg != "-o" && arg != "out.csv") text += " " + arg;
  }
  return test_name(text);
}

}  // namespace frictionref::cli_test
