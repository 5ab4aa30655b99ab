#include "figure.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "atomic_output.hpp"
#include "cli_error.hpp"

extern char** environ;

namespace frictionref::cli {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A gnuplot string literal: double quotes, with \ and " escaped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// `text` broken at spaces into lines of at most `width` characters (a word
// longer than that gets a line of its own): a general model's title is too
// long for one line of the figure.
std::vector<std::string> wrapped(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

// Lines as one gnuplot string literal, joined by its newline escape.
std::string quoted_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) {
    const std::string q = quoted(line);
    out += out.empty() ? q.substr(0, q.size() - 1) : "\\n" + q.substr(1, q.size() - 2);
  }
  return out + "\"";
}

// A scratch file in the system temporary directory, removed at scope exit.
class ScratchFile {
 public:
  explicit ScratchFile(const char* stem) {
    std::string name = (fs::temp_directory_path() / (std::string(stem) + ".XXXXXX")).string();
    const int fd = mkstemp(name.data());
    if (fd < 0) throw bad_input(fmt::format("cannot create a temporary file for gnuplot: {}",
                                            std::strerror(errno)));
    close(fd);
    path_ = name;
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

const char* const candidate_colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd"};

// One block per series, blocks separated by two blank lines (gnuplot "index").
void write_data(const Figure& figure, const std::string& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw bad_input("cannot write gnuplot's data file");
  for (const Panel& panel : figure.panels) {
    const HeatMap& map = panel.heat_map;
    if (!map.z.empty()) {  // one scan line per x, the block gnuplot's "with image" reads
      for (std::size_t i = 0; i < map.x.size(); ++i) {
        for (std::size_t j = 0; j < map.y.size(); ++j)
          std::fprintf(out, "%.17g %.17g %.17g\n", map.x[i], map.y[j], map.z[i * map.y.size() + j]);
        std::fprintf(out, "\n");
      }
      std::fprintf(out, "\n");
    }
    for (const Series& series : panel.series) {
      for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i)
        std::fprintf(out, "%.17g %.17g\n", series.x[i], series.y[i]);
      if (series.x.empty()) std::fprintf(out, "nan nan\n");  // keeps the index count right
      std::fprintf(out, "\n\n");
    }
  }
  const bool ok = std::fclose(out) == 0;
  if (!ok) throw bad_input("cannot write gnuplot's data file");
}

std::string script(const Figure& figure, const std::string& data, const std::string& output,
                   bool svg) {
  // About 7 pixels per character of the title's font, with a margin.
  const std::vector<std::string> title_lines =
      wrapped(figure.title, static_cast<std::size_t>(figure.width / 8));
  const int height = figure.panel_height * static_cast<int>(figure.panels.size()) +
                     (figure.title.empty() ? 0 : 40 + 16 * static_cast<int>(title_lines.size() - 1));
  std::string s;
  s += svg ? fmt::format("set terminal svg size {},{} dynamic noenhanced font 'Sans,12' "
                         "background rgb 'white'\n",
                         figure.width, height)
           : fmt::format("set terminal pngcairo size {},{} noenhanced font 'Sans,10'\n",
                         figure.width, height);
  s += "set output " + quoted(output) + "\n";
  s += "set grid lc rgb '#dddddd'\nset datafile missing 'nan'\n";
  s += "set autoscale\n";
  s += fmt::format("set multiplot layout {},1 title {}\n", figure.panels.size(),
                   quoted_lines(title_lines));
  int block = 0;
  for (const Panel& panel : figure.panels) {
    s += "set title " + quoted(panel.title) + "\n";
    s += "set xlabel " + quoted(panel.x_label) + "\n";
    s += "set ylabel " + quoted(panel.y_label) + "\n";
    s += panel.log_x ? "set logscale x\nset format x '%.0e'\n" : "unset logscale x\nset format x '% h'\n";
    s += panel.log_y ? "set logscale y\nset format y '%.0e'\n" : "unset logscale y\nset format y '% h'\n";
    // A key only where some series has a name (else gnuplot draws an empty box).
    const bool named = std::any_of(panel.series.begin(), panel.series.end(),
                                   [](const Series& series) { return !series.title.empty(); });
    s += named ? "set key top right box opaque\n" : "unset key\n";
    s += "unset arrow\n";
    for (double x : panel.vertical_lines)
      s += fmt::format("set arrow from {:.17g}, graph 0 to {:.17g}, graph 1 nohead front dt 2 "
                       "lc rgb '#555555'\n",  // front: not hidden under a curve drawn there
                       x, x);
    std::string plots;
    if (!panel.heat_map.z.empty()) {
      s += "set cblabel " + quoted(panel.heat_map.z_label) +
           "\nset palette rgb 33,13,10\nset autoscale xfix\nset autoscale yfix\n";
      plots = fmt::format("{} index {} using 1:2:3 with image notitle", quoted(data), block++);
    }
    int colour = 0;
    for (const Series& series : panel.series) {
      std::string style;
      if (series.role == Series::Role::reference) {
        style = series.points ? "with points pt 7 ps 0.5 lc rgb '#000000'"
                              : "with lines lw 3 lc rgb '#000000'";
      } else if (series.role == Series::Role::marker) {
        style = "with points pt 6 ps 1.2 lc rgb '#555555'";
      } else if (series.role == Series::Role::level) {
        style = "with lines dt 2 lw 1.5 lc rgb '#555555'";
      } else {
        const char* c = candidate_colours[colour++ % 5];
        style = series.points    ? fmt::format("with points pt 7 ps 0.4 lc rgb '{}'", c)
                : series.markers ? fmt::format("with linespoints lw 1.5 pt 7 ps 0.8 lc rgb '{}'", c)
                                 : fmt::format("with lines lw 1.2 lc rgb '{}'", c);
      }
      if (!plots.empty()) plots += ", \\\n     ";
      plots += fmt::format("{} index {} using 1:2 {} title {}", quoted(data), block++, style,
                           series.title.empty() ? "''" : quoted(series.title));
    }
    s += plots.empty() ? "plot NaN notitle\n" : "plot " + plots + "\n";
  }
  s += "unset multiplot\nunset output\n";
  return s;
}

}  // namespace

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "gnuplot";
    if (access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

void require_figure_path(const std::string& path, const std::string& option) {
  if (!ends_with(path, ".svg") && !ends_with(path, ".png"))
    throw bad_input(fmt::format("{} = {}: must end in .svg or .png", option, path));
  if (!gnuplot_available())
    throw bad_input(fmt::format("{} = {}: gnuplot is needed for figures and was not found on "
                                "PATH (Debian: apt-get install gnuplot-nox)",
                                option, path));
}

void write_figure(const Figure& figure, const std::string& path, const std::string& option) {
  require_figure_path(path, option);
  AtomicOutput output(path, option);  // gnuplot writes into its temporary file by name
  ScratchFile data("frictionref-plot-data");
  ScratchFile commands("frictionref-plot-script");
  ScratchFile messages("frictionref-plot-messages");
  write_data(figure, data.path());
  {
    std::ofstream out(commands.path());
    out << script(figure, data.path(), output.write_path(), ends_with(path, ".svg"));
    if (!out) throw bad_input("cannot write gnuplot's script file");
  }

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, messages.path().c_str(), O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::string program = "gnuplot";
  std::string script_path = commands.path();
  char* argv[] = {program.data(), script_path.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw bad_input(fmt::format("{} = {}: cannot run gnuplot: {}", option, path,
                                std::strerror(spawned)));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(messages.path());
    std::string first_line;
    std::getline(in, first_line);
    throw bad_input(fmt::format("{} = {}: gnuplot failed: {}", option, path,
                                first_line.empty() ? "no message" : first_line));
  }
  std::error_code error;
  if (fs::file_size(output.write_path(), error) == 0 || error)
    throw bad_input(fmt::format("{} = {}: gnuplot wrote nothing", option, path));
  output.commit();
}

}  // namespace frictionref::cli
