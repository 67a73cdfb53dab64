#include "skin/spectral_bundle_tally.h"

#include <stdexcept>
#include <string>

namespace hylios::skin {

SpectralBundleTally::SpectralBundleTally(std::size_t wavelengths, const TallyOptions& options)
    : options_(options), wavelengths_(wavelengths), control_(wavelengths), score_(wavelengths) {
  if (options.polarBins > 0 || options.radialBins > 0)
    each_.assign(wavelengths, SkinTally(options));
  else
    sums_.emplace(wavelengths, SkinTally::kQuantities);
}

void SpectralBundleTally::record(const SpectralPath& path, std::uint64_t ray) {
  const std::size_t n = wavelengths_;
  const bool sizesMatch = path.exitWeight.size() == n && path.absorbedTotal.size() == n &&
                          (path.surfaceWeight.empty() || path.surfaceWeight.size() == n) &&
                          (path.absorbed.empty() || path.absorbed.size() == kLayerCount * n) &&
                          path.absorbedInMelanosomes.size() == path.absorbed.size();
  if (!sizesMatch)
    throw std::invalid_argument("SpectralBundleTally::record: a path with " +
                                std::to_string(path.exitWeight.size()) + " weights in a tally of " +
                                std::to_string(n) + " wavelengths");
  if (sums_)
    recordSums(path, ray);
  else
    recordEach(path, ray);
}

void SpectralBundleTally::recordEach(const SpectralPath& path, std::uint64_t ray) {
  PathScore score = pathScoreOf(path);
  score.hasControlWeight = true;
  score.fold = static_cast<unsigned>(ray & 1);
  const bool perWavelengthDirection =
      path.end == PathEnd::Transmitted && !path.transmittedDirection.empty();
  for (std::size_t i = 0; i < wavelengths_; ++i) {
    score.exitWeight = path.exitWeight[i];
    score.surfaceWeight = path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[i];
    score.surfaceDirection = path.surfaceDirection;
    score.absorbed = path.absorbedTotal[i];
    score.controlWeight = score.absorbed + score.exitWeight + score.surfaceWeight;
    if (!path.absorbed.empty()) {
      score.absorbedInMelanosomes = 0;
      for (std::size_t layer = 0; layer < kLayerCount; ++layer) {
        score.absorbedByLayer[layer] = path.absorbed[layer * wavelengths_ + i];
        score.absorbedInMelanosomes += path.absorbedInMelanosomes[layer * wavelengths_ + i];
      }
    }
    if (perWavelengthDirection) score.exitDirection = path.transmittedDirection[i];
    each_[i].record(score);
  }
}

void SpectralBundleTally::recordSums(const SpectralPath& path, std::uint64_t ray) {
  // The scores of SkinTally::record(PathScore) as recordEach builds them, quantity by quantity;
  // a quantity that is 0 at every wavelength is not added (SkinTally's sums skip zeros).
  const std::size_t n = wavelengths_;
  const double* w = path.exitWeight.data();
  const double* sw = path.surfaceWeight.empty() ? nullptr : path.surfaceWeight.data();
  const double* absorbed = path.absorbedTotal.data();
  double* u = control_.data();
  double* t = score_.data();
  for (std::size_t i = 0; i < n; ++i) u[i] = absorbed[i] + w[i] + (sw ? sw[i] : 0.0);
  ControlledMeansArray& sums = *sums_;
  sums.beginPath(u, static_cast<unsigned>(ray & 1));
  events_ += path.events;
  const bool surface = path.end == PathEnd::SurfaceReflection;
  const bool reflected = surface || path.end == PathEnd::SubsurfaceReflection;
  // Reflection: the exit weight where the path left on the named side, plus the split entry's.
  auto addReflection = [&](std::size_t k, bool exits) {
    if (!exits && !sw) return;
    for (std::size_t i = 0; i < n; ++i) t[i] = (exits ? w[i] : 0.0) + (sw ? sw[i] : 0.0);
    sums.add(k, t);
  };
  addReflection(SkinTally::kTotal, reflected);
  addReflection(SkinTally::kSurface, surface);
  if (path.end == PathEnd::SubsurfaceReflection) sums.add(SkinTally::kSubsurface, w);
  if (path.end == PathEnd::Transmitted) sums.add(SkinTally::kTransmitted, w);
  sums.add(SkinTally::kAbsorbed, absorbed);
  if (path.end == PathEnd::EventLimit) sums.add(SkinTally::kEventLimited, w);
  if (path.absorbed.empty()) return;
  const double* inMelanosomes = path.absorbedInMelanosomes.data();
  for (std::size_t i = 0; i < n; ++i) t[i] = 0.0 + inMelanosomes[i];  // layer by layer, from 0
  for (std::size_t layer = 1; layer < kLayerCount; ++layer)
    for (std::size_t i = 0; i < n; ++i) t[i] += inMelanosomes[layer * n + i];
  sums.add(SkinTally::kMelanosome, t);
  for (std::size_t layer = 0; layer < kLayerCount; ++layer)
    sums.add(SkinTally::kFirstLayer + layer, &path.absorbed[layer * n]);
}

std::vector<SkinTally> SpectralBundleTally::tallies() const {
  if (!sums_) return each_;
  std::vector<SkinTally> result;
  result.reserve(wavelengths_);
  for (std::size_t i = 0; i < wavelengths_; ++i)
    result.push_back(SkinTally::fromControlledMeans(options_, sums_->member(i), events_));
  return result;
}

}  // namespace hylios::skin
