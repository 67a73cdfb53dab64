// Plots through Debian's gnuplot (gnuplot-nox, pngcairo terminal): the tool writes a data file and
// a script into a temporary folder and runs gnuplot, which writes the PNG (atomically).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace hylios {

struct PlotSeries {
  std::string title;
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> yError;  ///< optional: drawn as a shaded band y ± yError when non-empty
  std::string style;           ///< optional gnuplot style, e.g. "lines lw 2 dt 2"
  /// Optional: a shaded band from bandLow to bandHigh (e.g. a measured population's range); both
  /// or neither, not with yError.
  std::vector<double> bandLow{}, bandHigh{};
};

struct PlotPanel {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logY = false;
  std::vector<PlotSeries> series;
};

/// Writes a PNG of one or more panels stacked in a grid (`columns` wide). Throws
/// std::runtime_error if gnuplot is missing or fails (its stderr in the message).
void plotPanels(const std::filesystem::path& png, const std::string& title,
                const std::vector<PlotPanel>& panels, int columns = 1, int widthPx = 1200,
                int heightPx = 800);

}  // namespace hylios
