// Reading the candidate as bytes (candidate_file.hpp).
#include "candidate_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "frictionref/error.hpp"

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
  file.bytes = read_all(in, path);
  return file;
}

TimeHistory parse_candidate(const CandidateFile& file, const TimeHistoryReadOptions& options) {
  std::istringstream in(file.bytes, std::ios::binary);
  return parse_time_history(in, file.name, options);
}

}  // namespace frictionref::cli
