#include "renderer/tracing/skin_walk_cache.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <string>

#include "skin/skin_optics.h"

namespace hylios {

namespace {

/// One plan for a channel from pilots at the two end melanin levels (see the header).
skin::EffectPlan planChannel(const skin::Specimen& lowest, const skin::Specimen& highest,
                             const skin::SpectralDatabase& spectra, double wavelengthNm,
                             double epsilon) {
  std::vector<skin::SkinOptics> ends{skin::computeSkinOptics(lowest, spectra, wavelengthNm)};
  if (&lowest != &highest) ends.push_back(skin::computeSkinOptics(highest, spectra, wavelengthNm));
  skin::PlanOptions options;
  options.incidenceDeg = {0.0, 60.0};
  options.pilotRays = SkinWalkCache::kRenderPilotRays;
  return skin::planEffects(ends, epsilon, options);
}

}  // namespace

skin::Specimen scaleMelanin(const skin::Specimen& specimen, double multiplier) {
  skin::Specimen scaled = specimen;
  for (auto& v : scaled.melanosomeFraction) v *= multiplier;
  for (auto& v : scaled.colloidalMelaninFraction) v *= multiplier;
  return scaled;
}

SkinWalkCache::SkinWalkCache(const skin::Specimen& specimen, double minMultiplier,
                             double maxMultiplier, const std::vector<double>& channelWavelengths,
                             const skin::SpectralDatabase& spectra, const SourceLocation& where,
                             int levels, double effectTolerance,
                             const std::vector<std::vector<std::size_t>>& bundles)
    : lo_(std::min(minMultiplier, maxMultiplier)),
      hi_(std::max(minMultiplier, maxMultiplier)),
      rootLo_(std::sqrt(lo_)),
      rootHi_(std::sqrt(hi_)),
      levels_(hi_ > lo_ ? levels : 1),
      channels_(channelWavelengths.size()) {
  if (!(effectTolerance >= 0 && effectTolerance <= 1))
    throw SceneError(where,
                     "effect tolerance must lie in [0, 1], got " + std::to_string(effectTolerance));
  if (levels < 2)
    throw SceneError(where, "melanin levels must be at least 2, got " + std::to_string(levels));
  if (!(lo_ >= 0) || !std::isfinite(hi_))
    throw SceneError(where, "melanin multipliers must be finite and >= 0");
  for (int k = 0; k < levels_; ++k) {
    const double root = levels_ == 1 ? rootLo_ : rootLo_ + (rootHi_ - rootLo_) * k / (levels_ - 1);
    levelMultipliers_.push_back(k == 0 ? lo_ : k == levels_ - 1 ? hi_ : root * root);
  }
  std::vector<skin::Specimen> specimens;
  for (int k = 0; k < levels_; ++k) {
    specimens.push_back(scaleMelanin(specimen, levelMultiplier(k)));
    try {
      skin::validateSpecimen(specimens.back());
    } catch (const std::exception& e) {
      throw SceneError(where, "specimen '" + specimen.name + "' with melanin × " +
                                  std::to_string(levelMultiplier(k)) +
                                  " is not valid: " + e.what());
    }
  }
  // A wavelength shared by several channels (overlapping bands) is prepared once.
  std::vector<double> distinct;
  for (double w : channelWavelengths) {
    const auto at = std::find(distinct.begin(), distinct.end(), w);
    distinctOfChannel_.push_back(static_cast<std::size_t>(at - distinct.begin()));
    if (at == distinct.end()) distinct.push_back(w);
  }
  distinctWavelengths_ = distinct.size();
  walks_.resize(static_cast<std::size_t>(levels_) * distinctWavelengths_);
  std::mutex errorMutex;
  std::string error;
  if (effectTolerance > 0 && bundles.empty()) {
    plans_.resize(distinctWavelengths_);
    tbb::parallel_for(std::size_t{0}, distinctWavelengths_, [&](std::size_t c) {
      try {
        plans_[c] =
            planChannel(specimens.front(), specimens.back(), spectra, distinct[c], effectTolerance);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(errorMutex);
        if (error.empty()) error = e.what();
      }
    });
    if (!error.empty()) throw SceneError(where, "skin specimen '" + specimen.name + "': " + error);
  }
  tbb::parallel_for(std::size_t{0}, walks_.size(), [&](std::size_t i) {
    const std::size_t k = i / distinctWavelengths_, c = i % distinctWavelengths_;
    try {
      const skin::SkinOptics optics = skin::computeSkinOptics(specimens[k], spectra, distinct[c]);
      if (plans_.empty())
        walks_[i].emplace(optics);
      else
        walks_[i].emplace(plans_[c].apply(optics), plans_[c].walk);
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (error.empty()) error = e.what();
    }
  });
  if (!error.empty()) throw SceneError(where, "skin specimen '" + specimen.name + "': " + error);
  bundleCount_ = bundles.size();
  spectralWalks_.resize(static_cast<std::size_t>(levels_) * bundleCount_);
  skin::WalkOptions spectral;
  spectral.tabulatedMelanosomes = true;  // internal melanosome paths drawn from a 2¹⁸-path table
  spectral.layerAbsorption = false;      // a render needs the exit weights only
  tbb::parallel_for(std::size_t{0}, spectralWalks_.size(), [&](std::size_t i) {
    const std::size_t k = i / bundleCount_, b = i % bundleCount_;
    try {
      std::vector<skin::SkinOptics> optics;
      for (std::size_t channel : bundles[b])
        optics.push_back(
            skin::computeSkinOptics(specimens[k], spectra, channelWavelengths.at(channel)));
      spectralWalks_[i].emplace(optics, spectral);
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (error.empty()) error = e.what();
    }
  });
  if (!error.empty()) throw SceneError(where, "skin specimen '" + specimen.name + "': " + error);
}

const skin::SpectralWalk& SkinWalkCache::spectralWalk(std::size_t bundle, int level) const {
  return *spectralWalks_.at(static_cast<std::size_t>(level) * bundleCount_ + bundle);
}

double SkinWalkCache::levelMultiplier(int level) const {
  return levelMultipliers_.at(static_cast<std::size_t>(level));
}

int SkinWalkCache::level(double multiplier, double u) const {
  if (levels_ == 1) return 0;
  const double m = std::clamp(multiplier, lo_, hi_);
  const double t = (std::sqrt(m) - rootLo_) / (rootHi_ - rootLo_) * (levels_ - 1);
  const int below = std::clamp(static_cast<int>(t), 0, levels_ - 2);
  const double mBelow = levelMultipliers_[static_cast<std::size_t>(below)];
  const double mAbove = levelMultipliers_[static_cast<std::size_t>(below) + 1];
  return u < (m - mBelow) / (mAbove - mBelow) ? below + 1 : below;  // linear in m between them
}

std::string SkinWalkCache::explainEffectPlans() const {
  if (plans_.empty()) return "  effect planning off (epsilon = 0): every process simulated\n";
  std::string text;
  for (const skin::EffectPlan& plan : plans_)
    text += plans_.size() <= 4 ? plan.explain() : "  " + plan.summary();
  return text;
}

const skin::SkinWalk& SkinWalkCache::walk(std::size_t channel, int level) const {
  return *walks_[static_cast<std::size_t>(level) * distinctWavelengths_ +
                 distinctOfChannel_[channel]];
}

}  // namespace hylios
