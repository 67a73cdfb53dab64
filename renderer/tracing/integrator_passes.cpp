// Integrator's passes over the film (renderer/tracing/integrator.h): the coverage mask, tiles of
// kTileSize² pixels in parallel, passes sized to kAdaptivePassSeconds, and the noise checks that
// stop a render at its target.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>

#include "renderer/image/film_output.h"
#include "renderer/tracing/integrator.h"

namespace hylios {
namespace {
constexpr int kTileSize = 16;
}  // namespace

void Integrator::setCoverage(Film& film) const {
  const int width = film.width(), height = film.height();
  std::vector<char> seen(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const std::optional<SurfaceHit> hit =
          geometry_->intersect(camera_->generateRay(x + 0.5, y + 0.5, 0.5, 0.5));
      seen[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x)] = hit && !lights_->isEmitter(hit->shape);
    }
  });
  film.setCoverage(std::vector<bool>(seen.begin(), seen.end()));
}

RenderStats Integrator::render(Film& film, const RenderOptions& options) const {
  if (film.samplesPerPixelDone() > 0 && film.wholeBandSamples() != spectral_)
    throw std::invalid_argument("Integrator::render: the film was filled by the other estimator");
  film.setWholeBandSamples(spectral_);
  if (film.coverage().empty()) setCoverage(film);
  if (film.channels().size() != wavelengths_.size())
    throw std::invalid_argument(
        "Integrator::render: the film's channels differ from the integrator's");
  for (std::size_t c = 0; c < wavelengths_.size(); ++c)
    if (film.channels()[c].wavelengthNm != wavelengths_[c])
      throw std::invalid_argument(
          "Integrator::render: the film's channels differ from the integrator's");
  if (film.width() != scene_.film.width || film.height() != scene_.film.height)
    throw std::invalid_argument(
        "Integrator::render: the film's resolution differs from the scene's");
  const int spp = film.desc().samplesPerPixel;
  int done = film.samplesPerPixelDone();
  if (done < 0 || done > spp)
    throw std::invalid_argument("Integrator::render: the film has " + std::to_string(done) +
                                " samples per pixel, the target is " + std::to_string(spp));
  if (options.samplesPerPass < 0)
    throw std::invalid_argument("Integrator::render: samplesPerPass must be >= 0");
  const RenderDivision& division = options.division;
  if (division.parts == 0 || division.part >= division.parts)
    throw std::invalid_argument("Integrator::render: part " + std::to_string(division.part) +
                                " of " + std::to_string(division.parts));
  const std::uint64_t allTiles =
      static_cast<std::uint64_t>((film.width() + kTileSize - 1) / kTileSize) *
      static_cast<std::uint64_t>((film.height() + kTileSize - 1) / kTileSize);
  const std::uint64_t tiles = allTiles / division.parts +
                              (division.part < allTiles % division.parts ? 1 : 0);  // this part's
  auto noiseOf = [&](const Film& f) {
    return division.wholeFilmNoise ? division.wholeFilmNoise(f) : filmNoise(f);
  };
  std::unique_ptr<RenderProgress> progress;
  if (options.progress && done < spp)
    progress = options.progress(options.label, tiles * static_cast<std::uint64_t>(spp - done));
  RenderStats total;
  int passSamples = options.samplesPerPass > 0 ? options.samplesPerPass : 1;
  const int doneAtStart = done;
  // With a noise target the film's estimate is taken at sample counts that depend only on the
  // film (never on timing), so a render stops at the same spp on any machine: first at
  // kMinNoiseSamples, then at done × (noise/target)² (at most ×4), at least kNoiseCheckGranule
  // more, rounded down to a multiple of kNoiseCheckGranule (header): a check that falls short
  // costs one more check kNoiseCheckGranule later, one rounded up may pass over the count
  // that would have done.
  int nextCheck = std::max(kMinNoiseSamples, done);
  auto targetReached = [&] {
    total.noise = noiseOf(film);
    const double ratio = worstNoise(total.noise) / *options.noiseTarget;
    if (ratio <= 1) return total.noiseTargetReached = true;
    const int wanted = static_cast<int>(done * std::min(ratio * ratio, 4.0));
    const int next =
        std::max(wanted / kNoiseCheckGranule * kNoiseCheckGranule, done + kNoiseCheckGranule);
    nextCheck = std::min(spp, next);
    return false;
  };
  while (done < spp) {
    if (options.stopRequested && options.stopRequested()) break;
    if (options.noiseTarget && done >= nextCheck && targetReached()) break;
    int end = spp - done > passSamples ? done + passSamples : spp;
    if (options.noiseTarget) end = std::min(end, nextCheck);
    const auto start = std::chrono::steady_clock::now();
    // The first pass of a call may be long (a big film, a slow walk) and nothing of it could be
    // saved anyway: a stop request abandons it between tiles (issue 13, row 8). Later passes are
    // short (adaptive) and finish, so that the samples so far can be saved.
    const bool firstPass = done == doneAtStart;
    if (!renderPass(film, done, end, division, total, progress.get(),
                    firstPass ? options.stopRequested : std::function<bool()>{}))
      break;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    done = end;
    film.setSamplesPerPixelDone(done);
    if (options.onPassDone) options.onPassDone(done, seconds);
    if (options.noiseTarget && done >= nextCheck && targetReached()) break;
    if (options.samplesPerPass == 0 && seconds < kAdaptivePassSeconds && passSamples < (1 << 24)) {
      // Aim the next pass at kAdaptivePassSeconds, growing at most 8-fold (the first passes warm
      // up).
      const double factor =
          std::min(8.0, std::round(kAdaptivePassSeconds / std::max(seconds, 1e-9)));
      passSamples *= std::max(1, static_cast<int>(factor));
    }
  }
  if (options.noiseTarget && total.noise.empty() && done > 1) total.noise = noiseOf(film);
  if (progress) {
    if (done == spp || total.noiseTargetReached)
      progress->finish();
    else
      progress->stop();
  }
  return total;
}

