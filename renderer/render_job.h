// Rendering one scene file from the command line (shared by `hylios render` and `hylios figure`):
// load and validate the scene, apply the command-line overrides, prepare the integrator, render
// with the requested thread count, and report timing and counters.
#pragma once
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "renderer/film.h"
#include "renderer/integrator.h"
#include "renderer/render_checkpoint.h"
#include "renderer/scene.h"

namespace hylios {

struct RenderSettings {
  std::optional<int> samplesPerPixel;
  std::optional<int> width, height;
  std::optional<std::uint64_t> seed;
  int threads = 0;          ///< 0: all cores
  bool progressBar = true;
  std::optional<std::string> skinMode;     ///< "walk" or "table" (the scene's when unset)
  std::optional<double> effectTolerance;   ///< ε of the effect planner (the scene's when unset)
  bool explain = false;                    ///< print the effect plans before rendering
  /// Interruptible renders (render --resume): asked between sample passes, true stops the render.
  std::function<bool()> stopRequested;
  /// A checkpoint's state to continue (readMatchingCheckpoint has checked it against the scene).
  std::shared_ptr<const RenderCheckpoint> resumeFrom;
};

struct RenderResult {
  std::unique_ptr<Film> film;
  RenderStats stats;
  double prepareSeconds = 0;  ///< scene loading, BVH build, skin-walk precomputation
  double renderSeconds = 0;
  int samplesPerPixelAtStart = 0;  ///< > 0 when continued from a checkpoint
  bool stopped = false;            ///< stopped by stopRequested before the spp target
};

/// "WxH" → (W, H); throws std::invalid_argument otherwise.
std::pair<int, int> parseResolution(const std::string& text);

/// The options `render` and `figure` share, as given on the command line.
struct RenderCommandOptions {
  int spp = 0;                 ///< 0: the scene's
  std::string resolution;      ///< "": the scene's, else WxH
  int threads = 0;             ///< 0: all cores
  std::string skinMode;        ///< "": the scene's
  double effectTolerance = -1; ///< < 0: the scene's
  bool explain = false;
};
/// Adds --spp, --resolution, --threads, --skin-model, --epsilon and --explain to `command`.
void addRenderCommandOptions(CLI::App& command, RenderCommandOptions& options);
RenderSettings renderSettingsFromOptions(const RenderCommandOptions& options);

/// The scene with the settings applied (spp, resolution, seed).
SceneDesc applyRenderSettings(SceneDesc scene, const RenderSettings& settings);

/// Renders `scene` (after applyRenderSettings); writes a short report to `log` (may be null).
RenderResult renderScene(const SceneDesc& scene, const RenderSettings& settings, std::ostream* log);

}  // namespace hylios
