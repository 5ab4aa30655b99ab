// `--shard I/N` on sweep and map, and `frictionref merge`: the N shards,
// merged in any order, give the unsharded study's table, rows character for
// character and '#' lines but for the command and one '# merged:' line;
// every way a set of shard files can be wrong is refused with exit 2, one
// line naming the file, and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    lines.push_back(text.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return lines;
}

// The table without its '# command:' and '# merged:' lines.
std::vector<std::string> without_provenance(const std::string& text) {
  std::vector<std::string> kept;
  for (const std::string& line : lines_of(text))
    if (line.rfind("# command: ", 0) != 0 && line.rfind("# merged: ", 0) != 0)
      kept.push_back(line);
  return kept;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Runs `study` whole and in `count` shards (merged in reverse order), and
// checks the merge against the whole table.
void expect_merge_is_whole(const std::vector<std::string>& study, int count) {
  TempDir dir;
  const RunResult whole = run_frictionref(study);
  ASSERT_TRUE(succeeded(whole)) << whole.err;
  std::vector<std::string> merge{"merge", "-o", (dir.path() / "merged.csv").string()};
  std::size_t rows = 0;
  for (int i = count; i >= 1; --i) {
    const fs::path file = dir.path() / ("shard-" + std::to_string(i) + ".csv");
    const RunResult shard = run_frictionref(
        with(study, {"--shard", std::to_string(i) + "/" + std::to_string(count), "-o",
                     file.string()}));
    ASSERT_TRUE(succeeded(shard)) << shard.err;
    const std::string text = read_file(file);
    EXPECT_NE(text.find("\n# shard: " + std::to_string(i) + "/" + std::to_string(count) + " rows "),
              std::string::npos);
    for (const std::string& line : lines_of(text)) rows += !line.empty() && line[0] != '#';
    --rows;  // its header
    merge.push_back(file.string());
  }
  const RunResult merged = run_frictionref(merge);
  ASSERT_TRUE(succeeded(merged)) << merged.err;
  const std::string text = read_file(dir.path() / "merged.csv");
  EXPECT_EQ(without_provenance(text), without_provenance(whole.out));
  // The rows: every shard's, none twice (counted above, header by header).
  std::size_t whole_rows = 0;
  for (const std::string& line : lines_of(whole.out)) whole_rows += !line.empty() && line[0] != '#';
  EXPECT_EQ(rows, whole_rows - 1);
  EXPECT_NE(text.find("\n# merged: " + std::to_string(count) + " shards (rows 1.."),
            std::string::npos);
  EXPECT_NE(text.find("\n# command: frictionref merge -o "), std::string::npos);
}

const std::vector<std::string> seed_sweep{"sweep", "--lambda-from", "0", "--lambda-to", "1.2",
                                          "--points", "25", "--periods", "30", "--threads", "2"};
const std::vector<std::string> map_study{"map",         "--x", "lambda:0.05:0.65:4", "--y",
                                         "frequency-ratio:0.5:2.5:3", "--stiffness", "1",
                                         "--periods",   "40",  "--threads", "2"};

TEST(Shard, SeedSweepMergesToTheWholeSweep) { expect_merge_is_whole(seed_sweep, 4); }

// Den Hartog's rule: the '# regimes:' line's counts are recounted over all rows.
TEST(Shard, SpringSweepMergesToTheWholeSweep) {
  expect_merge_is_whole({"sweep", "--lambda-from", "0.05", "--lambda-to", "0.8", "--points", "16",
                         "--stiffness", "1", "--omega", "2", "--periods", "40", "--threads", "1"},
                        3);
}

TEST(Shard, GeneralModelSweepMergesToTheWholeSweep) {
  expect_merge_is_whole({"sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "11",
                         "--static-ratio", "1.5", "--stiffness", "1", "--damping", "0.1",
                         "--harmonic", "0.3,3", "--periods", "20", "--threads", "2"},
                        2);
}

TEST(Shard, MapMergesToTheWholeMap) { expect_merge_is_whole(map_study, 5); }

// More shards than points: some shards are empty and still merge.
TEST(Shard, MoreShardsThanPointsLeavesEmptyShardsThatMerge) {
  expect_merge_is_whole({"sweep", "--lambda-from", "0.2", "--lambda-to", "0.8", "--points", "3",
                         "--periods", "10"},
                        5);
}

TEST(Shard, OneShardOfOneMergesToo) { expect_merge_is_whole(seed_sweep, 1); }

TEST(Shard, TheShardLineGivesItsBlockOfRows) {
  // 25 lambdas in 4 shards: floor(25 i / 4) = 0, 6, 12, 18, 25.
  const RunResult third = run_frictionref(with(seed_sweep, {"--shard", "3/4"}));
  ASSERT_TRUE(succeeded(third)) << third.err;
  EXPECT_NE(third.out.find("\n# shard: 3/4 rows 13..18 of 25\n"), std::string::npos) << third.out;
  const RunResult empty = run_frictionref(
      {"sweep", "--lambda-from", "0.2", "--lambda-to", "0.8", "--points", "3", "--shard", "1/5"});
  ASSERT_TRUE(succeeded(empty)) << empty.err;
  EXPECT_NE(empty.out.find("\n# shard: 1/5 rows none of 3\n"), std::string::npos) << empty.out;
}

struct BadShard {
  std::string value;
  std::string message;
};

TEST(Shard, MalformedShardOptionIsRefused) {
  for (const BadShard& bad : std::vector<BadShard>{
           {"0/4", "--shard = 0/4: must be I/N"},
           {"5/4", "--shard = 5/4: must be I/N"},
           {"1/0", "--shard = 1/0: must be I/N"},
           {"3", "--shard = 3: must be I/N"},
           {"1/2/3", "--shard = 1/2/3: must be I/N"},
           {"-1/4", "--shard = -1/4: must be I/N"},
           {"+1/4", "--shard = +1/4: must be I/N"},
           {" 1/4", "--shard =  1/4: must be I/N"},
           {"1/1000001", "--shard = 1/1000001: must be I/N"},
           {"1/99999999999999999999999", "must be I/N"},
       }) {
    for (const auto& study : {seed_sweep, map_study}) {
      TempDir dir;
      const RunResult result = run_frictionref(
          with(study, {"--shard", bad.value, "-o", (dir.path() / "out.csv").string()}));
      EXPECT_EQ(result.exit_code, 2) << bad.value;
      EXPECT_NE(result.err.find(bad.message), std::string::npos) << result.err;
      EXPECT_TRUE(dir.entries().empty()) << bad.value;
    }
  }
}

TEST(Shard, AShardCannotBeDrawn) {
  TempDir dir;
  const RunResult result = run_frictionref(
      with(map_study, {"--shard", "1/2", "--plot", (dir.path() / "map.svg").string()}));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--shard = 1/2: a shard holds part of the study and cannot be drawn"),
            std::string::npos)
      << result.err;
  EXPECT_TRUE(dir.entries().empty());
}

