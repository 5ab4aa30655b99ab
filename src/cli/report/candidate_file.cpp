// Reading the candidate as bytes (candidate_file.hpp).
#include "candidate_file.hpp"

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "frictionref/error.hpp"
#include "frictionref/time_history.hpp"

namespace frictionref::cli {
namespace {

std::string read_all(std::istream& in, const std::string& name) {
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InvalidInput("file", name, "cannot be read (input error)");
  return bytes;
}

}  // namespace

CandidateFile read_candidate_file(const std::string& path) {
  CandidateFile file;
  file.path = path;
  if (path == "-") {
    file.name = "standard input";
    file.bytes = read_all(std::cin, file.name);
    return file;
  }
  file.name = path;
  std::ifstream in = open_time_history_file(path);
  file.bytes = read_all(in, path);
  return file;
}

TimeHistory parse_candidate(const CandidateFile& file, const TimeHistoryReadOptions& options) {
  std::istringstream in(file.bytes, std::ios::binary);
  return parse_time_history(in, file.name, options);
}

}  // namespace frictionref::cli
