// Figures through gnuplot: `curve --plot` writes a valid SVG or PNG next to
// (and atomically with) its table; a wrong extension or a missing gnuplot is
// bad input (exit 2, one line, no file of either kind).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

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

// A general model's figure names every term of the model in its title,
// wrapped onto a second line rather than cut at the figure's edge.
TEST(Figures, GeneralModelTitleNamesEveryTerm) {
  TempDir dir;
  const RunResult result = run_frictionref(
      {"curve", "--lambda", "0.8", "--static-lambda", "1", "--stiffness", "0.5", "--damping",
       "0.05", "--force-offset", "0.2", "--harmonic", "0.5,3", "--harmonic", "0.3,0.5,1",
       "--t-end", "20", "--dt", "0.01", "-o", "curve.csv", "--plot", "v.svg"},
      dir.path());
  ASSERT_TRUE(succeeded(result)) << result.err;
  const std::string figure = read_file(dir.path() / "v.svg");
  ASSERT_TRUE(is_svg(figure));
  // The text elements of the figure, in order, joined by spaces: the title's
  // lines are consecutive elements.
  std::vector<std::string> texts;
  for (std::size_t at = figure.find("<text>"); at != std::string::npos;
       at = figure.find("<text>", at + 1)) {
    const std::size_t end = figure.find("</text>", at);
    ASSERT_NE(end, std::string::npos);
    texts.push_back(figure.substr(at + 6, end - at - 6));
  }
  ASSERT_GE(texts.size(), 2u);
  ASSERT_EQ(texts[0].rfind("frictionref exact solution:", 0), 0u) << texts[0];
  EXPECT_LT(texts[0].size(), 120u) << "the first line is cut at the figure's edge";
  const std::string title = texts[0] + " " + texts[1];
  for (const char* term : {"R=0.8", "Rs=1", "k=0.5", "c=0.05", "F0=0.2", "+0.5 sin(3 t)",
                           "+0.3 sin(0.5 t + 1)", "x0=0 v0=0 t0=0"})
    EXPECT_NE(title.find(term), std::string::npos) << term << " in " << title;
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
