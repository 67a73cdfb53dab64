// docs/figures.md as `hylios gallery` writes it: per paper figure its contact sheet, the paper's
// caption and stated trend (quoted), a table of the panels (scene, spp, noise, the mean on the
// head ± its standard error, CPU time) and what the measured means say about the trend; then how
// the gallery was run (command, settings, time, machine load).
#pragma once
#include <string>
#include <vector>

#include "app/figure_job.h"
#include "app/paper_figures.h"

namespace hylios {

struct GalleryFigure {
  PaperFigure paper;
  FigureResult result;
  std::string sheetImage;  ///< path of the sheet relative to figures.md
};

struct GalleryRun {
  std::string command;   ///< the command line that made it
  std::string settings;  ///< resolution, noise target, spp cap, threads
  double wallSeconds = 0, cpuSeconds = 0;
  int cores = 0;
  double loadBefore = 0, loadAfter = 0;  ///< 1-minute load averages
};

/// What the measured means say about the paper's trend (one paragraph of Markdown).
std::string trendVerdict(const GalleryFigure& figure, const std::vector<GalleryFigure>& all);

/// The whole of figures.md.
std::string galleryMarkdown(const std::vector<GalleryFigure>& figures, const GalleryRun& run);

}  // namespace hylios
