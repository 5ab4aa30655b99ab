// -o FILE: written atomically (a temporary file, then rename), never partial.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "csv_reader.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

// The output without its "# command:" line, which differs by the -o itself.
std::string without_command_line(const std::string& text) {
  std::string result;
  for (const std::string& line : lines(text)) {
    if (line.rfind("# command:", 0) != 0) result += line + "\n";
  }
  return result;
}

class OutputFile : public ::testing::TestWithParam<const char*> {
 protected:
  std::vector<std::string> command(const std::vector<std::string>& extra) const {
    std::vector<std::string> args;
    if (std::string(GetParam()) == "events") {
      args = {"events", "--lambda", "0.7", "--t-end", "30"};
    } else {
      args = {"curve", "--lambda", "0.7", "--t-end", "30", "--dt", "0.01", "--include-events"};
    }
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
};

TEST_P(OutputFile, WritesTheSameAsStdoutAndNothingElse) {
  TempDir dir;
  const RunResult to_stdout = run_frictionref(command({}));
  ASSERT_TRUE(succeeded(to_stdout));
  const RunResult to_file = run_frictionref(command({"-o", "out.csv"}), dir.path());
  ASSERT_TRUE(succeeded(to_file));
  EXPECT_TRUE(to_file.out.empty()) << to_file.out;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});  // no temporary left over
  const std::string written = read_file(dir.path() / "out.csv");
  EXPECT_EQ(without_command_line(written), without_command_line(to_stdout.out));
  EXPECT_NE(parse_csv(written).meta("command").find("-o out.csv"), std::string::npos);
}

TEST_P(OutputFile, ReplacesAnExistingFile) {
  TempDir dir;
  { std::ofstream(dir.path() / "out.csv") << "old\n"; }
  ASSERT_TRUE(succeeded(run_frictionref(command({"-o", "out.csv"}), dir.path())));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
  EXPECT_EQ(read_file(dir.path() / "out.csv").rfind("# frictionref ", 0), 0u);
}

