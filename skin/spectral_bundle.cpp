#include "skin/spectral_bundle.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace hylios::skin {
namespace {
/// Σ coefficient·thickness over the walked layers (down to walk.deepestLayer): the optical depth
/// of one coefficient of LayerOptics at normal incidence.
double walkedDepth(const SkinOptics& optics, const WalkOptions& walk,
                   double LayerOptics::*coefficient_perCm) {
  double depth = 0;
  for (Layer layer : kAllLayers)
    if (index(layer) <= index(walk.deepestLayer))
      depth += optics[layer].*coefficient_perCm * optics[layer].thicknessCm;
  return depth;
}
}  // namespace

double rayleighDepth(const SkinOptics& optics, const WalkOptions& walk) {
  return walk.rayleigh ? walkedDepth(optics, walk, &LayerOptics::muRayleigh_perCm) : 0.0;
}

double absorptionDepth(const SkinOptics& optics, const WalkOptions& walk) {
  return walkedDepth(optics, walk, &LayerOptics::muATotal_perCm);
}

namespace {
struct Range {
  double lowest = 0, highest = 0;
  void reset(double x) { lowest = highest = x; }
  Range with(double x) const { return {std::min(lowest, x), std::max(highest, x)}; }
  double logSpread() const {
    return lowest > 0 ? std::log(highest / lowest) : (highest > 0 ? INFINITY : 0.0);
  }
};
}  // namespace

std::vector<std::vector<std::size_t>> groupIntoBundles(const std::vector<SkinOptics>& optics,
                                                       const WalkOptions& walk,
                                                       const BundleRule& rule) {
  if (rule.maxWavelengths == 0)
    throw std::invalid_argument("bundle rule: at most 0 wavelengths per bundle");
  std::vector<std::size_t> order(optics.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Deflecting members in increasing λ; undeflected ones (θo = 0) after them, least absorbed
  // first, so that a bundle's members are absorbed alike and its paths end together.
  const auto undeflected = [&](std::size_t i) {
    return walk.melanosomes && optics[i].meanScatteringAngleRad == 0;
  };
  std::vector<double> depth(optics.size());
  for (std::size_t i = 0; i < optics.size(); ++i) depth[i] = absorptionDepth(optics[i], walk);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (undeflected(a) != undeflected(b)) return undeflected(b);
    if (undeflected(a) && depth[a] != depth[b]) return depth[a] < depth[b];
    return optics[a].wavelengthNm < optics[b].wavelengthNm;
  });
  std::vector<std::vector<std::size_t>> bundles;
  Range angle, rayleigh;
  double surfaceIndex = 0;
  for (std::size_t i : order) {
    const SkinOptics& o = optics[i];
    const double theta = walk.melanosomes ? o.meanScatteringAngleRad : 0.0;
    const double tau = rayleighDepth(o, walk);
    const double n = o[Layer::StratumCorneum].refractiveIndex;
    bool fits = !bundles.empty() && bundles.back().size() < rule.maxWavelengths;
    if (fits) {
      const Range a = angle.with(theta), r = rayleigh.with(tau);
      // A run of members with one θo > 0 (the plateau below the ramp) takes no other θo: the
      // plateau's equal laws would dominate the balance heuristic and starve the ramp's members.
      const bool plateau =
          bundles.back().size() > 1 && angle.lowest == angle.highest && angle.lowest > 0;
      fits = (a.lowest == 0) == (a.highest == 0) && a.logSpread() <= rule.maxLogAngleSpread &&
             !(plateau && theta != angle.lowest) &&
             std::min(r.logSpread(), r.highest - r.lowest) <= rule.maxRayleighSpread &&
             (walk.roughSurface || n == surfaceIndex);
      if (fits) angle = a, rayleigh = r;
    }
    if (!fits) {
      bundles.emplace_back();
      angle.reset(theta);
      rayleigh.reset(tau);
      surfaceIndex = n;
    }
    bundles.back().push_back(i);
  }
  for (auto& bundle : bundles)  // each bundle in increasing λ (hero shares take neighbours so)
    std::sort(bundle.begin(), bundle.end(), [&](std::size_t a, std::size_t b) {
      return optics[a].wavelengthNm < optics[b].wavelengthNm;
    });
  return bundles;
}

}  // namespace hylios::skin
