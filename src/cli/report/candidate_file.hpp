// The candidate file read once, as bytes: the report hashes exactly the bytes
// it compares. Refuses what read_time_history refuses (no name, a directory,
// a file that cannot be opened or read), with the same messages.
#pragma once

#include <string>

#include "frictionref/time_history.hpp"

namespace frictionref::cli {

struct CandidateFile {
  std::string path;   // as given; "-" for standard input
  std::string name;   // how the library names it: the path, or "standard input"
  std::string bytes;  // the whole content
};

// Reads `path` ("-": standard input). Throws InvalidInput with parameter
// "file", as read_time_history does.
CandidateFile read_candidate_file(const std::string& path);

// The time history in those bytes (parse_time_history; errors name the file
// and line as read_time_history's do).
TimeHistory parse_candidate(const CandidateFile& file, const TimeHistoryReadOptions& options);

}  // namespace frictionref::cli
