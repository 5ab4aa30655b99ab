// Every kind of bad input: exit code 2, exactly one line on stderr that names
// the option as typed, nothing on stdout, and no output file (nor temporary).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bad_input.hpp"
#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

std::vector<std::string> events(std::vector<std::string> args) {
  return writing("events", std::move(args));
}
std::vector<std::string> curve(std::vector<std::string> args) {
  return writing("curve", std::move(args));
}

const std::vector<BadInput> bad_inputs = {
    // Model values, each rule, and numbers that are not numbers.
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "-1"}), "--mass = -1", "> 0"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "0"}), "--mass = 0", "> 0"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "nan"}), "--mass = nan", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "inf"}), "--mass = inf", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "-inf"}), "--mass = -inf", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "1e999"}), "--mass = 1e999", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "abc"}), "--mass = abc", "number"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", "1x"}), "--mass = 1x", "number"},
    {events({"--lambda", "0.3", "--t-end", "10", "--mass", ""}), "--mass", "number"},
    {events({"--lambda", "0.3", "--t-end", "10", "--amplitude", "-1"}), "--amplitude = -1", ">= 0"},
    {events({"--lambda", "0.3", "--t-end", "10", "--amplitude", "nan"}), "--amplitude", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--omega", "0"}), "--omega = 0", "> 0"},
    {events({"--lambda", "0.3", "--t-end", "10", "--omega", "-2"}), "--omega = -2", "> 0"},
    {events({"--lambda", "0.3", "--t-end", "10", "--omega", "inf"}), "--omega", "finite"},
    {events({"--friction", "-0.1", "--t-end", "10"}), "--friction = -0.1", ">= 0"},
    {events({"--friction", "nan", "--t-end", "10"}), "--friction = nan", "finite"},
    {events({"--friction", "one", "--t-end", "10"}), "--friction = one", "number"},
    {events({"--lambda", "-0.1", "--t-end", "10"}), "--lambda = -0.1", ">= 0"},
    {events({"--lambda", "nan", "--t-end", "10"}), "--lambda = nan", "finite"},
    {events({"--lambda", "inf", "--t-end", "10"}), "--lambda = inf", "finite"},
    {events({"--lambda", "0.5", "--amplitude", "0", "--t-end", "10"}), "--lambda", "amplitude"},
    {events({"--lambda", "1e300", "--amplitude", "1e300", "--t-end", "10"}), "--lambda", "finite"},
    {events({"--friction", "0.3", "--lambda", "0.3", "--t-end", "10"}), "--lambda", ""},
    {events({"--t-end", "10"}), "--friction", ""},
    {events({"--lambda", "0.3", "--t-end", "10", "--x0", "nan"}), "--x0 = nan", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--v0", "inf"}), "--v0 = inf", "finite"},
    {events({"--lambda", "0.3", "--t-end", "10", "--t0", "nan"}), "--t0 = nan", "finite"},
    // The horizon.
    {events({"--lambda", "0.3", "--t-end", "0"}), "--t-end = 0", ""},
    {events({"--lambda", "0.3", "--t-end", "-1"}), "--t-end = -1", ""},
    {events({"--lambda", "0.3", "--t0", "5", "--t-end", "5"}), "--t-end = 5", ""},
    {events({"--lambda", "0.3", "--t0", "6", "--t-end", "5"}), "--t-end = 5", ""},
    {events({"--lambda", "0.3", "--t-end", "nan"}), "--t-end = nan", ""},
    {events({"--lambda", "0.3", "--t-end", "inf"}), "--t-end = inf", ""},
    {events({"--lambda", "0.3", "--t-end", "ten"}), "--t-end = ten", "number"},
    {events({"--lambda", "0.3"}), "--t-end", ""},
    {events({"--lambda", "0.3", "--t-end", "1e10"}), "--t-end = 1e10", "--force"},
    {events({"--lambda", "0.3", "--t-end", "1e10", "--summary"}), "--t-end = 1e10", "--force"},
    {events({"--lambda", "0.3", "--stiffness", "1e17", "--t-end", "30"}), "--t-end = 30",
     "4 per natural period"},
    {events({"--lambda", "0.3", "--omega", "100", "--t-end", "2e7"}), "--t-end", "--force"},
    // Forcing phases a double cannot resolve are refused even with --force.
    {events({"--lambda", "0.3", "--t-end", "2e10", "--force"}), "--t-end = 2e10", "1e10"},
    {events({"--lambda", "0.3", "--t0", "-2e10", "--t-end", "1", "--force"}), "--t0 = -2e10", "1e10"},
    {curve({"--lambda", "0.3", "--omega", "1e5", "--t-end", "1e6", "--dt", "1e3", "--force"}),
     "--t-end = 1e6", "1e10"},
    // Parsing.
    {events({"--lambda", "0.3", "--t-end", "10", "--bogus"}), "--bogus", ""},
    {events({"--lambda", "0.3", "--t-end", "10", "--dt", "0.1"}), "--dt", ""},
    {events({"--lambda", "0.3", "--t-end", "10", "extra"}), "extra", ""},
    {events({"--lambda", "0.3", "--t-end", "10", "--t-end", "20"}), "--t-end", ""},
    {{"events", "--lambda", "0.3", "-o", "out.csv", "--t-end"}, "--t-end", ""},
    {{"events", "--lambda", "0.3", "--t-end", "10", "-o"}, "-o", ""},
    // A missing value: CLI11 takes the next option as the value.
    {events({"--mass", "--lambda", "0.3", "--t-end", "10"}), "--mass = --lambda", "number"},
    {events({"--lambda", "--t-end", "10"}), "--lambda = --t-end", "number"},
    {events({"--lambda", "0.3", "--t-end", "--summary"}), "--t-end = --summary", "number"},
    // curve.
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "0"}), "--dt = 0", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "-0.01"}), "--dt = -0.01", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "nan"}), "--dt = nan", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "inf"}), "--dt = inf", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "0.1s"}), "--dt = 0.1s", "number"},
    {curve({"--lambda", "0.3", "--t-end", "10"}), "--dt", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "--include-events"}), "--dt", "number"},
    {curve({"--lambda", "0.3", "--dt", "0.1"}), "--t-end", ""},
    {curve({"--lambda", "0.3", "--t-end", "0", "--dt", "0.1"}), "--t-end = 0", ""},
    {curve({"--lambda", "0.3", "--t-end", "1e9", "--dt", "0.01"}), "--dt = 0.01", "--force"},
    {curve({"--lambda", "0.3", "--t0", "1e20", "--t-end", "2e20", "--dt", "1"}), "--dt = 1", ""},
    {curve({"--mass", "-1", "--lambda", "0.3", "--t-end", "10", "--dt", "0.1"}), "--mass = -1", ""},
    {curve({"--lambda", "0.3", "--t-end", "10", "--dt", "0.1", "--summary"}), "--summary", ""},
    // classify (no output file).
    {{"classify", "--lambda", "-1"}, "--lambda = -1", ">= 0"},
    {{"classify", "--friction", "1", "--amplitude", "0"}, "--amplitude = 0", ""},
    {{"classify", "--mass", "0", "--lambda", "0.3"}, "--mass = 0", ""},
    {{"classify", "--json"}, "--friction", ""},
    {{"classify", "--lambda", "0.3", "--t-end", "5"}, "--t-end", ""},
    // reproduce has fixed cases: no model options.
    {{"reproduce", "--mass", "1"}, "--mass", ""},
    {{"reproduce", "--lambda", "0.3"}, "--lambda", ""},
    {{"reproduce", "--out"}, "--out", ""},
    // The command itself.
    {{}, "command", ""},
    {{"foo"}, "foo", ""},
    {{"foo", "--mass", "1"}, "foo", ""},
    {{"--bogus"}, "--bogus", ""},
    {{"events", "classify", "--lambda", "0.3", "--t-end", "1"}, "classify", ""},
};

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, OneLineExitTwoNoFile) { expect_rejected(GetParam()); }

INSTANTIATE_TEST_SUITE_P(All, BadInputTest, ::testing::ValuesIn(bad_inputs), bad_input_name);

}  // namespace
}  // namespace frictionref::cli_test
