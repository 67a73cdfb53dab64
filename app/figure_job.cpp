#include "app/figure_job.h"

#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>

#include "app/figure_layout.h"
#include "app/option_checks.h"
#include "renderer/image/film_output.h"
#include "renderer/image/preview_image.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/render_memory.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

/// Process CPU time (user + sys of every thread).
double cpuNow() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

/// The output folder must be a folder we can write in (made if missing); checked before any work.
void checkOutputFolder(const fs::path& out) {
  if (out.empty()) throw std::invalid_argument("--out '': empty path; give an output folder");
  std::error_code error;
  if (fs::exists(out, error) && !fs::is_directory(out, error))
    throw std::invalid_argument("--out '" + out.string() + "': exists and is not a folder");
  fs::create_directories(out, error);
  if (error)
    throw std::invalid_argument("--out '" + out.string() +
                                "': cannot create the folder: " + error.message());
  checkWritableOutput({"--out", (out / "contact_sheet.png").string()});
}

/// The title line on the pseudo-colour scale: one shared range, or each panel's own bar.
std::string scaleLine(const std::vector<SceneDesc>& scenes) {
  std::vector<const BandDesc*> pseudo;
  for (const SceneDesc& s : scenes)
    for (const BandDesc& b : s.film.bands)
      if (!isColourBand(b)) pseudo.push_back(&b);
  if (pseudo.empty()) return "";
  bool shared = true;
  for (const BandDesc* b : pseudo)
    shared =
        shared && b->previewMin == pseudo[0]->previewMin && b->previewMax == pseudo[0]->previewMax;
  const std::string unit = "relative: 1 = white diffuser, unit environment";
  if (!shared) return "pseudo-colour: radiance as on each bar (" + unit + ")";
  return "pseudo-colour: radiance " + formatLabelNumber(pseudo[0]->previewMin) + " to " +
         formatLabelNumber(pseudo[0]->previewMax) + " (" + unit + ")";
}

}  // namespace

std::string panelQuantity(const Film& film, std::size_t band) {
  return isColourBand(film.desc().bands.at(band)) ? "luminance Y" : "radiance";
}

PanelMean panelMean(const Film& film, std::size_t band, const std::vector<bool>* mask) {
  const NoiseImage first = filmHalfNoiseImage(film, false), second = filmHalfNoiseImage(film, true);
  const std::vector<double> share = filmSecondHalfShare(film);
  const std::size_t groups = first.groups.size();
  const bool colour = isColourBand(film.desc().bands.at(band));
  // Band groups come first, in band order, then R, G, B of the colour band.
  auto valueOf = [&](const NoiseImage& image, std::size_t pixel) {
    const double* v = &image.values[pixel * groups];
    if (!colour) return v[band];
    return 0.2126 * v[first.rgb[0]] + 0.7152 * v[first.rgb[1]] + 0.0722 * v[first.rgb[2]];
  };
  const auto& coverage = mask ? *mask : film.coverage();
  const std::size_t pixels = static_cast<std::size_t>(film.width()) * film.height();
  double sum = 0, variance = 0;
  bool bothHalves = true;
  PanelMean result;
  for (std::size_t p = 0; p < pixels; ++p) {
    if (!coverage.empty() && !coverage[p]) continue;
    const double a = valueOf(first, p), b = valueOf(second, p), q = share[p * groups + band];
    sum += (1 - q) * a + q * b;
    variance += q * (1 - q) * (a - b) * (a - b);
    bothHalves = bothHalves && q > 0 && q < 1;
    ++result.pixels;
  }
  if (result.pixels == 0) return result;
  const double n = static_cast<double>(result.pixels);
  result.mean = sum / n;
  // With a half empty (fewer samples than one block per half) the halves say nothing of the noise.
  result.standardError =
      bothHalves ? std::sqrt(variance) / n : std::numeric_limits<double>::quiet_NaN();
  return result;
}

