#include "csv_format.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <iterator>

#include "frictionref/types.hpp"
#include "frictionref/version.hpp"

namespace frictionref::cli {

std::string number(double value) { return fmt::format("{}", value); }

namespace {

bool needs_quotes(const std::string& word) {
  if (word.empty()) return true;
  for (const char c : word) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       std::string_view("-_+=.,:/@%").find(c) != std::string_view::npos;
    if (!plain) return true;
  }
  return false;
}

// POSIX shell single quotes; a control character would end the comment line,
// so it becomes '?' (the line is a record, not a second channel of input).
std::string shell_quote(const std::string& word) {
  if (!needs_quotes(word)) return word;
  std::string quoted = "'";
  for (const char c : word) {
    if (c == '\'') {
      quoted += "'\\''";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      quoted += '?';
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

}  // namespace

std::string command_line(int argc, const char* const* argv) {
  // The program by its name, not the path it was run from: the metadata of
  // a file must not depend on where the binary happened to be built.
  std::string line = "frictionref";
  for (int i = 1; i < argc; ++i) line += ' ' + shell_quote(argv[i]);
  return line;
}

std::vector<std::string> record_metadata(const GroundMotion& record) {
  std::vector<std::string> lines;
  lines.push_back(
      fmt::format("record: {} ({}), sha256 {}", record.file, record.format, record.sha256));
  for (const std::string& line : record.header) lines.push_back("record header: " + line);
  lines.push_back(fmt::format(
      "record: npts={} dt={} t={}..{} pga_as_read={} {} scaling={} factor={} gravity={}",
      record.npts, record.dt ? number(*record.dt) : std::string("non-uniform"),
      number(record.t.front()), number(record.t.back()), number(record.pga_as_read),
      to_string(record.units), record.scaling, number(record.factor), number(record.gravity)));
  lines.push_back(
      "record: the ground acceleration is linear between samples and 0 before the first and "
      "after the last; x and v are relative to the ground");
  for (const std::string& note : record.notes) lines.push_back("record note: " + note);
  return lines;
}

void write_metadata(std::FILE* out, const Model& model, const std::string& command,
                    const std::vector<std::string>& extra_lines) {
  fmt::print(out, "# frictionref {}\n# model: {}\n# command: {}\n", version,
             model_fields(model, number), command);
  if (model.ground_motion)
    for (const std::string& line : record_metadata(*model.ground_motion))
      fmt::print(out, "# {}\n", line);
  for (const std::string& line : extra_lines) fmt::print(out, "# {}\n", line);
}

void write_phase_header(std::FILE* out) {
  std::fputs("phase,t_begin,t_end,x_begin,x_end,v_begin,v_end\n", out);
}

void write_phase_row(std::FILE* out, const Phase& phase) {
  fmt::basic_memory_buffer<char, 256> text;  // as write_state_rows
  fmt::format_to(std::back_inserter(text), FMT_COMPILE("{},{},{},{},{},{},{}\n"),
                 to_string(phase.kind), phase.t_begin, phase.t_end, phase.x_begin, phase.x_end,
                 phase.v_begin, phase.v_end);
  std::fwrite(text.data(), 1, text.size(), out);
}

void write_state_header(std::FILE* out) { std::fputs("t,x,v,a,phase\n", out); }

void write_state_rows(std::FILE* out, const StateRows& rows) {
  // One block of text per call, formatted with the format parsed at compile
  // time: fmt::print per row parsed it and locked the stream each time, which
  // cost more than computing the row (docs/benchmarks.md, "Seventh session").
  // The same text: fmt's shortest form either way.
  fmt::basic_memory_buffer<char, 8192> text;
  const std::string_view phase = to_string(rows.phase);
  for (std::size_t i = 0; i < rows.size; ++i)
    fmt::format_to(std::back_inserter(text), FMT_COMPILE("{},{},{},{},{}\n"), rows.t[i], rows.x[i],
                   rows.v[i], rows.a[i], phase);
  std::fwrite(text.data(), 1, text.size(), out);
}

}  // namespace frictionref::cli
