#include "renderer/skin_walk_cache.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>

#include "skin/skin_optics.h"

namespace hylios {

skin::Specimen scaleMelanin(const skin::Specimen& specimen, double multiplier) {
  skin::Specimen scaled = specimen;
  for (auto& v : scaled.melanosomeFraction) v *= multiplier;
  for (auto& v : scaled.colloidalMelaninFraction) v *= multiplier;
  return scaled;
}

SkinWalkCache::SkinWalkCache(const skin::Specimen& specimen, double minMultiplier, double maxMultiplier,
                             const std::vector<double>& channelWavelengths, const skin::SpectralDatabase& spectra,
                             const FileLocation& where)
    : lo_(std::min(minMultiplier, maxMultiplier)), hi_(std::max(minMultiplier, maxMultiplier)),
      levels_(hi_ > lo_ ? kMelaninLevels : 1), channels_(channelWavelengths.size()) {
  if (!(lo_ >= 0) || !std::isfinite(hi_)) throw SceneError(where, "melanin multipliers must be finite and >= 0");
  std::vector<skin::Specimen> specimens;
  for (int k = 0; k < levels_; ++k) {
    specimens.push_back(scaleMelanin(specimen, levelMultiplier(k)));
    try {
      skin::validateSpecimen(specimens.back());
    } catch (const std::exception& e) {
      throw SceneError(where, "specimen '" + specimen.name + "' with melanin × " + std::to_string(levelMultiplier(k)) +
                                  " is not valid: " + e.what());
    }
  }
  walks_.resize(static_cast<std::size_t>(levels_) * channels_);
  std::mutex errorMutex;
  std::string error;
  tbb::parallel_for(std::size_t{0}, walks_.size(), [&](std::size_t i) {
    const std::size_t k = i / channels_, c = i % channels_;
    try {
      walks_[i].emplace(skin::computeSkinOptics(specimens[k], spectra, channelWavelengths[c]));
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (error.empty()) error = e.what();
    }
  });
  if (!error.empty()) throw SceneError(where, "skin specimen '" + specimen.name + "': " + error);
}

double SkinWalkCache::levelMultiplier(int level) const {
  return levels_ == 1 ? lo_ : lo_ + (hi_ - lo_) * level / (levels_ - 1);
}

int SkinWalkCache::level(double multiplier, double u) const {
  if (levels_ == 1) return 0;
  const double t = std::clamp((multiplier - lo_) / (hi_ - lo_), 0.0, 1.0) * (levels_ - 1);
  const int below = std::min(static_cast<int>(t), levels_ - 1);
  return (u < t - below) ? below + 1 : below;
}

const skin::SkinWalk& SkinWalkCache::walk(std::size_t channel, int level) const {
  return *walks_[static_cast<std::size_t>(level) * channels_ + channel];
}

}  // namespace hylios
