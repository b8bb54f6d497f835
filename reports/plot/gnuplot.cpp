#include "reports/plot/gnuplot.hpp"

#include <fmt/format.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "reports/report_error.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;

// Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
constexpr std::array<std::string_view, 8> kPalette = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                      "#E69F00", "#56B4E9", "#000000", "#F0E442"};

// A private temporary folder, removed with its content.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "ccm-plot-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      throw ReportError("cannot create a temporary folder in " +
                        fs::temp_directory_path().string());
    path = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

// A double-quoted gnuplot string.
std::string gnuplot_string(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string style_clause(const Series& s) {
  const std::string_view colour = kPalette[static_cast<std::size_t>(s.color) % kPalette.size()];
  const int point_type = 7 + 2 * (s.color % 3);  // filled circle, triangle, diamond
  switch (s.style) {
    case SeriesStyle::lines:
      return fmt::format("with lines lw 2 lc rgb '{}'", colour);
    case SeriesStyle::linespoints:
      return fmt::format("with linespoints lw 1.5 pt {} ps 0.8 lc rgb '{}'", point_type, colour);
    case SeriesStyle::squares:
      return fmt::format("with points pt 5 ps 1.6 lc rgb '{}'", colour);
    case SeriesStyle::cells:
      return fmt::format("with boxxyerror fs solid 1.0 noborder lc rgb '{}'", colour);
    case SeriesStyle::surface:
      return fmt::format("with lines lw 0.8 lc rgb '{}'", colour);
    case SeriesStyle::thin_lines:
      return fmt::format("with lines lw 0.7 lc rgb '{}'", colour);
    case SeriesStyle::band:
      return fmt::format("with filledcurves fs transparent solid 0.25 noborder lc rgb '{}'",
                         colour);
    case SeriesStyle::marks:
      return fmt::format("with vectors nohead lw 1.2 dt 2 lc rgb '{}'", colour);
    case SeriesStyle::points:
      break;
  }
  return fmt::format("with points pt {} ps 0.9 lc rgb '{}'", point_type, colour);
}

bool has_upper(const Series& s) {
  return s.style == SeriesStyle::band || s.style == SeriesStyle::marks;
}

void write_series(const Series& s, bool three_d, const fs::path& file) {
  std::ofstream out(file);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (three_d || has_upper(s))
      out << fmt::format("{:.17g} {:.17g} {:.17g}\n", s.x[i], s.y[i], s.z[i]);
    else
      out << fmt::format("{:.17g} {:.17g}\n", s.x[i], s.y[i]);
    // gnuplot reads a mesh as rows separated by blank lines.
    if (s.style == SeriesStyle::surface && s.surface_columns > 0 &&
        (i + 1) % s.surface_columns == 0)
      out << '\n';
  }
  if (!out) throw ReportError("cannot write plot data to " + file.string());
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `gnuplot script` with its error output in `log`; returns its exit status.
int run_gnuplot(const std::string& gnuplot, const fs::path& script, const fs::path& log) {
  const pid_t pid = fork();
  if (pid < 0) throw ReportError("cannot start gnuplot (fork failed)");
  if (pid == 0) {
    if (freopen(log.c_str(), "w", stderr) == nullptr) _exit(127);
    execl(gnuplot.c_str(), gnuplot.c_str(), script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// The `using` columns of one series: x y [z], for a band x low high, for marks x y 0 dy, or for
// cells x y x_low x_high y_low y_high.
std::string using_columns(const PlotSpec& plot, const Series& series) {
  if (plot.three_d || series.style == SeriesStyle::band) return "1:2:3";
  if (series.style == SeriesStyle::marks) return "1:2:(0):($3-$2)";
  if (series.style != SeriesStyle::cells) return "1:2";
  const std::string x_range =
      plot.log_x ? fmt::format("($1*10**(-{0:.17g})):($1*10**({0:.17g}))", series.cell_dx)
                 : fmt::format("($1-{0:.17g}):($1+{0:.17g})", series.cell_dx);
  return fmt::format("1:2:{}:($2-{:.17g}):($2+{:.17g})", x_range, series.cell_dy, series.cell_dy);
}

// Whole-number tics, about ten of them, over the x values of the plot.
std::string integer_x_tics(const PlotSpec& plot) {
  const auto x = all_values(plot, 0);
  if (x.empty()) return {};
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double step = std::max(1.0, std::ceil((*hi - *lo) / 10.0));
  return fmt::format("set xtics {:.0f}\nset mxtics 1\nset format x '%.0f'\n", step);
}

}  // namespace

std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "gnuplot";
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  throw ReportError(
      "gnuplot not found on PATH: the report draws its figures with it; install the Debian "
      "package gnuplot-nox (scripts/install-deps.sh)");
}

std::string gnuplot_script(const PlotSpec& plot, const std::string& svg_file) {
  // The key below the plot, one line taller than gnuplot makes it and the x label raised a
  // little (2-D): else the label touches the key's box.
  std::string s = fmt::format(
      "set terminal svg size {},{} noenhanced font 'DejaVu Sans,11' background rgb 'white'\n"
      "set output {}\nset title {}\nset xlabel {}{}\nset ylabel {}\nset grid\n"
      "set key below Left reverse box height 1\nset datafile missing 'nan'\n",
      plot.width, plot.height, gnuplot_string(svg_file), gnuplot_string(plot.title),
      gnuplot_string(plot.x_label), plot.three_d ? "" : " offset 0,0.3",
      gnuplot_string(plot.y_label));
  if (plot.integer_x && !plot.log_x) s += integer_x_tics(plot);
  if (plot.log_x) s += "set logscale x\nset format x '%.0e'\n";
  if (plot.log_y) s += "set logscale y\nset format y '%.0e'\n";
  if (plot.three_d) {
    // The z label moved off its tic labels; the z axis stretched a little into the free space.
    s += fmt::format(
        "set zlabel {} rotate parallel offset -2,0\nset view 60,35,1,1.15\nset ticslevel 0\n",
        gnuplot_string(plot.z_label));
    if (plot.log_z) s += "set logscale z\nset format z '%.0e'\n";
  }
  std::string command = plot.three_d ? "splot" : "plot";
  bool first = true;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const Series& series = plot.series[i];
    if (series.empty()) continue;
    command += fmt::format("{} 'series-{}.dat' using {} {} title {}", first ? " " : ", \\\n  ", i,
                           using_columns(plot, series), style_clause(series),
                           gnuplot_string(series.title));
    first = false;
  }
  return s + command + "\n";
}

std::string render_svg(const PlotSpec& plot) {
  bool any_data = false;
  for (const Series& s : plot.series) any_data = any_data || !s.empty();
  if (!any_data) throw ReportError("figure \"" + plot.title + "\" has no data to plot");
  const std::string gnuplot = find_gnuplot();
  ScratchDir scratch;
  for (std::size_t i = 0; i < plot.series.size(); ++i)
    if (!plot.series[i].empty())
      write_series(plot.series[i], plot.three_d, scratch.path / fmt::format("series-{}.dat", i));
  const fs::path svg = scratch.path / "figure.svg";
  const fs::path script = scratch.path / "figure.gp";
  std::ofstream(script) << "cd " << gnuplot_string(scratch.path.string()) << "\n"
                        << gnuplot_script(plot, svg.string());
  const fs::path log = scratch.path / "gnuplot.log";
  if (run_gnuplot(gnuplot, script, log) != 0 || !fs::exists(svg))
    throw ReportError("gnuplot failed on figure \"" + plot.title + "\": " + read_file(log));
  return read_file(svg);
}

}  // namespace ccm::reports
