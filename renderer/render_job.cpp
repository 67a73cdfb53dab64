#include "renderer/render_job.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdlib>
#include <ostream>
#include <stdexcept>

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
  const Integrator integrator(scene, wavelengths);
  std::string degenerate;
  if (integrator.skippedDegenerateTriangles(&degenerate) > 0 && log) *log << degenerate;
  const auto prepared = Clock::now();
  RenderOptions options;
  options.progressBar = settings.progressBar;
  options.label = scene.file.filename().string();
  result.stats = integrator.render(*result.film, options);
  const auto done = Clock::now();
  result.prepareSeconds = std::chrono::duration<double>(prepared - start).count();
  result.renderSeconds = std::chrono::duration<double>(done - prepared).count();
  if (log) {
    const RenderStats& s = result.stats;
    *log << scene.file.filename().string() << ": " << scene.film.width << "x" << scene.film.height << ", "
         << scene.film.samplesPerPixel << " spp, " << wavelengths.size() << " channels; prepared in "
         << result.prepareSeconds << " s, rendered in " << result.renderSeconds << " s ("
         << static_cast<double>(s.paths) / std::max(result.renderSeconds, 1e-9) << " paths/s)\n"
         << "  skin walks " << s.skinWalks << " (absorbed " << s.skinAbsorbed << ", surface " << s.skinSurfaceExits
         << ", subsurface " << s.skinSubsurfaceExits << ", event limit " << s.skinEventLimited
         << "); exit-projection fallbacks " << s.exitFallbacks << "; continuations below the surface "
         << s.belowSurface << "\n";
  }
  return result;
}

RenderSettings renderSettingsFromOptions(int spp, const std::string& resolution, int threads) {
  RenderSettings settings;
  if (spp > 0) settings.samplesPerPixel = spp;
  if (!resolution.empty()) {
    const auto [w, h] = parseResolution(resolution);
    settings.width = w;
    settings.height = h;
  }
  settings.threads = threads;
  return settings;
}

}  // namespace hylios
