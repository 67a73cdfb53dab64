#include "app/gnuplot_plot.h"

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "skin/core/atomic_file.h"

namespace hylios {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// A scratch folder removed when it goes out of scope.
struct ScratchFolder {
  std::filesystem::path path;
  ScratchFolder() {
    std::random_device device;
    path = std::filesystem::temp_directory_path() /
           ("hylios-plot-" + std::to_string(::getpid()) + "-" + std::to_string(device()));
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

bool hasBand(const PlotSeries& series) { return !series.yError.empty() || !series.bandLow.empty(); }

/// Columns x, y and, with a band, its lower and upper edges.
void writeSeriesData(const std::filesystem::path& file, const PlotSeries& series) {
  const std::size_t n = series.y.size();
  const bool symmetric = !series.yError.empty(), edges = !series.bandLow.empty();
  if (series.x.size() != n || (symmetric && series.yError.size() != n) ||
      (edges && (series.bandLow.size() != n || series.bandHigh.size() != n)) ||
      (!edges && !series.bandHigh.empty()) || (symmetric && edges))
    throw std::invalid_argument("plot series '" + series.title +
                                "' has columns of unequal length or two bands");
  std::ofstream out(file);
  out.precision(10);
  for (std::size_t i = 0; i < n; ++i) {
    out << series.x[i] << ' ' << series.y[i];
    if (symmetric)
      out << ' ' << series.y[i] - series.yError[i] << ' ' << series.y[i] + series.yError[i];
    if (edges) out << ' ' << series.bandLow[i] << ' ' << series.bandHigh[i];
    out << '\n';
  }
}

std::string panelCommands(const PlotPanel& panel, const std::filesystem::path& folder,
                          std::size_t panelIndex) {
  std::ostringstream script;
  script << "set title " << quoted(panel.title) << "\n"
         << "set xlabel " << quoted(panel.xLabel) << "\nset ylabel " << quoted(panel.yLabel) << "\n"
         << (panel.logY ? "set logscale y\nset format y '10^{%T}'\n"
                        : "unset logscale y\nset format y '%g'\n")
         << "plot ";
  bool first = true;
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const PlotSeries& series = panel.series[s];
    const auto data =
        folder / ("p" + std::to_string(panelIndex) + "s" + std::to_string(s) + ".dat");
    writeSeriesData(data, series);
    const std::string file = quoted(data.string());
    if (!first) script << ", \\\n  ";
    first = false;
    if (hasBand(series))
      script << file << " using 1:3:4 with filledcurves fs transparent solid 0.25 "
             << "lc " << (s + 1) << " notitle, \\\n  ";
    const std::string style = series.style.empty() ? "lines lw 2" : series.style;
    script << file << " using 1:2 with " << style;
    if (style.find(" lc ") == std::string::npos) script << " lc " << (s + 1);
    script << " title " << quoted(series.title);
  }
  script << "\n";
  return script.str();
}

}  // namespace

void plotPanels(const std::filesystem::path& png, const std::string& title,
                const std::vector<PlotPanel>& panels, int columns, int widthPx, int heightPx) {
  if (panels.empty()) throw std::invalid_argument("plot '" + png.string() + "' has no panels");
  ScratchFolder scratch;
  writeAtomically(png, [&](const std::filesystem::path& tmp) {
    std::ostringstream script;
    const int rows = static_cast<int>((panels.size() + static_cast<std::size_t>(columns) - 1) /
                                      static_cast<std::size_t>(columns));
    script << "set terminal pngcairo size " << widthPx << "," << heightPx
           << " enhanced font 'sans,10'\nset output " << quoted(tmp.string()) << "\n"
           << "set grid\nset key below\nset datafile missing 'nan'\n"
           << "set multiplot layout " << rows << "," << columns << " title " << quoted(title)
           << "\n";
    for (std::size_t p = 0; p < panels.size(); ++p)
      script << panelCommands(panels[p], scratch.path, p);
    script << "unset multiplot\n";
    const auto scriptFile = scratch.path / "plot.gp";
    std::ofstream(scriptFile) << script.str();
    const auto errors = scratch.path / "gnuplot.err";
    const std::string command =
        "gnuplot " + quoted(scriptFile.string()) + " 2> " + quoted(errors.string());
    const int status = std::system(command.c_str());
    if (status != 0 || !std::filesystem::exists(tmp)) {
      std::ifstream errorStream(errors);
      std::string message((std::istreambuf_iterator<char>(errorStream)),
                          std::istreambuf_iterator<char>());
      // The shell exits 127 when it cannot find the program; anything else is gnuplot's own
      // failure (a folder it cannot write in, a bad script), reported with its message.
      if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 127)
        throw std::runtime_error(
            "cannot plot '" + png.string() +
            "': gnuplot is not installed or not on PATH (Debian: apt-get install gnuplot-nox)");
      throw std::runtime_error("gnuplot failed writing '" + png.string() + "'" +
                               (message.empty() ? std::string() : ": " + message));
    }
  });
}

}  // namespace hylios