// The shard files of one study, for the merge's refusals.
class MergeRefuses : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 1; i <= 3; ++i) {
      const RunResult r = run_frictionref(with(seed_sweep, {"--shard", std::to_string(i) + "/3"}));
      ASSERT_TRUE(succeeded(r)) << r.err;
      write(file(i), r.out);
    }
  }
  fs::path file(int i) const { return dir.path() / ("s" + std::to_string(i) + ".csv"); }
  // Merges `files` into out.csv; expects exit 2, `message` on stderr, no out.csv.
  void expect_refused(const std::vector<fs::path>& files, const std::string& message) {
    std::vector<std::string> args{"merge", "-o", (dir.path() / "out.csv").string()};
    for (const fs::path& f : files) args.push_back(f.string());
    const RunResult result = run_frictionref(args);
    EXPECT_EQ(result.exit_code, 2) << message;
    EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "one line: " << result.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out.csv"));
  }
  TempDir dir;
};

TEST_F(MergeRefuses, AMissingShard) {
  expect_refused({file(1), file(3)}, "shard 2/3 is missing: 2 of the 3 shards given");
}

TEST_F(MergeRefuses, AShardGivenTwice) {
  expect_refused({file(1), file(2), file(2), file(3)}, "is shard 2/3, and so is");
}

TEST_F(MergeRefuses, ATruncatedShard) {
  const std::string text = read_file(file(2));
  write(file(2), text.substr(0, text.size() - 5));
  expect_refused({file(1), file(2), file(3)},
                 "s2.csv: does not end with a newline: it is incomplete");
}

TEST_F(MergeRefuses, AShardWithARowMissing) {
  std::string text = read_file(file(2));
  text.erase(text.rfind('\n', text.size() - 2) + 1);
  write(file(2), text);
  expect_refused({file(1), file(2), file(3)},
                 "s2.csv: holds 7 rows where its shard line gives 8: incomplete or edited");
}

TEST_F(MergeRefuses, AShardOfAnotherStudy) {
  const RunResult other = run_frictionref(
      {"sweep", "--lambda-from", "0", "--lambda-to", "1.2", "--points", "25", "--periods", "31",
       "--shard", "2/3"});
  ASSERT_TRUE(succeeded(other)) << other.err;
  write(file(2), other.out);
  expect_refused({file(1), file(2), file(3)}, "differ from");
}

TEST_F(MergeRefuses, AShardOfAnotherCount) {
  const RunResult other = run_frictionref(with(seed_sweep, {"--shard", "2/4"}));
  write(file(2), other.out);
  expect_refused({file(1), file(2), file(3)}, "s2.csv: is shard 2/4 of a study of 25 rows");
}

TEST_F(MergeRefuses, AWholeStudy) {
  const RunResult whole = run_frictionref(seed_sweep);
  write(file(2), whole.out);
  expect_refused({file(1), file(2), file(3)}, "s2.csv: has no '# shard:' line");
}

TEST_F(MergeRefuses, AnEditedShardLine) {
  std::string text = read_file(file(2));
  const std::size_t at = text.find("rows 9..16 of 25");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, 16, "rows 9..17 of 25");
  write(file(2), text);
  expect_refused({file(1), file(2), file(3)}, "gives rows 9..17 where shard 2/3 of 25 rows is rows 9..16");
}

TEST_F(MergeRefuses, FilesThatAreNotShardTables) {
  write(file(2), "");
  expect_refused({file(1), file(2), file(3)}, "s2.csv: is empty");
  write(file(2), "t,v\n0,1\n");
  expect_refused({file(1), file(2), file(3)}, "s2.csv: does not begin with '# frictionref'");
  write(file(2), std::string("#\0junk\n", 7));
  expect_refused({file(1), file(2), file(3)}, "s2.csv: line 1 starts with '#' but not '# '");
  expect_refused({file(1), dir.path() / "nonexistent.csv", file(3)},
                 "nonexistent.csv: cannot be read (No such file or directory)");
  expect_refused({file(1), dir.path(), file(3)}, ": not a regular file");
}

TEST(Merge, NeedsFiles) {
  const RunResult result = run_frictionref({"merge"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("files is required"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace frictionref::cli_test
