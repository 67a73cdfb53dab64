#include "renderer/tracing/melanin_level_use.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skin/core/random.h"

namespace hylios {
namespace {
/// Stream of the use estimate's numbers (any fixed value: the estimate is the same every run).
constexpr std::uint64_t kUseStream = 0x6d656c616e696e55ULL;
/// Expected freckle centres on the sampled plane: enough that the shares' sampling error is small.
constexpr double kFrecklesOnPlane = 2000;
}  // namespace

std::vector<double> melaninLevelUse(const SkinWalkCache& walks, const TextureMap* map,
                                    double mapMin, double mapMax, const FreckleField& freckles,
                                    std::size_t samples) {
  if (samples == 0) throw std::invalid_argument("melaninLevelUse: no sample points");
  std::vector<double> use(static_cast<std::size_t>(walks.levels()), 0.0);
  if (use.size() == 1) return {1.0};
  // A square patch of the plane z = 0 holding kFrecklesOnPlane freckles on average (any side
  // without freckles: their field is then 1 everywhere).
  const double sideCm =
      freckles.empty() ? 1.0 : std::sqrt(kFrecklesOnPlane / freckles.densityPerCm2());
  skin::Rng rng(1, kUseStream);
  for (std::size_t i = 0; i < samples; ++i) {
    double m = 1;
    if (map) {
      const glm::dvec2 uv{rng.uniform(), rng.uniform()};
      m = mapMin + (mapMax - mapMin) * map->lookup(uv);
    }
    const glm::dvec3 pointCm{rng.uniform() * sideCm, rng.uniform() * sideCm, 0.0};
    m *= freckles.multiplier(pointCm);
    use[static_cast<std::size_t>(walks.level(m, rng.uniform()))] += 1.0;
  }
  for (double& u : use) u /= static_cast<double>(samples);
  return use;
}

std::vector<double> levelRayShares(const std::vector<double>& use) {
  const double largest = use.empty() ? 0.0 : *std::max_element(use.begin(), use.end());
  if (!(largest > 0) || !std::isfinite(largest))
    throw std::invalid_argument("levelRayShares: no level is used");
  std::vector<double> shares;
  for (double u : use) {
    if (!(u >= 0)) throw std::invalid_argument("levelRayShares: a negative or NaN use");
    shares.push_back(std::max(kMinLevelRayShare, std::sqrt(u / largest)));
  }
  return shares;
}

}  // namespace hylios
