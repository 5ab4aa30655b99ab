// Figures through gnuplot: `curve --plot` writes a valid SVG or PNG next to
// (and atomically with) its table; a wrong extension or a missing gnuplot is
// bad input (exit 2, one line, no file of either kind).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

namespace fs = std::filesystem;

bool is_svg(const std::string& content) {
  return (content.rfind("<?xml", 0) == 0 || content.rfind("<svg", 0) == 0) &&
         content.find("</svg>") != std::string::npos;
}

bool is_png(const std::string& content) {
  return content.size() > 100 && content.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// PATH without gnuplot for the lifetime of the object.
class PathWithoutGnuplot {
 public:
  PathWithoutGnuplot() : saved_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    setenv("PATH", "/nonexistent-frictionref-test", 1);
  }
  ~PathWithoutGnuplot() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

TEST(Figures, CurvePlotWritesSvgAndPng) {
  TempDir dir;
  for (const std::string name : {"v.svg", "v.png"}) {
    const RunResult result = run_frictionref(
        {"curve", "--lambda", "0.7", "--t-end", "30", "--dt", "0.01", "--include-events", "-o",
         "curve.csv", "--plot", name},
        dir.path());
    ASSERT_TRUE(succeeded(result)) << name;
    const std::string figure = read_file(dir.path() / name);
    const bool svg = name == "v.svg";
    EXPECT_TRUE(svg ? is_svg(figure) : is_png(figure)) << name;
    if (svg) {
      // Axis labels carry units; the exact solution is in the legend.
      EXPECT_NE(figure.find("v [length/time]"), std::string::npos);
      EXPECT_NE(figure.find("t [time]"), std::string::npos);
      EXPECT_NE(figure.find("exact"), std::string::npos);
    }
    EXPECT_GT(fs::file_size(dir.path() / "curve.csv"), 1000u);
  }
  for (const std::string& entry : dir.entries())
    EXPECT_EQ(entry.find(".tmp."), std::string::npos) << entry;
}

TEST(Figures, WrongExtensionIsBadInput) {
  TempDir dir;
  const RunResult result = run_frictionref(
      {"curve", "--lambda", "0.7", "--t-end", "3", "--dt", "0.1", "-o", "c.csv", "--plot", "v.pdf"},
      dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--plot = v.pdf"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(".svg or .png"), std::string::npos) << result.err;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Figures, MissingGnuplotIsOneClearLineAndNoFiles) {
  TempDir dir;
  RunResult result;
  {
    PathWithoutGnuplot no_gnuplot;
    result = run_frictionref({"curve", "--lambda", "0.7", "--t-end", "3", "--dt", "0.1", "-o",
                              "c.csv", "--plot", "v.svg"},
                             dir.path());
  }
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("gnuplot"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("--plot"), std::string::npos) << result.err;
  EXPECT_TRUE(dir.entries().empty());
}

// reproduce draws figures by default: without gnuplot it says how to get it,
// or how to do without (--no-figures), and writes nothing.
TEST(Figures, ReproduceWithoutGnuplotNamesTheWayOut) {
  TempDir dir;
  RunResult result;
  {
    PathWithoutGnuplot no_gnuplot;
    result = run_frictionref({"reproduce", "--out", "r"}, dir.path());
  }
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("gnuplot"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("--no-figures"), std::string::npos) << result.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace frictionref::cli_test
