// The paper's rendered figures (Figs. 1, 12, 13, 14) as `hylios gallery` regenerates them: the
// scene files of each, a short quote of the paper's caption and of the trend Sec. 5 states, and
// how the measured panel means are held against that trend (app/gallery_report.h).
#pragma once
#include <string>
#include <vector>

namespace hylios {

/// What the paper says the panels show, as a check on the measured means (in panel order).
enum class PaperTrend {
  Freckles,    ///< Fig. 1: freckles stand out at 365 nm, not at 1100 nm (freckle contrast)
  Decreasing,  ///< Fig. 12: darker with more melanin
  SmallStep,   ///< Fig. 13: the last step (7 → 30 %) changes little, against Fig. 12's
  Increasing,  ///< Fig. 14: brighter with dehydration
};

struct PaperFigure {
  int number = 0;
  std::string subject;              ///< heading, e.g. "epidermal melanin in the visible"
  std::vector<std::string> scenes;  ///< relative to the data root (renderer/scene/data_paths.h)
  std::string caption;              ///< the paper's caption, quoted (shortened with …)
  std::string trend;                ///< the paper's statement of what the panels show, quoted
  PaperTrend check = PaperTrend::Decreasing;
};

/// Figures 1, 12, 13 and 14, in that order.
const std::vector<PaperFigure>& paperFigures();

}  // namespace hylios