bool Integrator::renderPass(Film& film, int firstSample, int endSample,
                            const RenderDivision& division, RenderStats& total,
                            RenderProgress* progress, const std::function<bool()>& abandon) const {
  std::atomic<bool> abandoned{false};
  const int width = film.width(), height = film.height();
  const int tilesX = (width + kTileSize - 1) / kTileSize,
            tilesY = (height + kTileSize - 1) / kTileSize;
  const std::size_t tiles = static_cast<std::size_t>(tilesX) * static_cast<std::size_t>(tilesY);
  std::mutex totalMutex;
  const std::uint64_t seed = scene_.integrator.seed;
  const std::uint64_t strata = spectral_ ? film.bandCount() : film.channels().size();
  const PixelSampler sampler(scene_.integrator.sampler, seed, strata);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, tiles, 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        RenderStats stats;
        std::vector<double> values;
        for (std::size_t tile = range.begin(); tile != range.end(); ++tile) {
          if (tile % division.parts != division.part) continue;  // another part's tile
          if (abandoned.load(std::memory_order_relaxed) || (abandon && abandon())) {
            abandoned.store(true, std::memory_order_relaxed);
            break;
          }
          const int x0 = static_cast<int>(tile % static_cast<std::size_t>(tilesX)) * kTileSize;
          const int y0 = static_cast<int>(tile / static_cast<std::size_t>(tilesX)) * kTileSize;
          for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
            for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) {
              const std::uint64_t pixel =
                  static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(width) +
                  static_cast<std::uint64_t>(x);
              // The sample's numbers (renderer/tracing/pixel_sampler.h): bands (spectral) or
              // channels (per-wavelength) stratified over the pixel's samples, then the camera
              // sample, then the path's decisions; the skin walks draw from rng.
              for (int s = firstSample; s < endSample; ++s) {
                skin::Rng rng(seed, pixel, static_cast<std::uint64_t>(s));
                SampleStream samples = sampler.stream(pixel, static_cast<std::uint64_t>(s), rng);
                const CameraSample c =
                    sampler.cameraSample(pixel, static_cast<std::uint64_t>(s), samples);
                const double u = c.band;
                const Ray cameraRay =
                    camera_->generateRay(x + c.filmX, y + c.filmY, c.lensU, c.lensV);
                const bool secondHalf = inSecondFilmHalf(static_cast<std::uint64_t>(s));
                if (spectral_) {  // the path carries every channel of a band
                  const std::size_t band = film.sampleBand(u);
                  const std::vector<std::size_t>& channels = film.bandChannels(band);
                  values.resize(channels.size());
                  radiance(cameraRay, PathSpectrum{channels.data(), channels.size(), band, true},
                           samples, stats, values.data());
                  film.addBandSample(x, y, band, values.data(), secondHalf);
                } else {
                  const std::size_t channel = film.sampleChannel(u);
                  const std::size_t channels[1] = {channel};
                  double value = 0;
                  radiance(cameraRay, PathSpectrum{channels, 1, 0, false}, samples, stats, &value);
                  film.addSample(x, y, channel, value, secondHalf);
                }
              }
            }
          if (progress) progress->advance(static_cast<std::uint64_t>(endSample - firstSample));
        }
        std::lock_guard<std::mutex> lock(totalMutex);
        total.add(stats);
      });
  return !abandoned.load();
}

}  // namespace hylios
