// Whole-number options (count_options.hpp).
#include "count_options.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>

#include "cli_error.hpp"

namespace frictionref::cli {

std::uint64_t whole_number(const TypedNumber& typed, double max, const char* max_text) {
  const double value = parse_number(typed);
  if (!(value >= 1) || value != std::floor(value))
    throw bad_input(fmt::format("{} = {}: must be a whole number >= 1", typed.option, typed.text));
  if (!(value <= max))
    throw bad_input(fmt::format("{} = {}: must be <= {}", typed.option, typed.text, max_text));
  return static_cast<std::uint64_t>(value);
}

CLI::Option* add_threads_option(CLI::App& command, std::string& text) {
  return numeric(
             command.add_option("--threads", text, "worker threads; 1 to 256 (default: all cores)"))
      ->type_name("N");
}

unsigned thread_count(const std::string& text) {
  if (text.empty()) return 0;
  return static_cast<unsigned>(whole_number({"--threads", text}, 256, "256"));
}

}  // namespace frictionref::cli
