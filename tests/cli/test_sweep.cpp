// `frictionref sweep`: the columns and metadata, values against the
// independent reference motion, the regimes against the threshold, the same
// output for any --threads, -o atomic (also when interrupted), the figure,
// the progress line (on a terminal only, cleared at the end), and every bad
// input (one line, exit 2, no file).
#include <gtest/gtest.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bad_input.hpp"
#include "csv_reader.hpp"
#include "reference_motion.hpp"
#include "run_binary.hpp"
#include "test_support.hpp"

namespace frictionref::cli_test {
namespace {

constexpr long double kPi = 3.14159265358979323846264338327950288L;
// mpmath: 2/sqrt(4+pi**2)
constexpr long double kLambdaStar = 0.5370292721463150768526284L;

const char* const kHeader =
    "lambda,regime_simulated,regime_threshold,stuck_fraction,slide_per_period,stops_per_period,"
    "reversals_per_period";

std::size_t column(const Csv& csv, const std::string& name) { return csv.column(name); }

// Sets an environment variable for the lifetime of the object (children inherit it).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    const char* old = std::getenv(name);
    had_ = old != nullptr;
    if (had_) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (had_)
      setenv(name_.c_str(), old_.c_str(), 1);
    else
      unsetenv(name_.c_str());
  }

 private:
  std::string name_, old_;
  bool had_ = false;
};