// mkstemp creates 0600; the finished file must get the usual 0666 & ~umask.
TEST_P(OutputFile, UsualPermissions) {
  TempDir dir;
  const mode_t old_mask = umask(022);  // inherited by the child
  const RunResult result = run_frictionref(command({"-o", "out.csv"}), dir.path());
  umask(old_mask);
  ASSERT_TRUE(succeeded(result));
  struct stat info {};
  ASSERT_EQ(stat((dir.path() / "out.csv").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST_P(OutputFile, BadInputLeavesAnExistingFileAlone) {
  TempDir dir;
  { std::ofstream(dir.path() / "out.csv") << "old\n"; }
  const RunResult result = run_frictionref(command({"--mass", "-1", "-o", "out.csv"}), dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(read_file(dir.path() / "out.csv"), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
}

TEST_P(OutputFile, MissingDirectoryIsBadInput) {
  TempDir dir;
  const RunResult result = run_frictionref(command({"-o", "no/such/dir/out.csv"}), dir.path());
  EXPECT_EQ(result.exit_code, 2);
  ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("-o = no/such/dir/out.csv"), std::string::npos) << result.err;
  EXPECT_TRUE(result.out.empty());
  EXPECT_TRUE(dir.entries().empty());
}

TEST_P(OutputFile, DirectoryAsFileIsBadInput) {
  TempDir dir;
  fs::create_directory(dir.path() / "out.csv");
  const RunResult result = run_frictionref(command({"-o", "out.csv"}), dir.path());
  EXPECT_EQ(result.exit_code, 2);
  ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("-o"), std::string::npos) << result.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
  EXPECT_TRUE(fs::is_empty(dir.path() / "out.csv"));
}

TEST_P(OutputFile, EmptyNameIsBadInput) {
  TempDir dir;
  const RunResult result = run_frictionref(command({"-o", ""}), dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_TRUE(dir.entries().empty());
}

INSTANTIATE_TEST_SUITE_P(Commands, OutputFile, ::testing::Values("events", "curve"),
                         [](const ::testing::TestParamInfo<const char*>& case_info) {
                           return std::string(case_info.param);
                         });

// Killed while writing (Ctrl-C, kill): the temporary file goes too.
TEST(OutputFileSignal, InterruptedRunLeavesNothing) {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    TempDir dir;
    const int pid = spawn_frictionref(
        {"events", "--lambda", "0.3", "--t-end", "1e8", "--summary", "-o", "s.txt"}, dir.path());
    // Wait (at most 10 s) until the temporary file exists, so the signal
    // really arrives in the middle of a write.
    bool writing = false;
    for (int i = 0; i < 1000 && !writing; ++i) {
      for (const std::string& name : dir.entries()) writing |= name.rfind("s.txt.tmp.", 0) == 0;
      if (!writing) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(writing);
    kill(pid, signal_number);
    EXPECT_EQ(wait_exit_code(pid), 128 + signal_number);
    EXPECT_TRUE(dir.entries().empty()) << "left behind: " << dir.entries().front();
  }
}

// The other long-running writers clean up the same way: stiff, and curve
// with a figure pending (two outputs in flight).
TEST(OutputFileSignal, InterruptedStiffAndCurveWithFigureLeaveNothing) {
  const std::vector<std::vector<std::string>> runs = {
      {"stiff", "--lambda", "0.7", "--t-end", "1e6", "-o", "s.csv"},
      {"curve", "--lambda", "0.7", "--t-end", "1e7", "--dt", "0.01", "--force", "-o", "s.csv",
       "--plot", "s.svg"},
  };
  for (const auto& args : runs) {
    TempDir dir;
    const int pid = spawn_frictionref(args, dir.path());
    bool writing = false;
    for (int i = 0; i < 1000 && !writing; ++i) {
      for (const std::string& name : dir.entries()) writing |= name.rfind("s.csv.tmp.", 0) == 0;
      if (!writing) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(writing) << args[0];
    kill(pid, SIGTERM);
    EXPECT_EQ(wait_exit_code(pid), 128 + SIGTERM);
    EXPECT_TRUE(dir.entries().empty()) << args[0] << " left behind: " << dir.entries().front();
  }
}

// A full disk (/dev/full fails every write with ENOSPC) is one clear line and
// exit 2; the device itself is written in place, never replaced by a rename.
TEST(OutputFileHostile, FullDiskIsOneClearLine) {
  const std::vector<std::vector<std::string>> runs = {
      {"events", "--lambda", "0.7", "--t-end", "30", "-o", "/dev/full"},
      {"curve", "--lambda", "0.7", "--t-end", "30", "--dt", "0.01", "-o", "/dev/full"},
      {"stiff", "--lambda", "0.7", "--t-end", "30", "-o", "/dev/full"},
      {"convergence", "--lambda", "0.7", "--kf-list", "1e6", "--dt-fractions", "0.1", "-o",
       "/dev/full"},
  };
  for (const auto& args : runs) {
    const RunResult result = run_frictionref(args);
    EXPECT_EQ(result.exit_code, 2) << args[0];
    ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
    EXPECT_NE(result.err.find("-o = /dev/full"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("No space left on device"), std::string::npos) << result.err;
    EXPECT_TRUE(std::filesystem::is_character_file("/dev/full"));
  }
  EXPECT_FALSE(std::filesystem::exists("/dev/full.tmp.XXXXXX"));
}

// A place nobody may create files in, not even root: one line, exit 2.
TEST(OutputFileHostile, UnwritablePathIsOneClearLine) {
  const RunResult result =
      run_frictionref({"events", "--lambda", "0.7", "--t-end", "30", "-o", "/proc/out.csv"});
  EXPECT_EQ(result.exit_code, 2);
  ASSERT_EQ(lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("-o = /proc/out.csv"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists("/proc/out.csv"));
}

// A symbolic link stays a link; the file it points to is replaced.
TEST(OutputFileHostile, SymlinkKeepsPointingAtTheNewFile) {
  TempDir dir;
  std::filesystem::create_symlink("real.csv", dir.path() / "link.csv");
  {
    std::ofstream(dir.path() / "real.csv") << "old\n";
  }
  ASSERT_TRUE(succeeded(
      run_frictionref({"events", "--lambda", "0.7", "--t-end", "3", "-o", "link.csv"}, dir.path())));
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path() / "link.csv"));
  EXPECT_NE(read_file(dir.path() / "real.csv").find("phase,t_begin"), std::string::npos);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "real.csv"}));
}

// Writing to a pipe or terminal device by name works (no rename over it).
TEST(OutputFileHostile, DeviceTargetIsWrittenInPlace) {
  const RunResult result =
      run_frictionref({"events", "--lambda", "0.7", "--t-end", "3", "-o", "/dev/stdout"});
  ASSERT_TRUE(succeeded(result));
  EXPECT_NE(result.out.find("phase,t_begin,t_end"), std::string::npos) << result.out;
}

TEST(OutputFileSummary, SummaryGoesToTheFileToo) {
  TempDir dir;
  const RunResult result = run_frictionref(
      {"events", "--lambda", "0.7", "--t-end", "30", "--summary", "-o", "s.txt"}, dir.path());
  ASSERT_TRUE(succeeded(result));
  EXPECT_TRUE(result.out.empty());
  EXPECT_EQ(lines(read_file(dir.path() / "s.txt")).size(), 1u);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.txt"});
}

}  // namespace
}  // namespace frictionref::cli_test