FigureResult renderFigure(const std::vector<std::string>& sceneFiles, const fs::path& outDir,
                          const RenderSettings& settings, std::ostream* log) {
  // Two scenes with one stem would write one DIR/<stem>.exr (the second over the first).
  std::map<std::string, std::string> stems;
  for (const auto& file : sceneFiles) {
    const std::string stem = fs::path(file).stem().string();
    if (const auto [it, inserted] = stems.emplace(stem, file); !inserted)
      throw std::invalid_argument("scenes '" + it->second + "' and '" + file +
                                  "' would both be written to '" +
                                  (outDir / (stem + ".exr")).string() + "'; rename one of them");
  }
  // Parse every scene first, so a typo in the last one fails before hours of rendering.
  std::vector<SceneDesc> scenes;
  for (const auto& file : sceneFiles)
    scenes.push_back(applyRenderSettings(loadSceneFile(file), settings));
  const FigureLayout layout = layoutFigure(scenes);
  checkOutputFolder(outDir);
  std::vector<NamedPath> inputs, outputs;
  for (const auto& file : sceneFiles) inputs.push_back({"scene", file});
  for (const auto& [stem, file] : stems)
    outputs.push_back({"--out", (outDir / (stem + ".exr")).string()});
  checkOutputs(outputs, inputs);
  for (const SceneDesc& scene : scenes) checkRenderMemory(scene);

  FigureResult figure;
  int columns = 1;
  for (std::size_t i = 0; i < layout.order.size(); ++i) {
    const SceneDesc& scene = scenes[layout.order[i]];
    const double cpuStart = cpuNow();
    const RenderResult result = renderScene(scene, settings, log);
    const std::string stem = scene.file.stem().string();
    const auto written =
        writeFilmOutputs(*result.film, outDir / (stem + ".exr"), renderAttributes(scene, result));
    const double cpu = cpuNow() - cpuStart;
    figure.cpuSeconds += cpu;
    const double noise = worstNoise(filmNoise(*result.film));
    int previews = 0;
    for (std::size_t b = 0; b < scene.film.bands.size(); ++b) {
      const BandDesc& band = scene.film.bands[b];
      // writeFilmOutputs names the previews <stem>_<band>.png, in band order.
      fs::path preview;
      for (const auto& path : written)
        if (path.extension() == ".png" && path.stem().string().size() > stem.size() &&
            path.stem().string().substr(stem.size() + 1) == band.name)
          preview = path;
      if (preview.empty()) continue;  // an --out device writes no previews
      FigurePanel panel;
      panel.scene = scene.file;
      panel.preview = preview;
      panel.band = band.name;
      std::string caption = layout.captions[i];
      if (scene.film.bands.size() > 1)
        caption = caption.empty() ? bandText(band) : caption + ", " + bandText(band);
      if (caption.empty()) caption = bandText(band);
      panel.caption = caption;
      panel.quantity = panelQuantity(*result.film, b);
      panel.head = panelMean(*result.film, b);
      panel.freckles = freckleContrast(scene, *result.film, b);
      panel.noise = noise;
      panel.samplesPerPixel = result.film->samplesPerPixelDone();
      panel.renderSeconds = result.renderSeconds;
      panel.cpuSeconds = cpu;
      figure.panels.push_back(panel);
      ++previews;
    }
    for (const auto& path : written)
      if (log) *log << "wrote " << path.string() << "\n";
    columns = std::max(columns, previews);
  }
  if (!layout.title.empty()) figure.titleLines.push_back(layout.title);
  if (const std::string scale = scaleLine(scenes); !scale.empty())
    figure.titleLines.push_back(scale);
  figure.sheet = outDir / "contact_sheet.png";
  std::vector<fs::path> previews;
  std::vector<std::string> captions;
  for (const FigurePanel& p : figure.panels) {
    previews.push_back(p.preview);
    captions.push_back(p.caption);
  }
  if (previews.empty()) return figure;
  // One row per scene with its previews side by side; scenes with a single preview each (the
  // paper's figures) make one row of panels, like the paper's.
  writeContactSheet(previews, captions, figure.sheet,
                    columns == 1 ? static_cast<int>(previews.size()) : columns, figure.titleLines);
  if (log) *log << "wrote " << figure.sheet.string() << "\n";
  return figure;
}

}  // namespace hylios
