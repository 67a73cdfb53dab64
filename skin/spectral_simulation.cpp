#include "skin/spectral_simulation.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <string>

#include "skin/spectral_bundle_tally.h"
#include "skin/spectral_walk.h"

namespace hylios::skin {
namespace {
constexpr std::uint64_t kPathsPerChunk = 1024;

struct Chunk {
  std::size_t bundle;
  std::uint64_t first, last;
};

}  // namespace

SpectralRunOptions commandSpectralRun(const WalkRunOptions& run) {
  SpectralRunOptions spectral;
  spectral.incidenceDeg = run.incidenceDeg;
  spectral.rays = run.rays;
  spectral.seed = run.seed;
  spectral.walk = run.walk;
  spectral.walk.tabulatedMelanosomes = true;
  spectral.walk.splitEntryReflection = true;
  spectral.walk.melanosomeAbsorption = false;  // no command prints it (0.96x the curve's time)
  spectral.tally = run.tally;
  // Curves: heroes in shares by law (skin/hero_shares.h) even out the variance over a bundle's
  // members, and the tallies' control variate (skin/core/controlled_means.h) takes most of the MIS
  // ratio's, so bundles may span wider laws than the tables' (skin/spectral_bundle.h) at the
  // largest standard error uniform heroes gave with 0.8 and 0.3: 16 bundles on the S1 curve
  // instead of 24 (docs/benchmarks.md, sessions 21 and 24).
  spectral.walk.heroSharesByLaw = true;
  // A Rayleigh spread of 2.6 leaves the plateau two bundles instead of four: 0.78x its time at a
  // variance up to 1.6x (mean 1.27x) at bundle edges, whose largest standard error (0.0013) stays
  // under the ramp's (session 27).
  spectral.bundles.maxRayleighSpread = 2.6;
  spectral.bundles.maxLogAngleSpread = 0.6;
  // Above 1400 nm the bundles, grouped by absorption, hold more members for less time: 96 took
  // 0.89x the time of 64 there, at a mean variance 3 % higher (session 26).
  spectral.bundles.maxWavelengths = 96;
  spectral.splitRayleighWithoutDeflection = run.tally.polarBins == 0 && run.tally.radialBins == 0;
  return spectral;
}

std::uint64_t bundleStream(const std::vector<double>& wavelengthsNm) {
  std::uint64_t stream = 0x6a09e667f3bcc909ULL;
  for (double w : wavelengthsNm) stream = mix64(stream ^ wavelengthStream(w));
  return stream;
}

std::vector<SkinTally> simulateSkinSpectral(const std::vector<SkinOptics>& optics,
                                            const SpectralRunOptions& options) {
  return mergeSpectralChunks(simulateSkinSpectralChunks(optics, options), optics.size(),
                             options.tally);
}

SpectralChunks simulateSkinSpectralChunks(const std::vector<SkinOptics>& optics,
                                          const SpectralRunOptions& options, std::size_t part,
                                          std::size_t parts) {
  if (parts == 0 || part >= parts)
    throw std::invalid_argument("simulateSkinSpectralChunks: part " + std::to_string(part) +
                                " of " + std::to_string(parts));
  if (!(options.incidenceDeg >= 0 && options.incidenceDeg < 90))
    throw std::invalid_argument("incidence angle " + std::to_string(options.incidenceDeg) +
                                "° is outside [0°, 90°)");
  if (options.rays == 0) throw std::invalid_argument("the number of rays must be positive");
  const auto bundles = groupIntoBundles(optics, options.walk, options.bundles);
  std::vector<SpectralWalk> walks;
  std::vector<std::uint64_t> streams;
  std::vector<Chunk> chunks;
  for (std::size_t b = 0; b < bundles.size(); ++b) {
    std::vector<SkinOptics> members;
    std::vector<double> wavelengths;
    for (std::size_t i : bundles[b]) {
      members.push_back(optics[i]);
      wavelengths.push_back(optics[i].wavelengthNm);
    }
    WalkOptions walk = options.walk;  // bundles never mix θo = 0 and θo > 0
    if (options.splitRayleighWithoutDeflection && members.front().meanScatteringAngleRad == 0)
      walk.splitFirstRayleigh = true;
    walks.emplace_back(members, walk);
    streams.push_back(bundleStream(wavelengths));
    for (std::uint64_t first = 0; first < options.rays; first += kPathsPerChunk)
      chunks.push_back({b, first, std::min(options.rays, first + kPathsPerChunk)});
  }
  const Vec3 incident = incidentDirection(options.incidenceDeg);
  SpectralChunks result;
  for (const Chunk& chunk : chunks) result.members.push_back(bundles[chunk.bundle]);
  std::vector<std::vector<SkinTally>>& chunkTallies = result.tallies;
  chunkTallies.resize(chunks.size());
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    if (c % parts != part) return;  // another part's chunk
    const Chunk& chunk = chunks[c];
    SpectralBundleTally tally(bundles[chunk.bundle].size(), options.tally);
    SpectralPath path;
    for (std::uint64_t ray = chunk.first; ray < chunk.last; ++ray) {
      Rng rng(options.seed, streams[chunk.bundle], ray);
      walks[chunk.bundle].trace(incident, rng, path);
      tally.record(path, ray);
    }
    chunkTallies[c] = tally.tallies();
  });
  return result;
}

std::vector<SkinTally> mergeSpectralChunks(const SpectralChunks& chunks, std::size_t count,
                                           const TallyOptions& tally) {
  std::vector<SkinTally> result(count, SkinTally(tally));
  for (std::size_t c = 0; c < chunks.members.size(); ++c) {
    const auto& members = chunks.members[c];
    if (chunks.tallies.at(c).size() != members.size())
      throw std::invalid_argument("mergeSpectralChunks: chunk " + std::to_string(c) +
                                  " was not run");
    for (std::size_t k = 0; k < members.size(); ++k)
      result.at(members[k]).merge(chunks.tallies[c][k]);
  }
  return result;
}

}  // namespace hylios::skin
