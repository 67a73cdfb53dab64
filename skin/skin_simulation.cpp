#include "skin/skin_simulation.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {
constexpr std::uint64_t kRaysPerChunk = 4096;
}  // namespace

std::uint64_t wavelengthStream(double wavelengthNm) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &wavelengthNm, sizeof bits);
  return mix64(bits);
}

Vec3 incidentDirection(double incidenceDeg) {
  const double theta = incidenceDeg * kPi / 180.0;
  return {std::sin(theta), 0.0, std::cos(theta)};
}

SkinTally simulateSkin(const SkinOptics& optics, const WalkRunOptions& options) {
  if (!(options.incidenceDeg >= 0 && options.incidenceDeg < 90))
    throw std::invalid_argument("incidence angle " + std::to_string(options.incidenceDeg) +
                                "° is outside [0°, 90°)");
  if (options.rays == 0) throw std::invalid_argument("the number of rays must be positive");
  const SkinWalk walk(optics, options.walk);
  const Vec3 incident = incidentDirection(options.incidenceDeg);
  const std::uint64_t stream = wavelengthStream(optics.wavelengthNm);
  const std::uint64_t chunks = (options.rays + kRaysPerChunk - 1) / kRaysPerChunk;
  std::vector<SkinTally> chunkTallies(chunks, SkinTally(options.tally));
  tbb::parallel_for(std::uint64_t{0}, chunks, [&](std::uint64_t chunk) {
    const std::uint64_t first = chunk * kRaysPerChunk;
    const std::uint64_t last = std::min(options.rays, first + kRaysPerChunk);
    SkinTally& tally = chunkTallies[chunk];
    for (std::uint64_t ray = first; ray < last; ++ray) {
      Rng rng(options.seed, stream, ray);
      tally.record(walk.trace(incident, rng));
    }
  });
  SkinTally total(options.tally);
  for (const SkinTally& tally : chunkTallies) total.merge(tally);
  return total;
}

}  // namespace hylios::skin
