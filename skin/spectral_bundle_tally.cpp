#include "skin/spectral_bundle_tally.h"

#include <stdexcept>
#include <string>

namespace hylios::skin {

SpectralBundleTally::SpectralBundleTally(std::size_t wavelengths, const TallyOptions& options)
    : options_(options),
      wavelengths_(wavelengths),
      control_(wavelengths),
      score_(wavelengths),
      backwardScore_(wavelengths) {
  if (options.polarBins > 0 || options.radialBins > 0)
    each_.assign(wavelengths, SkinTally(options));
  else
    sums_.emplace(wavelengths, SkinTally::kQuantities);
}

void SpectralBundleTally::record(const SpectralPath& path, std::uint64_t ray) {
  const std::size_t n = wavelengths_;
  bool sizesMatch = path.exitWeight.size() == n && path.absorbedTotal.size() == n &&
                    (path.surfaceWeight.empty() || path.surfaceWeight.size() == n) &&
                    (path.absorbed.empty() || path.absorbed.size() == kLayerCount * n) &&
                    (path.absorbedInMelanosomes.empty() ||
                     path.absorbedInMelanosomes.size() == path.absorbed.size());
  if (path.split && (path.backward.empty() || !path.backward.front().surfaceWeight.empty()))
    throw std::invalid_argument(
        "SpectralBundleTally::record: a split path without its backward branch, or with a "
        "surface weight of the branch's own");
  const SpectralPath* backward = path.split ? &path.backward.front() : nullptr;
  if (backward)
    sizesMatch = sizesMatch && backward->exitWeight.size() == n &&
                 backward->absorbedTotal.size() == n &&
                 backward->absorbed.size() == path.absorbed.size() &&
                 backward->absorbedInMelanosomes.size() == path.absorbedInMelanosomes.size();
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
  if (path.split)
    throw std::logic_error(
        "SpectralBundleTally: a path split at a Rayleigh event in a tally with histograms "
        "(WalkOptions::splitFirstRayleigh is for the scalar curves)");
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
      const bool melanosomes = !path.absorbedInMelanosomes.empty();
      for (std::size_t layer = 0; layer < kLayerCount; ++layer) {
        score.absorbedByLayer[layer] = path.absorbed[layer * wavelengths_ + i];
        if (melanosomes)
          score.absorbedInMelanosomes += path.absorbedInMelanosomes[layer * wavelengths_ + i];
      }
    }
    if (perWavelengthDirection) score.exitDirection = path.transmittedDirection[i];
    each_[i].record(score);
  }
}

const double* SpectralBundleTally::scoresOf(const SpectralPath& path, std::size_t k,
                                            double* scratch) const {
  // The scores of SkinTally::record(PathScore) as recordEach builds them; null where the
  // quantity is 0 at every wavelength (SkinTally's sums skip zeros).
  const std::size_t n = wavelengths_;
  const double* w = path.exitWeight.data();
  const double* sw = path.surfaceWeight.empty() ? nullptr : path.surfaceWeight.data();
  const bool surface = path.end == PathEnd::SurfaceReflection;
  // Reflection: the exit weight where the path left on the named side, plus the split entry's.
  auto reflection = [&](bool exits) -> const double* {
    if (!exits && !sw) return nullptr;
    for (std::size_t i = 0; i < n; ++i) scratch[i] = (exits ? w[i] : 0.0) + (sw ? sw[i] : 0.0);
    return scratch;
  };
  const bool layers = !path.absorbed.empty();
  switch (k) {
    case SkinTally::kTotal:
      return reflection(surface || path.end == PathEnd::SubsurfaceReflection);
    case SkinTally::kSurface:
      return reflection(surface);
    case SkinTally::kSubsurface:
      return path.end == PathEnd::SubsurfaceReflection ? w : nullptr;
    case SkinTally::kTransmitted:
      return path.end == PathEnd::Transmitted ? w : nullptr;
    case SkinTally::kAbsorbed:
      return path.absorbedTotal.data();
    case SkinTally::kEventLimited:
      return path.end == PathEnd::EventLimit ? w : nullptr;
    case SkinTally::kMelanosome: {
      if (path.absorbedInMelanosomes.empty()) return nullptr;  // not booked
      const double* inMelanosomes = path.absorbedInMelanosomes.data();
      for (std::size_t i = 0; i < n; ++i) scratch[i] = 0.0 + inMelanosomes[i];  // layer by layer
      for (std::size_t layer = 1; layer < kLayerCount; ++layer)
        for (std::size_t i = 0; i < n; ++i) scratch[i] += inMelanosomes[layer * n + i];
      return scratch;
    }
    default:
      return layers ? &path.absorbed[(k - SkinTally::kFirstLayer) * n] : nullptr;
  }
}

void SpectralBundleTally::recordSums(const SpectralPath& path, std::uint64_t ray) {
  const std::size_t n = wavelengths_;
  const SpectralPath* backward = path.split ? &path.backward.front() : nullptr;
  const double* sw = path.surfaceWeight.empty() ? nullptr : path.surfaceWeight.data();
  double* u = control_.data();
  for (std::size_t i = 0; i < n; ++i)
    u[i] = path.absorbedTotal[i] + path.exitWeight[i] + (sw ? sw[i] : 0.0);
  events_ += path.events;
  if (backward) {  // a split path: one sample, the sum of its branches (weights ½ included)
    for (std::size_t i = 0; i < n; ++i)
      u[i] += backward->absorbedTotal[i] + backward->exitWeight[i];
    events_ += backward->events - path.splitAtEvent;
  }
  ControlledMeansArray& sums = *sums_;
  sums.beginPath(u, static_cast<unsigned>(ray & 1));
  double* t = score_.data();
  double* other = backwardScore_.data();
  for (std::size_t k = 0; k < SkinTally::kQuantities; ++k) {
    const double* forward = scoresOf(path, k, t);
    const double* back = backward ? scoresOf(*backward, k, other) : nullptr;
    if (!back) {
      if (forward) sums.add(k, forward);
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) t[i] = (forward ? forward[i] : 0.0) + back[i];
    sums.add(k, t);
  }
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
