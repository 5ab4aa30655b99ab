// Reading another code's time history (time_history.hpp): the columns of a
// tolerant text table (io/text_table.hpp) as t, v and optionally x, with the
// time rules (non-decreasing, restarts resolved on request).
#include "frictionref/time_history.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "io/text_table.hpp"

namespace frictionref {
namespace {

using namespace io;

io::TableShape time_history_shape(const TimeHistoryReadOptions& options) {
  io::TableShape shape;
  shape.decimal_comma = options.decimal_comma;
  shape.skip_rows = options.skip_rows;
  return shape;
}

TimeHistory read_table(std::istream& in, const std::string& name,
                       const TimeHistoryReadOptions& options) {
  TextTableReader table(in, name, time_history_shape(options));
  table.open();

  static const char* const time_names[] = {"t", "time", nullptr};
  static const char* const velocity_names[] = {"v", "vel", "velocity", nullptr};
  const std::size_t time =
      table.resolve(options.time_column, "time_column", time_names, 1, "t or time");
  const std::size_t velocity = table.resolve(options.velocity_column, "velocity_column",
                                             velocity_names, 2, "v, vel or velocity");
  if (velocity == time)
    throw InvalidInput("velocity_column",
                       options.velocity_column.empty() ? "(default)" : options.velocity_column,
                       "is the time column (" + table.column_label(time) + "); choose another");
  std::optional<std::size_t> displacement;
  if (!options.displacement_column.empty()) {
    displacement =
        table.resolve(options.displacement_column, "displacement_column", nullptr, 0, "");
    if (*displacement == time || *displacement == velocity)
      throw InvalidInput("displacement_column", options.displacement_column,
                         "is the " + std::string(*displacement == time ? "time" : "velocity") +
                             " column (" + table.column_label(*displacement) + "); choose another");
  }

  TimeHistory history;
  if (displacement) history.x.emplace();
  std::vector<std::string>& notes = table.notes();
  std::size_t restarts = 0;
  std::size_t first_row_line = 0;
  std::size_t previous_line = 0;
  while (table.next_row()) {
    const std::size_t line = table.line();
    if (first_row_line == 0) first_row_line = line;
    const double t = table.number(time);
    if (!history.t.empty() && t < history.t.back()) {
      if (options.on_overlap == TimeHistoryReadOptions::OnOverlap::error)
        throw InvalidInput(
            table.location(line, time), table.fields()[time],
            "must be >= the time on line " + std::to_string(previous_line) + " (" +
                text(history.t.back()) +
                "): times must not decrease; if the run restarted from a checkpoint and "
                "wrote the overlap again, --on-overlap keep-last (on_overlap = "
                "keep_last) keeps the later segment");
      // A restart: the later segment counts from its first time on.
      const double from = history.t.back();
      std::size_t dropped = 0;
      while (!history.t.empty() && history.t.back() >= t) {
        history.t.pop_back();
        history.v.pop_back();
        if (history.x) history.x->pop_back();
        ++dropped;
      }
      ++restarts;
      if (restarts <= 5)
        notes.push_back("time went back at line " + std::to_string(line) + " (from " + text(from) +
                        " to " + text(t) + "): kept the later segment, dropped the " +
                        std::to_string(dropped) + " earlier row" + (dropped > 1 ? "s" : "") +
                        " at or after " + text(t));
    }
    history.t.push_back(t);
    history.v.push_back(table.number(velocity));
    if (displacement) history.x->push_back(table.number(*displacement));
    previous_line = line;
  }
  table.check_stream();

  if (history.t.empty())
    throw InvalidInput(
        "file", name,
        "has no data rows after its header (line " + std::to_string(table.first_line()) + ")");
  if (history.t.size() == 1)
    throw InvalidInput("file", name,
                       "has only 1 data row (line " + std::to_string(first_row_line) +
                           "); a time history needs at least 2");
  if (!(history.t.back() > history.t.front()))
    throw InvalidInput("file", name,
                       "every row has the same time " + text(history.t.front()) + " (" +
                           table.column_label(time) + "); the times must span an interval");

  if (restarts > 5)
    notes.push_back("time went back " + std::to_string(restarts) +
                    " times in all; each time the later segment was kept");
  history.notes = notes;
  history.source = name + " [time: " + table.column_label(time) +
                   ", velocity: " + table.column_label(velocity) +
                   (displacement ? ", displacement: " + table.column_label(*displacement) : "") +
                   "; " + std::to_string(history.t.size()) + " rows on lines " +
                   std::to_string(first_row_line) + "-" + std::to_string(previous_line) + "]";
  return history;
}

}  // namespace

void TimeHistory::validate() const {
  const std::size_t n = t.size();
  if (v.size() != n)
    throw InvalidInput("v", std::to_string(v.size()) + " values",
                       "must have as many values as t (" + std::to_string(n) + ")");
  if (x && x->size() != n)
    throw InvalidInput("x", std::to_string(x->size()) + " values",
                       "must have as many values as t (" + std::to_string(n) + ")");
  if (n < 2) throw InvalidInput("t", std::to_string(n) + " values", "needs at least 2 rows");
  const auto finite = [](const char* name, const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw InvalidInput(std::string(name) + "[" + std::to_string(i) + "]", text(values[i]),
                           "must be a finite number");
  };
  finite("t", t);
  finite("v", v);
  if (x) finite("x", *x);
  for (std::size_t i = 1; i < n; ++i)
    if (t[i] < t[i - 1])
      throw InvalidInput("t[" + std::to_string(i) + "]", text(t[i]),
                         "must be >= t[" + std::to_string(i - 1) + "] = " + text(t[i - 1]) +
                             ": times must not decrease");
  if (!(t.back() > t.front()))
    throw InvalidInput("t", text(t.front()) + " ... " + text(t.back()),
                       "must span an interval (last time > first time)");
}

void TimeHistoryReadOptions::validate() const {
  const auto check = [](const char* name, const std::string& spec) {
    if (!spec.empty() && trim(spec).empty())
      throw InvalidInput(name, "'" + spec + "'", "must be a column name or a 1-based number");
    if (only_digits(spec) && spec.find_first_not_of('0') == std::string::npos)
      throw InvalidInput(name, spec, "column numbers start at 1");
  };
  check("time_column", time_column);
  check("velocity_column", velocity_column);
  check("displacement_column", displacement_column);
}

TimeHistory parse_time_history(std::istream& in, const std::string& name,
                               const TimeHistoryReadOptions& options) {
  options.validate();
  return read_table(in, name, options);
}

std::ifstream open_time_history_file(const std::string& path) {
  if (path.empty()) throw InvalidInput("file", "''", "must be a file name");
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InvalidInput("file", path, "is a directory, not a file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int code = errno;
    throw InvalidInput(
        "file", path,
        std::string("cannot be opened: ") + (code ? std::strerror(code) : "unknown error"));
  }
  return in;
}

TimeHistory read_time_history(const std::string& path, const TimeHistoryReadOptions& options) {
  options.validate();
  if (path == "-") return parse_time_history(std::cin, "standard input", options);
  std::ifstream in = open_time_history_file(path);
  return parse_time_history(in, path, options);
}

}  // namespace frictionref
