// docs/reliability.md lists every rejected input with the exact line the
// program prints. This runs each row of that table through the real binary:
// exit code 2, nothing on stdout, exactly that line on stderr, and no file
// left in the working directory. The doc cannot drift from the program.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

struct DocumentedRejection {
  std::vector<std::string> args;  // after "frictionref"
  std::string message;            // the stderr line, without its newline
};

// Table rows "| `frictionref ARGS` | `MESSAGE` |", with "\|" for "|".
std::vector<DocumentedRejection> documented_rejections() {
  const std::string doc =
      read_file(std::filesystem::path(FRICTIONREF_SOURCE_DIR) / "docs/reliability.md");
  std::vector<DocumentedRejection> rows;
  for (const std::string& line : lines(doc)) {
    if (line.rfind("| `frictionref ", 0) != 0) continue;
    std::vector<std::string> cells;  // the two code spans
    std::string cell;
    bool in_code = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
        cell += '|';
        ++i;
      } else if (line[i] == '`') {
        if (in_code) cells.push_back(cell);
        cell.clear();
        in_code = !in_code;
      } else if (in_code) {
        cell += line[i];
      }
    }
    if (cells.size() != 2) {
      ADD_FAILURE() << "malformed row: " << line;
      continue;
    }
    DocumentedRejection row;
    std::istringstream words(cells[0]);
    for (std::string word; words >> word;) row.args.push_back(word);
    row.args.erase(row.args.begin());  // "frictionref"
    row.message = cells[1];
    rows.push_back(row);
  }
  return rows;
}

TEST(ReliabilityDoc, EveryDocumentedRejectionIsExactlyWhatTheProgramSays) {
  const std::vector<DocumentedRejection> rows = documented_rejections();
  EXPECT_GE(rows.size(), 40u);
  for (const DocumentedRejection& row : rows) {
    SCOPED_TRACE(row.message);
    TempDir dir;
    const RunResult result = run_frictionref(row.args, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_TRUE(result.out.empty()) << result.out;
    EXPECT_EQ(result.err, row.message + "\n");
    EXPECT_TRUE(dir.entries().empty());
  }
}

}  // namespace
}  // namespace frictionref::cli_test
