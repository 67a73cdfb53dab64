#include "renderer/tracing/render_job.h"

#include <algorithm>
#include <chrono>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "renderer/tracing/exit_table_cache.h"
#include "skin/core/thread_limit.h"

namespace hylios {

SceneDesc applyRenderSettings(SceneDesc scene, const RenderSettings& settings) {
  if (settings.samplesPerPixel) {
    if (*settings.samplesPerPixel <= 0) throw std::invalid_argument("--spp must be positive");
    scene.film.samplesPerPixel = *settings.samplesPerPixel;
  }
  if (settings.width) scene.film.width = *settings.width;
  if (settings.height) scene.film.height = *settings.height;
  if (settings.seed) scene.integrator.seed = *settings.seed;
  if (settings.skinMode) scene.integrator.skinMode = *settings.skinMode;
  if (settings.effectTolerance) scene.integrator.effectTolerance = *settings.effectTolerance;
  if (settings.estimator) scene.integrator.estimator = *settings.estimator;
  if (settings.noiseTarget) scene.integrator.noiseTarget = *settings.noiseTarget;
  if (settings.sampler) scene.integrator.sampler = *settings.sampler;
  return scene;
}

std::vector<std::pair<std::string, std::string>> renderAttributes(const SceneDesc& scene,
                                                                  const RenderResult& result) {
  std::vector<std::pair<std::string, std::string>> attributes = {
      {"hylios:seed", std::to_string(scene.integrator.seed)},
      {"hylios:estimator", skin::estimatorName(scene.integrator.estimator)},
      {"hylios:sampler", std::string(enumName(scene.integrator.sampler, kSamplerNames))}};
  if (scene.integrator.noiseTarget) {
    std::ostringstream target;
    target.precision(17);
    target << *scene.integrator.noiseTarget;
    attributes.push_back({"hylios:noiseTarget", target.str()});
    std::string noise = formatNoise(result.stats.noise);
    std::replace(noise.begin(), noise.end(), '\n', ';');
    attributes.push_back({"hylios:noise", noise});
  }
  return attributes;
}

RenderResult renderScene(const SceneDesc& scene, const RenderSettings& settings,
                         std::ostream* log) {
  const ThreadLimit threadLimit(settings.threads);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  RenderResult result;
  result.film = std::make_unique<Film>(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : result.film->channels()) wavelengths.push_back(c.wavelengthNm);
  const bool tableMode = scene.integrator.skinMode == skin::SkinMode::Table;
  const std::size_t loadedBefore = tableMode ? ExitTableCache::shared().loaded() : 0;
  const std::size_t builtBefore = tableMode ? ExitTableCache::shared().built() : 0;
  const Integrator integrator(scene, wavelengths);
  if (tableMode && log) {
    const ExitTableCache& cache = ExitTableCache::shared();
    const std::chrono::duration<double> setUp = Clock::now() - start;
    *log << "exit tables: " << cache.loaded() - loadedBefore << " loaded, "
         << cache.built() - builtBefore << " built (cache '" << cache.folder().string()
         << "'); scene set up in " << setUp.count() << " s\n"
         << integrator.tableWalksReport();
  }
  if (log) *log << integrator.lights().selectionReport(scene);
  std::string degenerate;
  if (integrator.skippedDegenerateTriangles(&degenerate) > 0 && log) *log << degenerate;
  if (settings.explain && log) *log << integrator.effectPlanReport();
  if (settings.resumeFrom) {
    const RenderCheckpoint& saved = *settings.resumeFrom;
    result.film->setWholeBandSamples(integrator.estimator() == skin::Estimator::Spectral);
    result.film->restoreState(saved.sums, saved.counts, saved.secondHalfSums, saved.secondHalfCounts,
                              saved.samplesPerPixelDone);
    result.samplesPerPixelAtStart = saved.samplesPerPixelDone;
    if (log)
      *log << "continuing from " << saved.samplesPerPixelDone << " of "
           << scene.film.samplesPerPixel << " spp\n";
  }
  const auto prepared = Clock::now();
  RenderOptions options;
  options.progress = settings.progress;
  options.label = scene.file.filename().string();
  options.stopRequested = settings.stopRequested;
  options.noiseTarget = scene.integrator.noiseTarget;
  options.division = settings.division;
  // A line after the first pass, then at most one every 10 s (the progress bar shows the rest).
  auto lastReport = Clock::time_point{};
  options.onPassDone = [&](int samplesDone, double) {
    if (!log ||
        (lastReport != Clock::time_point{} && Clock::now() - lastReport < std::chrono::seconds(10)))
      return;
    lastReport = Clock::now();
    *log << "  pass done: " << samplesDone << "/" << scene.film.samplesPerPixel << " spp"
         << std::endl;
  };
  result.stats = integrator.render(*result.film, options);
  if (settings.division.gather) settings.division.gather(*result.film, result.stats);
  result.stopped = result.film->samplesPerPixelDone() < scene.film.samplesPerPixel &&
                   !result.stats.noiseTargetReached;
  const auto done = Clock::now();
  result.prepareSeconds = std::chrono::duration<double>(prepared - start).count();
  result.renderSeconds = std::chrono::duration<double>(done - prepared).count();
  if (log) {
    const RenderStats& s = result.stats;
    *log << scene.file.filename().string() << ": " << scene.film.width << "x" << scene.film.height
         << ", " << scene.film.samplesPerPixel << " spp"
         << (result.stopped
                 ? " (stopped at " + std::to_string(result.film->samplesPerPixelDone()) + ")"
                 : "")
         << ", " << wavelengths.size() << " channels; prepared in " << result.prepareSeconds
         << " s, rendered in " << result.renderSeconds << " s ("
         << static_cast<double>(s.paths) / std::max(result.renderSeconds, 1e-9) << " paths/s)\n"
         << "  skin walks " << s.skinWalks << " (absorbed " << s.skinAbsorbed << ", surface "
         << s.skinSurfaceExits << ", subsurface " << s.skinSubsurfaceExits << ", event limit "
         << s.skinEventLimited << "); exit-projection fallbacks " << s.exitFallbacks
         << "; continuations below the surface " << s.belowSurface << "\n";
    if (scene.integrator.noiseTarget)
      *log << "  estimated noise (median per-pixel relative, over pixels that see an object) after "
           << result.film->samplesPerPixelDone() << " spp, target " << *scene.integrator.noiseTarget
           << (s.noiseTargetReached ? " reached" : " not reached (spp cap)") << ":\n"
           << formatNoise(s.noise);
  }
  return result;
}

}  // namespace hylios
