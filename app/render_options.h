// The options `hylios render` and `hylios figure` share, as given on the command line, and the
// plain RenderSettings (renderer/tracing/render_job.h) they become.
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>

#include "renderer/tracing/render_job.h"
#include "skin/estimator.h"
#include "skin/skin_mode.h"

namespace hylios {

/// "WxH" → (W, H); throws std::invalid_argument otherwise.
std::pair<int, int> parseResolution(const std::string& text);

struct RenderCommandOptions {
  int spp = 0;                             ///< 0: the scene's
  std::string resolution;                  ///< "": the scene's, else WxH
  int threads = 0;                         ///< 0: all cores
  std::optional<skin::SkinMode> skinMode;  ///< unset: the scene's
  double effectTolerance = -1;             ///< < 0: the scene's
  bool explain = false;
  std::optional<skin::Estimator> estimator;  ///< unset: the scene's
  double noiseTarget = -1;                   ///< < 0: the scene's (if any)
  /// --sampler (renderer/tracing/pixel_sampler.h); unset: the scene's.
  std::optional<SamplerKind> sampler;
};
/// Adds --spp, --resolution, --threads, --skin-model, --epsilon, --explain, --estimator,
/// --noise-target and --sampler to `command`.
void addRenderCommandOptions(CLI::App& command, RenderCommandOptions& options);
/// The settings of `options`, with a progress bar on stderr (drawn only on a terminal).
RenderSettings renderSettingsFromOptions(const RenderCommandOptions& options);

}  // namespace hylios
