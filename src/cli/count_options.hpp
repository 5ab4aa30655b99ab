// Whole-number options of the commands (--points, --periods, --threads): the
// rule and its message in one place, so every command words it the same.
#pragma once

#include <cstdint>
#include <string>

#include "model_options.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace frictionref::cli {

// A whole number in [1, max]; "1e5" is fine. Throws bad input
// "--points = 0.5: must be a whole number >= 1" or "--points = 1e8: must be
// <= 10^7" (max_text).
std::uint64_t whole_number(const TypedNumber& typed, double max, const char* max_text);

// Adds --threads N to `command`, bound to `text` (empty: not given).
CLI::Option* add_threads_option(CLI::App& command, std::string& text);

// The worker threads of --threads: 0 (every core) when not given, else a
// whole number from 1 to 256.
unsigned thread_count(const std::string& text);

}  // namespace frictionref::cli
