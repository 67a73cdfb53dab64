// Rendering a figure (what `hylios figure` and `hylios gallery` run): several scene files → DIR/
// <scene stem>.exr with its previews each, and DIR/contact_sheet.png with every preview in the
// order and with the captions of app/figure_layout.h (one row per scene when a scene has several
// bands, else one row of panels as in the paper), a title with what the panels share and, for
// pseudo-colour panels, the scale and its unit. Each panel is measured on the pixels that see an
// object (the film's coverage): the mean of its quantity with a standard error, and the noise.
#pragma once
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/freckle_contrast.h"
#include "renderer/image/film.h"
#include "renderer/tracing/render_job.h"

namespace hylios {

/// The mean over the covered pixels of a band's radiance (the mean over its channels) or, for a
/// colour band, of its luminance Y (linear sRGB, 1 for a white diffuser under a uniform D65
/// environment of scale 1), with the standard error of that mean from the film's two halves
/// (independent, pixel_sampler.h): per pixel the mean is (1 − q)·a + q·b with variance
/// q(1 − q)(a − b)², q the second half's share of the samples (renderer/image/render_noise.h),
/// so SE = √(Σ q(1 − q)(a − b)²) / N over the N covered pixels; NaN while a half is empty.
struct PanelMean {
  double mean = 0;
  double standardError = 0;
  std::size_t pixels = 0;
};
/// `mask` (one entry per pixel), when given, replaces the coverage as the set of pixels.
PanelMean panelMean(const Film& film, std::size_t band, const std::vector<bool>* mask = nullptr);

/// What the panel's numbers measure: "radiance" or "luminance Y".
std::string panelQuantity(const Film& film, std::size_t band);

struct FigurePanel {
  std::filesystem::path scene;              ///< the scene file
  std::filesystem::path preview;            ///< its PNG preview of this band
  std::string band;                         ///< the band's name
  std::string caption;                      ///< app/figure_layout.h
  std::string quantity;                     ///< panelQuantity
  PanelMean head;                           ///< over the pixels that see an object
  std::optional<FreckleContrast> freckles;  ///< when the scene has freckles
  double noise = 0;  ///< the film's own estimate: the worst group (render_noise.h)
  int samplesPerPixel = 0;
  double renderSeconds = 0;  ///< the scene's render (wall)
  double cpuSeconds = 0;     ///< the scene's preparation and render, CPU (user + sys, all threads)
};

struct FigureResult {
  std::vector<FigurePanel> panels;  ///< in sheet order
  std::vector<std::string> titleLines;
  std::filesystem::path sheet;
  double cpuSeconds = 0;  ///< every scene's (user + sys)
};

/// Renders `sceneFiles` into `outDir` (made if missing) with `settings` and writes the contact
/// sheet; `log` (may be null) gets each scene's report. Every scene is parsed and every output
/// checked before the first render.
FigureResult renderFigure(const std::vector<std::string>& sceneFiles,
                          const std::filesystem::path& outDir, const RenderSettings& settings,
                          std::ostream* log);

}  // namespace hylios
