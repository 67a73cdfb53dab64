#include "skin/skin_tally.h"

#include <algorithm>
#include <cmath>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {}

SkinTally::SkinTally(const TallyOptions& options) : options_(options) {
  if (options.polarBins > 0) {
    const double bins = static_cast<double>(options.polarBins * options.azimuthBins);
    surfaceDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
    subsurfaceDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
    transmittedDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
  }
  if (options.radialBins > 0) radialExits_.emplace(0.0, options.maxRadiusCm, options.radialBins);
}

std::size_t SkinTally::directionBin(const Vec3& exitDirection) const {
  const double polar = std::acos(std::clamp(std::fabs(exitDirection.z), 0.0, 1.0));  // [0, π/2]
  const double azimuth = std::atan2(exitDirection.y, exitDirection.x);               // [-π, π]
  auto bin = [](double value, double lower, double upper, std::size_t count) {
    const auto b =
        static_cast<std::size_t>((value - lower) / (upper - lower) * static_cast<double>(count));
    return std::min(b, count - 1);
  };
  return bin(polar, 0.0, kPi / 2, options_.polarBins) * options_.azimuthBins +
         bin(azimuth, -kPi, kPi, options_.azimuthBins);
}

void SkinTally::record(const SkinPath& path) {
  PathScore score = pathScoreOf(path);
  const bool absorbed = path.end == PathEnd::Absorbed;
  score.exitWeight = absorbed ? 0.0 : 1.0;
  if (absorbed) {
    score.absorbed = 1.0;
    score.absorbedByLayer[index(path.layer)] = 1.0;
    score.absorbedInMelanosomes = path.absorbedInMelanosome ? 1.0 : 0.0;
  }
  record(score);
}

void SkinTally::record(const PathScore& score) {
  const double w = score.exitWeight;
  const bool surface = score.end == PathEnd::SurfaceReflection;
  const bool subsurface = score.end == PathEnd::SubsurfaceReflection;
  const bool transmitted = score.end == PathEnd::Transmitted;
  const double sw = score.surfaceWeight;
  total_.add((surface || subsurface ? w : 0.0) + sw);
  surface_.add((surface ? w : 0.0) + sw);
  subsurface_.add(subsurface ? w : 0.0);
  transmitted_.add(transmitted ? w : 0.0);
  eventLimited_.add(score.end == PathEnd::EventLimit ? w : 0.0);
  for (std::size_t i = 0; i < kLayerCount; ++i) absorbedByLayer_[i].add(score.absorbedByLayer[i]);
  absorbed_.add(score.absorbed);
  melanosomeAbsorbed_.add(score.absorbedInMelanosomes);
  events_ += score.events;
  if (surfaceDirections_) {
    surfaceDirections_->countPacket();
    subsurfaceDirections_->countPacket();
    transmittedDirections_->countPacket();
    if (surface) surfaceDirections_->addToBin(directionBin(score.exitDirection), w);
    if (sw != 0) surfaceDirections_->addToBin(directionBin(score.surfaceDirection), sw);
    if (subsurface) subsurfaceDirections_->addToBin(directionBin(score.exitDirection), w);
    if (transmitted) transmittedDirections_->addToBin(directionBin(score.exitDirection), w);
  }
  if (radialExits_) {
    radialExits_->countPacket();
    if (subsurface) radialExits_->add(std::hypot(score.exitOffsetXCm, score.exitOffsetYCm), w);
  }
}

void SkinTally::merge(const SkinTally& other) {
  for (auto [mine, theirs] : {std::pair{&total_, &other.total_},
                              {&surface_, &other.surface_},
                              {&subsurface_, &other.subsurface_},
                              {&transmitted_, &other.transmitted_},
                              {&absorbed_, &other.absorbed_},
                              {&melanosomeAbsorbed_, &other.melanosomeAbsorbed_},
                              {&eventLimited_, &other.eventLimited_}})
    mine->merge(*theirs);
  for (std::size_t i = 0; i < kLayerCount; ++i)
    absorbedByLayer_[i].merge(other.absorbedByLayer_[i]);
  events_ += other.events_;
  if (surfaceDirections_) {
    surfaceDirections_->merge(*other.surfaceDirections_);
    subsurfaceDirections_->merge(*other.subsurfaceDirections_);
    transmittedDirections_->merge(*other.transmittedDirections_);
  }
  if (radialExits_) radialExits_->merge(*other.radialExits_);
}

}  // namespace hylios::skin
