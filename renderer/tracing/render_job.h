// Rendering one scene file (what `hylios render` and `hylios figure` run): load and validate the
// scene, apply the overrides of a plain RenderSettings (app/render_options.h fills it from the
// command line), prepare the integrator, render with the requested thread count, and report
// timing and counters.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/image/render_checkpoint.h"
#include "renderer/scene/scene.h"
#include "renderer/tracing/integrator.h"

namespace hylios {

struct RenderSettings {
  std::optional<int> samplesPerPixel;
  std::optional<int> width, height;
  std::optional<std::uint64_t> seed;
  int threads = 0;                           ///< 0: all cores
  RenderProgressFactory progress;            ///< empty: no progress display
  std::optional<skin::SkinMode> skinMode;    ///< the scene's when unset
  std::optional<double> effectTolerance;     ///< ε of the effect planner (the scene's when unset)
  bool explain = false;                      ///< print the effect plans before rendering
  std::optional<skin::Estimator> estimator;  ///< the scene's when unset
  std::optional<double> noiseTarget;  ///< the scene's when unset (renderer/image/render_noise.h)
  /// The camera paths' numbers (renderer/tracing/pixel_sampler.h); the scene's when unset.
  std::optional<SamplerKind> sampler;
  /// Interruptible renders (render --resume): asked between sample passes, true stops the render.
  std::function<bool()> stopRequested;
  /// A checkpoint's state to continue (readMatchingCheckpoint has checked it against the scene).
  std::shared_ptr<const RenderCheckpoint> resumeFrom;
  /// This process's share of the tiles and how the parts are put together (integrator.h); the
  /// log is written after division.gather, with the whole render's counters.
  RenderDivision division;
};

struct RenderResult {
  std::unique_ptr<Film> film;
  RenderStats stats;
  double prepareSeconds = 0;  ///< scene loading, BVH build, skin-walk precomputation
  double renderSeconds = 0;
  int samplesPerPixelAtStart = 0;  ///< > 0 when continued from a checkpoint
  bool stopped = false;            ///< stopped by stopRequested before the spp target
};

/// The scene with the settings applied (spp, resolution, seed).
SceneDesc applyRenderSettings(SceneDesc scene, const RenderSettings& settings);

/// The EXR attributes of a finished render: hylios:seed, hylios:estimator and, with a noise
/// target, hylios:noiseTarget and hylios:noise (each group's estimated median relative noise).
std::vector<std::pair<std::string, std::string>> renderAttributes(const SceneDesc& scene,
                                                                  const RenderResult& result);

/// Renders `scene` (after applyRenderSettings); writes a short report to `log` (may be null).
RenderResult renderScene(const SceneDesc& scene, const RenderSettings& settings, std::ostream* log);

}  // namespace hylios