TEST(Sweep, ColumnsMetadataAndRegimes) {
  const RunResult result = run_frictionref(
      {"sweep", "--lambda-from", "0", "--lambda-to", "1.2", "--points", "13", "--periods", "20"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  EXPECT_EQ(csv.header, kHeader);
  ASSERT_EQ(csv.rows.size(), 13u);
  EXPECT_EQ(csv.metadata.at(0), std::string("frictionref ") + FRICTIONREF_EXPECTED_VERSION);
  EXPECT_EQ(csv.meta("model"),
            "mass=1 amplitude=1 omega=1 friction=lambda lambda=lambda x0=0 v0=0 t0=0");
  EXPECT_EQ(csv.meta("command"),
            "frictionref sweep --lambda-from 0 --lambda-to 1.2 --points 13 --periods 20");
  const auto sweep = key_values(csv.meta("sweep"));
  EXPECT_EQ(sweep.at("lambda_from"), "0");
  EXPECT_EQ(sweep.at("lambda_to"), "1.2");
  EXPECT_EQ(sweep.at("points"), "13");
  EXPECT_EQ(sweep.at("periods"), "20");
  EXPECT_EQ(sweep.at("threshold"), "0.5370292721463151");
  EXPECT_NEAR(to_double(sweep.at("measured_from")), static_cast<double>(2 * kPi * 19 + kPi / 2),
              1e-12);
  EXPECT_NEAR(to_double(sweep.at("measured_to")), static_cast<double>(2 * kPi * 20 + kPi / 2),
              1e-12);
  EXPECT_EQ(csv.meta("regimes").rfind("simulated and threshold differ at 0 of 13 lambdas", 0), 0u)
      << csv.meta("regimes");

  const std::size_t lambda = column(csv, "lambda"), simulated = column(csv, "regime_simulated");
  const std::size_t threshold = column(csv, "regime_threshold");
  const std::size_t stops = column(csv, "stops_per_period");
  const std::size_t reversals = column(csv, "reversals_per_period");
  const std::size_t stuck = column(csv, "stuck_fraction");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const std::vector<std::string>& row = csv.rows[i];
    SCOPED_TRACE(row[lambda]);
    const double l = to_double(row[lambda]);
    EXPECT_EQ(l, static_cast<double>(i) / 10);  // the doubles nearest the decimal grid
    const std::string expected = l < kLambdaStar ? "continuous" : l < 1 ? "dead-bands" : "stops";
    EXPECT_EQ(row[threshold], expected);
    EXPECT_EQ(row[simulated], expected);
    EXPECT_EQ(row[stops], expected == "dead-bands" ? "2" : "0");
    EXPECT_EQ(row[reversals], expected == "continuous" && l > 0 ? "2" : "0");
    const double fraction = to_double(row[stuck]);
    EXPECT_EQ(fraction == 0, expected == "continuous");
    EXPECT_EQ(fraction == 1, expected == "stops");
  }
}

// Against the independent reference solver of the CLI tests (long double,
// bisection; no library code): the time at rest and the distance slid over
// [2 pi (P - 1) + pi/2, 2 pi P + pi/2].
TEST(Sweep, FiguresAgreeWithTheReferenceMotion) {
  const long double periods = 4;
  const long double begin = 2 * kPi * (periods - 1) + kPi / 2, end = 2 * kPi * periods + kPi / 2;
  const RunResult result = run_frictionref({"sweep", "--lambda-from", "0.3", "--lambda-to", "0.7",
                                            "--points", "3", "--periods", "4", "--v0", "0.5"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  ASSERT_EQ(csv.rows.size(), 3u);
  for (const std::vector<std::string>& row : csv.rows) {
    const long double lambda = to_double(row[0]);
    SCOPED_TRACE(row[0]);
    const ReferenceMotion motion(lambda, 0.5L, end);
    long double rest = 0, slide = 0;
    int stops = 0, reversals = 0;
    std::string previous;
    for (const RefPhase& p : motion.phases()) {
      if (p.t_end > begin) {
        const long double from = std::max(p.t_begin, begin);
        if (p.kind == "stick") {
          rest += p.t_end - from;
        } else {
          const long double x_from = p.t_begin >= begin ? p.x_begin : motion.state(p, begin).x;
          slide += std::fabs(p.x_end - x_from);
        }
        if (p.t_begin >= begin && !previous.empty()) {
          stops += previous != "stick" && p.kind == "stick";
          reversals += previous != "stick" && p.kind != "stick" && p.kind != previous;
        }
      }
      previous = p.kind;
    }
    EXPECT_NEAR(to_double(row[3]), static_cast<double>(rest / (2 * kPi)), 1e-12);
    EXPECT_NEAR(to_double(row[4]), static_cast<double>(slide), 1e-11);
    EXPECT_EQ(row[5], std::to_string(stops));
    EXPECT_EQ(row[6], std::to_string(reversals));
  }
  EXPECT_EQ(csv.rows[0][6], "2");  // 0.3: reversals
  EXPECT_EQ(csv.rows[2][5], "2");  // 0.7: stops
}

TEST(Sweep, OneLambda) {
  const RunResult result =
      run_frictionref({"sweep", "--lambda-from", "0.7", "--lambda-to", "0.7", "--points", "1"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  ASSERT_EQ(csv.rows.size(), 1u);
  // theory.md 5.8: stuck fraction 0.221920695194, slide 2 x 0.432493939724.
  EXPECT_EQ(csv.rows[0][0], "0.7");
  EXPECT_NEAR(to_double(csv.rows[0][3]), 0.221920695194, 1e-12);
  EXPECT_NEAR(to_double(csv.rows[0][4]), 0.864987879448, 1e-11);
}

TEST(Sweep, SameOutputForAnyNumberOfThreads) {
  const std::vector<std::string> args = {"sweep", "--lambda-from", "0",   "--lambda-to",
                                         "1.2",   "--points",      "241", "--periods",
                                         "10",    "--v0",          "-0.3"};
  std::string first;
  for (const char* threads : {"1", "2", "5"}) {
    std::vector<std::string> with = args;
    with.insert(with.end(), {"--threads", threads});
    const RunResult result = run_frictionref(with);
    ASSERT_TRUE(succeeded(result));
    // Everything but the command line, which names --threads.
    const std::string body = result.out.substr(result.out.find("# sweep:"));
    if (first.empty()) first = body;
    EXPECT_EQ(body, first) << threads;
  }
}

TEST(Sweep, OutputFileIsWhatStdoutGetsAndFigureIsDrawn) {
  TempDir dir;
  const std::vector<std::string> args = {
      "sweep", "--lambda-from", "0.4", "--lambda-to", "1.1", "--points", "36", "--periods", "5"};
  const RunResult to_stdout = run_frictionref(args, dir.path());
  ASSERT_TRUE(succeeded(to_stdout));
  std::vector<std::string> to_files = args;
  to_files.insert(to_files.end(), {"-o", "s.csv", "--plot", "s.svg"});
  const RunResult result = run_frictionref(to_files, dir.path());
  ASSERT_TRUE(succeeded(result));
  EXPECT_TRUE(result.out.empty());
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"s.csv", "s.svg"}));
  const std::string file = read_file(dir.path() / "s.csv");
  // Only the command line differs.
  EXPECT_EQ(file.substr(file.find("# sweep:")),
            to_stdout.out.substr(to_stdout.out.find("# sweep:")));
  const std::string svg = read_file(dir.path() / "s.svg");
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("lambda = R / B [1]"), std::string::npos);
  EXPECT_NE(svg.find("stuck fraction [1]"), std::string::npos);
  EXPECT_NE(svg.find("0.5370292721463151"), std::string::npos);  // lambda* in the title

  const RunResult png = run_frictionref(
      {"sweep", "--lambda-from", "0.7", "--lambda-to", "0.7", "--points", "1", "--plot", "p.png"},
      dir.path());
  ASSERT_TRUE(succeeded(png));
  const std::string image = read_file(dir.path() / "p.png");
  EXPECT_EQ(image.compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);
}

TEST(Sweep, InterruptedRunLeavesNothing) {
  TempDir dir;
  const int pid = spawn_frictionref({"sweep", "--lambda-from", "0", "--lambda-to", "1", "--points",
                                     "100000", "--periods", "1000", "-o", "s.csv"},
                                    dir.path());
  bool writing = false;
  for (int i = 0; i < 1000 && !writing; ++i) {
    for (const std::string& name : dir.entries()) writing |= name.rfind("s.csv.tmp.", 0) == 0;
    if (!writing) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(writing);  // -o is opened before the run, so a bad path fails at once
  kill(pid, SIGINT);
  EXPECT_EQ(wait_exit_code(pid), 128 + SIGINT);
  EXPECT_TRUE(dir.entries().empty()) << "left behind: " << dir.entries().front();
}

// ---- the general model -----------------------------------------------------------

// A spring without damper, m = B = k = 1, w = 2 (beta = 2): Den Hartog's
// non-stop solution holds below lambda = 4 / (3 sqrt 5) = 0.59628479399994
// (theory.md 8.2, closed form in tests/steady_state_values.py): there the
// closed form gives `continuous`, above it n/a, and the simulation shows
// stops above it.
TEST(SweepGeneral, SpringAgainstDenHartogsBoundary) {
  const RunResult result =
      run_frictionref({"sweep", "--lambda-from", "0.1", "--lambda-to", "0.9", "--points", "9",
                       "--stiffness", "1", "--omega", "2"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  EXPECT_EQ(csv.header, kHeader);
  EXPECT_EQ(csv.meta("model"),
            "mass=1 amplitude=1 omega=2 friction=lambda lambda=lambda stiffness=1 x0=0 v0=0 t0=0");
  const auto sweep = key_values(csv.meta("sweep"));
  EXPECT_EQ(sweep.at("threshold"), "den-hartog");
  EXPECT_EQ(sweep.at("frequency_ratio"), "2");
  EXPECT_NEAR(to_double(sweep.at("den_hartog_boundary")), 0.59628479399994392, 1e-11);
  // The window is in user time: (2 pi P + pi/2) / w.
  EXPECT_NEAR(to_double(sweep.at("measured_to")), static_cast<double>((2 * kPi * 100 + kPi / 2) / 2),
              1e-12);
  EXPECT_EQ(csv.meta("regimes").rfind("Den Hartog's closed form gives the regime", 0), 0u);
  ASSERT_EQ(csv.rows.size(), 9u);
  for (const std::vector<std::string>& row : csv.rows) {
    SCOPED_TRACE(row[0]);
    if (to_double(row[0]) < 0.59628479399994392) {
      EXPECT_EQ(row[1], "continuous");
      EXPECT_EQ(row[2], "continuous");
      EXPECT_EQ(row[5], "0");
      EXPECT_EQ(row[6], "2");
    } else {
      EXPECT_EQ(row[1], "dead-bands");
      EXPECT_EQ(row[2], "n/a");
      EXPECT_EQ(row[5], "2");
    }
  }
}

// k = 0, F0 = 0.5, static friction 1.2 R: every model option the sweep takes
// is recorded, the threshold is n/a, and the regimes are what the forces
// allow: R = 0.2 < F0 drifts forward for ever (no stop, no reversal; slide
// over the window from x = 0.3 t^2 / 2 + t - sin t), 0.5 < R and
// Rs = 1.2 R < B + F0 = 1.5 slides forward once per period, Rs >= 1.5
// never moves.
TEST(SweepGeneral, ConstantForceAndStaticFriction) {
  const RunResult result = run_frictionref(
      {"sweep", "--lambda-from", "0.2", "--lambda-to", "1.4", "--points", "3", "--force-offset",
       "0.5", "--static-ratio", "1.2", "--mass", "1", "--harmonic", "0,3", "--periods", "30"});
  ASSERT_TRUE(succeeded(result));
  const Csv csv = parse_csv(result.out);
  EXPECT_EQ(csv.meta("model"),
            "mass=1 amplitude=1 omega=1 friction=lambda lambda=lambda "
            "static_friction=1.2*friction force_offset=0.5 harmonic=0,3,0 x0=0 v0=0 t0=0");
  EXPECT_EQ(key_values(csv.meta("sweep")).at("threshold"), "none");
  EXPECT_EQ(csv.meta("regimes").rfind("no closed form gives the regime", 0), 0u);
  ASSERT_EQ(csv.rows.size(), 3u);
  for (const std::vector<std::string>& row : csv.rows) EXPECT_EQ(row[2], "n/a") << row[0];
  EXPECT_EQ(csv.rows[0][1], "continuous");
  EXPECT_EQ(csv.rows[0][5] + csv.rows[0][6], "00");
  const long double end = 2 * kPi * 30 + kPi / 2, begin = end - 2 * kPi;
  const auto x = [](long double t) { return 0.3L * t * t / 2 + t - std::sin(t); };
  // Two positions of ~1.4e4 (ulp 1.8e-12), a few ulps each.
  EXPECT_NEAR(to_double(csv.rows[0][4]), static_cast<double>(x(end) - x(begin)), 3e-11);
  EXPECT_EQ(csv.rows[1][1], "dead-bands");  // lambda 0.8: Rs = 0.96 < 1.5
  EXPECT_EQ(csv.rows[1][5], "1");
  EXPECT_EQ(csv.rows[2][1], "stops");  // lambda 1.4: Rs = 1.68 >= 1.5
  EXPECT_EQ(csv.rows[2][3], "1");
}

// ---- progress ----------------------------------------------------------------

// Runs the binary on a pseudo-terminal (stdout and stderr both on it) and
// returns everything it printed there.
std::string run_on_terminal(const std::vector<std::string>& args, const std::string& cwd,
                            int& exit_code) {
  const std::string binary = FRICTIONREF_BINARY;
  std::vector<std::string> words{binary};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) {
    ADD_FAILURE() << "forkpty failed";
    return {};
  }
  if (pid == 0) {
    if (chdir(cwd.c_str()) != 0) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(master, buffer, sizeof buffer);
    if (n > 0) {
      text.append(buffer, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // EIO once the child has closed the terminal
    }
  }
  close(master);
  exit_code = wait_exit_code(pid);
  return text;
}

TEST(SweepProgress, OnATerminalUpdatedInPlaceAndClearedAtTheEnd) {
  // The delay before the line appears (1 s) is set to 0 for the test; the
  // run must still last over 0.1 s, the interval of the updates (10^6
  // periods: ~0.8 s with the engine of docs/benchmarks.md).
  const ScopedEnv delay("FRICTIONREF_PROGRESS_DELAY", "0");
  TempDir dir;
  int exit_code = -1;
  const std::string screen =
      run_on_terminal({"sweep", "--lambda-from", "0.3", "--lambda-to", "0.8", "--points", "500",
                       "--periods", "2000", "--threads", "1", "-o", "s.csv"},
                      dir.path().string(), exit_code);
  EXPECT_EQ(exit_code, 0) << screen;
  EXPECT_NE(screen.find("\rfrictionref sweep: "), std::string::npos) << screen;
  EXPECT_NE(screen.find("/500 lambdas ("), std::string::npos) << screen;
  EXPECT_EQ(screen.find('\n'), std::string::npos) << screen;  // in place: never a new line
  // Cleared: the last thing on the terminal is a blanked line.
  ASSERT_GE(screen.size(), 2u);
  EXPECT_EQ(screen.back(), '\r');
  const std::size_t blank = screen.rfind('\r', screen.size() - 2);
  ASSERT_NE(blank, std::string::npos);
  EXPECT_EQ(screen.find_first_not_of(' ', blank + 1), screen.size() - 1) << screen;
  // The file has no trace of it.
  const std::string file = read_file(dir.path() / "s.csv");
  EXPECT_EQ(file.find("/500 lambdas"), std::string::npos);
  EXPECT_EQ(file.find('\r'), std::string::npos);
}

TEST(SweepProgress, NeverInFilesOrPipes) {
  const ScopedEnv delay("FRICTIONREF_PROGRESS_DELAY", "0");
  const RunResult result =
      run_frictionref({"sweep", "--lambda-from", "0.3", "--lambda-to", "0.8", "--points", "200",
                       "--periods", "200", "--threads", "1"});
  EXPECT_TRUE(succeeded(result));  // stderr empty
  EXPECT_EQ(result.out.find("/200 lambdas"), std::string::npos);
  EXPECT_EQ(result.out.find('\r'), std::string::npos);
}

// ---- bad input -----------------------------------------------------------------

std::vector<std::string> sweep_args(std::vector<std::string> extra) {
  std::vector<std::string> args = {"sweep", "--lambda-from", "0", "--lambda-to",
                                   "1.2",   "--points",      "5"};
  // A later occurrence of an option would be refused by CLI11; replace instead.
  for (std::size_t i = 0; i + 1 < extra.size(); i += 2) {
    bool replaced = false;
    for (std::size_t j = 1; j + 1 < args.size(); j += 2) {
      if (args[j] == extra[i]) {
        args[j + 1] = extra[i + 1];
        replaced = true;
      }
    }
    if (!replaced) args.insert(args.end(), {extra[i], extra[i + 1]});
  }
  args.insert(args.end(), {"-o", "out.csv"});
  return args;
}

class SweepBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SweepBadInput, IsOneLineExitTwoAndNoFile) { expect_rejected(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    Rules, SweepBadInput,
    ::testing::Values(
        BadInput{sweep_args({"--lambda-from", "-0.1"}), "--lambda-from = -0.1", "must be >= 0"},
        BadInput{sweep_args({"--lambda-from", "nan"}), "--lambda-from = nan", "finite"},
        BadInput{sweep_args({"--lambda-from", "abc"}), "--lambda-from = abc", "must be a number"},
        BadInput{sweep_args({"--lambda-to", "inf"}), "--lambda-to = inf", "finite"},
        BadInput{sweep_args({"--lambda-to", "2e6"}), "--lambda-to = 2e6", "<= 1e6"},
        BadInput{sweep_args({"--lambda-from", "0.7", "--lambda-to", "0.5"}), "--lambda-to = 0.5",
                 ">= --lambda-from = 0.7"},
        BadInput{sweep_args({"--points", "0"}), "--points = 0", "whole number >= 1"},
        BadInput{sweep_args({"--points", "2.5"}), "--points = 2.5", "whole number >= 1"},
        BadInput{sweep_args({"--points", "-3"}), "--points = -3", "whole number >= 1"},
        BadInput{sweep_args({"--points", "2e7"}), "--points = 2e7", "<= 10^7"},
        BadInput{sweep_args({"--points", "1"}), "--points = 1", "--lambda-to = --lambda-from"},
        BadInput{sweep_args({"--lambda-from", "0.5", "--lambda-to", "0.5"}), "--points = 5",
                 "must be 1"},
        BadInput{sweep_args({"--lambda-from", "0.5", "--lambda-to", "0.5000000000000002",
                             "--points", "10"}),
                 "--points = 10", "repeat"},
        BadInput{sweep_args({"--periods", "0"}), "--periods = 0", "whole number >= 1"},
        BadInput{sweep_args({"--periods", "1e7"}), "--periods = 1e7", "<= 10^6"},
        BadInput{sweep_args({"--points", "1e5", "--periods", "1e5"}), "--periods = 1e5",
                 "more than 10^9"},
        BadInput{sweep_args({"--threads", "0"}), "--threads = 0", "whole number >= 1"},
        BadInput{sweep_args({"--threads", "1000"}), "--threads = 1000", "<= 256"},
        BadInput{sweep_args({"--v0", "nan"}), "--v0 = nan", "finite"},
        BadInput{sweep_args({"--v0", "-1e7"}), "--v0 = -1e7", "<= 1e6"},
        BadInput{sweep_args({"--plot", "s.pdf"}), "--plot = s.pdf", ".svg or .png"},
        BadInput{{"sweep", "--lambda-to", "1", "--points", "3", "-o", "out.csv"},
                 "--lambda-from",
                 "required"},
        BadInput{{"sweep", "--lambda-from", "0", "--lambda-to", "1", "-o", "out.csv"},
                 "--points",
                 "required"},
        BadInput{sweep_args({"--lambda", "0.3"}), "--lambda = 0.3", "not a sweep option"},
        BadInput{sweep_args({"--friction", "0.3"}), "--friction = 0.3", "sets R = lambda B"},
        BadInput{sweep_args({"--static-lambda", "0.6"}), "--static-lambda = 0.6",
                 "--static-ratio"},
        BadInput{sweep_args({"--t0", "1"}), "--t0 = 1", "starts at t = 0"},
        BadInput{sweep_args({"--static-ratio", "0.5"}), "--static-ratio = 0.5", "must be >= 1"},
        BadInput{sweep_args({"--static-ratio", "nan"}), "--static-ratio = nan", "finite"},
        BadInput{sweep_args({"--static-ratio", "1e7"}), "--static-ratio = 1e7", "<= 1e6"},
        BadInput{sweep_args({"--stiffness", "-1"}), "--stiffness = -1", "must be >= 0"},
        BadInput{sweep_args({"--damping", "inf"}), "--damping = inf", "finite"},
        BadInput{sweep_args({"--mass", "0"}), "--mass = 0", "must be > 0"},
        BadInput{sweep_args({"--amplitude", "0"}), "--amplitude = 0", "must be > 0"},
        BadInput{sweep_args({"--harmonic", "1"}), "--harmonic = 1", "must be B,W or B,W,PHI"},
        BadInput{sweep_args({"--harmonic", "1,0"}), "--harmonic = 1,0", "W must be > 0"},
        BadInput{sweep_args({"--harmonic", "0.2,1.4142135623730951"}),
                 "--harmonic = 0.2,1.4142135623730951", "no common period"},
        BadInput{{"sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "-o",
                  "/proc/out.csv"},
                 "-o = /proc/out.csv",
                 "cannot create"}),
    bad_input_name);

TEST(Sweep, Help) {
  const RunResult result = run_frictionref({"sweep", "--help"});
  ASSERT_TRUE(succeeded(result));
  for (const char* part :
       {"--lambda-from", "--lambda-to", "--points", "--v0", "--periods", "--threads", "-o",
        "--plot", "--static-ratio", "--mass", "--stiffness", "--damping", "--force-offset",
        "--harmonic", "--x0", "n/a", "Den Hartog", "Exit codes", "Example",
        "frictionref sweep "}) {
    EXPECT_NE(result.out.find(part), std::string::npos) << part;
  }
  EXPECT_NE(run_frictionref({"--help"}).out.find("sweep"), std::string::npos);
}

}  // namespace
}  // namespace frictionref::cli_test
