// The validation report as one self-contained HTML page: provenance, model,
// verdict and checks, figures (inline SVG), the event-matching table, and the
// commands that reproduce it. No script and nothing loaded from anywhere:
// it renders the same offline, attached to a report or printed.
#pragma once

#include <string>

#include "candidate_file.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/time_history.hpp"
#include "reproduce_commands.hpp"

namespace frictionref::cli {

struct ReportSources {
  const ComparisonReport& report;
  const TimeHistory& history;
  const CandidateFile& candidate;
  std::string sha256;        // of candidate.bytes
  std::string command_line;  // this run, shell-quoted
  std::string date;          // when it ran, "2025-01-31 12:00:00 UTC"
  ReproduceCommands commands;
};

// Rows of the event-matching tables shown; the rest are counted (the JSON of
// `compare --json` has them all).
constexpr std::size_t max_table_rows = 1000;

std::string report_page(const ReportSources& sources);

}  // namespace frictionref::cli
