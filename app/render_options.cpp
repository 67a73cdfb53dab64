#include "app/render_options.h"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>

#include "app/common_options.h"
#include "app/enum_option.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "renderer/scene/scene_file.h"
#include "skin/skin_mode.h"

namespace hylios {

std::pair<int, int> parseResolution(const std::string& text) {
  const auto x = text.find('x');
  auto number = [&](const std::string& part, const char* side) {
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument("--resolution '" + text +
                                  "': expected WxH with positive integers, e.g. 512x512");
    if (part.size() > 9 || std::stol(part) > kMaxFilmSide)
      throw std::invalid_argument(
          fmt::format("--resolution '{}': the {} {} exceeds the limit of {} pixels per side", text,
                      side, part, kMaxFilmSide));
    const long v = std::stol(part);
    if (v < 1)
      throw std::invalid_argument(
          fmt::format("--resolution '{}': the {} must be at least 1", text, side));
    return static_cast<int>(v);
  };
  if (x == std::string::npos) number("", "width");
  const int w = number(text.substr(0, x), "width"), h = number(text.substr(x + 1), "height");
  if (static_cast<long long>(w) * h > kMaxFilmPixels)
    throw std::invalid_argument(
        fmt::format("--resolution '{}': {} pixels exceeds the limit of {} (64 Mpixel)", text,
                    static_cast<long long>(w) * h, kMaxFilmPixels));
  return {w, h};
}

void addRenderCommandOptions(CLI::App& command, RenderCommandOptions& options) {
  command.add_option("--spp", options.spp, "Samples per pixel (default: the scene's)")
      ->check(CLI::Range(1, 1 << 24));
  command.add_option("--resolution", options.resolution, "WxH in pixels (default: the scene's)");
  addThreadsOption(command, options.threads);
  addEnumOption(
      command, "--skin-model", options.skinMode, skin::kSkinModeNames,
      "walk (exact HyLIoS walk per hit) or table (tabulated fast path); default: the scene's");
  command
      .add_option("--epsilon", options.effectTolerance,
                  "Effect-planner tolerance: processes whose summed optical depth stays below it "
                  "are skipped "
                  "(0 = simulate everything; default: the scene's, else 1e-3)")
      ->check(finiteRange(0.0, 1.0));
  command.add_flag("--explain", options.explain,
                   "Print the effect plan (process, layer, optical depth, kept or skipped)");
  addEnumOption(command, "--estimator", options.estimator, skin::kEstimatorNames,
                "spectral (a path carries every channel of a band; skin runs the spectral walk) or "
                "per-wavelength (one channel per path, the analog walk: the reference); default: "
                "the scene's, else spectral");
  command
      .add_option("--noise-target", options.noiseTarget,
                  "Render in passes until the estimated median per-pixel relative noise over the "
                  "pixels that see "
                  "an object is at most this in every band (and R, G, B, chromaticity), or --spp "
                  "is reached, "
                  "e.g. 0.05")
      ->check(finiteRange(1e-6, 10.0));
  addEnumOption(command, "--sampler", options.sampler, kSamplerNames,
                "independent (every number of a camera path independent) or sobol "
                "(Owen-scrambled Sobol' points per pixel for the camera sample and the first "
                "light samples and bounces); default: the scene's, else sobol");
}

RenderSettings renderSettingsFromOptions(const RenderCommandOptions& options) {
  RenderSettings settings;
  if (options.spp > 0) settings.samplesPerPixel = options.spp;
  if (!options.resolution.empty()) {
    const auto [w, h] = parseResolution(options.resolution);
    settings.width = w;
    settings.height = h;
  }
  settings.threads = options.threads;
  settings.skinMode = options.skinMode;
  if (options.effectTolerance >= 0) settings.effectTolerance = options.effectTolerance;
  settings.explain = options.explain;
  settings.estimator = options.estimator;
  settings.sampler = options.sampler;
  if (options.noiseTarget >= 0) settings.noiseTarget = options.noiseTarget;
  settings.progress = progressBarFactory();
  return settings;
}

}  // namespace hylios
