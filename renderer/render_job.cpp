#include "renderer/render_job.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdlib>
#include <ostream>
#include <stdexcept>

#include "renderer/exit_table_cache.h"

namespace hylios {

std::pair<int, int> parseResolution(const std::string& text) {
  const auto x = text.find('x');
  auto number = [&](const std::string& part) {
    char* end = nullptr;
    const long v = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0' || v <= 0 || v > 65536)
      throw std::invalid_argument("--resolution '" + text + "': expected WxH with positive integers, e.g. 512x512");
    return static_cast<int>(v);
  };
  if (x == std::string::npos) number("");
  return {number(text.substr(0, x)), number(text.substr(x + 1))};
}

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
  return scene;
}

RenderResult renderScene(const SceneDesc& scene, const RenderSettings& settings, std::ostream* log) {
  std::unique_ptr<tbb::global_control> threadLimit;
  if (settings.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        static_cast<std::size_t>(settings.threads));
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  RenderResult result;
  result.film = std::make_unique<Film>(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : result.film->channels()) wavelengths.push_back(c.wavelengthNm);
  const bool tableMode = scene.integrator.skinMode == "table";
  const std::size_t loadedBefore = tableMode ? ExitTableCache::shared().loaded() : 0;
  const std::size_t builtBefore = tableMode ? ExitTableCache::shared().built() : 0;
  const Integrator integrator(scene, wavelengths);
  if (tableMode && log) {
    const ExitTableCache& cache = ExitTableCache::shared();
    *log << "exit tables: " << cache.loaded() - loadedBefore << " loaded, " << cache.built() - builtBefore
         << " built (cache '" << cache.folder().string() << "')\n";
  }
  std::string degenerate;
  if (integrator.skippedDegenerateTriangles(&degenerate) > 0 && log) *log << degenerate;
  if (settings.explain && log) *log << integrator.effectPlanReport();
  if (settings.resumeFrom) {
    const RenderCheckpoint& saved = *settings.resumeFrom;
    result.film->restoreState(saved.sums, saved.counts, saved.samplesPerPixelDone);
    result.samplesPerPixelAtStart = saved.samplesPerPixelDone;
    if (log) *log << "continuing from " << saved.samplesPerPixelDone << " of " << scene.film.samplesPerPixel << " spp\n";
  }
  const auto prepared = Clock::now();
  RenderOptions options;
  options.progressBar = settings.progressBar;
  options.label = scene.file.filename().string();
  options.stopRequested = settings.stopRequested;
  // A line after the first pass, then at most one every 10 s (the progress bar shows the rest).
  auto lastReport = Clock::time_point{};
  options.onPassDone = [&](int samplesDone, double) {
    if (!log || (lastReport != Clock::time_point{} && Clock::now() - lastReport < std::chrono::seconds(10))) return;
    lastReport = Clock::now();
    *log << "  pass done: " << samplesDone << "/" << scene.film.samplesPerPixel << " spp" << std::endl;
  };
  result.stats = integrator.render(*result.film, options);
  result.stopped = result.film->samplesPerPixelDone() < scene.film.samplesPerPixel;
  const auto done = Clock::now();
  result.prepareSeconds = std::chrono::duration<double>(prepared - start).count();
  result.renderSeconds = std::chrono::duration<double>(done - prepared).count();
  if (log) {
    const RenderStats& s = result.stats;
    *log << scene.file.filename().string() << ": " << scene.film.width << "x" << scene.film.height << ", "
         << scene.film.samplesPerPixel << " spp" << (result.stopped ? " (stopped at " + std::to_string(result.film->samplesPerPixelDone()) + ")" : "")
         << ", " << wavelengths.size() << " channels; prepared in "
         << result.prepareSeconds << " s, rendered in " << result.renderSeconds << " s ("
         << static_cast<double>(s.paths) / std::max(result.renderSeconds, 1e-9) << " paths/s)\n"
         << "  skin walks " << s.skinWalks << " (absorbed " << s.skinAbsorbed << ", surface " << s.skinSurfaceExits
         << ", subsurface " << s.skinSubsurfaceExits << ", event limit " << s.skinEventLimited
         << "); exit-projection fallbacks " << s.exitFallbacks << "; continuations below the surface "
         << s.belowSurface << "\n";
  }
  return result;
}

void addRenderCommandOptions(CLI::App& command, RenderCommandOptions& options) {
  command.add_option("--spp", options.spp, "Samples per pixel (default: the scene's)")->check(CLI::Range(1, 1 << 24));
  command.add_option("--resolution", options.resolution, "WxH in pixels (default: the scene's)");
  command.add_option("--threads", options.threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  command.add_option("--skin-model", options.skinMode, "walk (exact HyLIoS walk per hit) or table (tabulated fast path); default: the scene's")
      ->check(CLI::IsMember({"walk", "table"}));
  command.add_option("--epsilon", options.effectTolerance,
                     "Effect-planner tolerance: processes whose summed optical depth stays below it are skipped "
                     "(0 = simulate everything; default: the scene's, else 1e-3)")
      ->check(CLI::Range(0.0, 1.0));
  command.add_flag("--explain", options.explain, "Print the effect plan (process, layer, optical depth, kept or skipped)");
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
  if (!options.skinMode.empty()) settings.skinMode = options.skinMode;
  if (options.effectTolerance >= 0) settings.effectTolerance = options.effectTolerance;
  settings.explain = options.explain;
  return settings;
}

}  // namespace hylios
