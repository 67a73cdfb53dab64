#include "skin/skin_tally.h"

#include <algorithm>
#include <cmath>

namespace hylios::skin {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

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
  const double azimuth = std::atan2(exitDirection.y, exitDirection.x);      // [-π, π]
  auto bin = [](double value, double lower, double upper, std::size_t count) {
    const auto b = static_cast<std::size_t>((value - lower) / (upper - lower) * static_cast<double>(count));
    return std::min(b, count - 1);
  };
  return bin(polar, 0.0, kPi / 2, options_.polarBins) * options_.azimuthBins +
         bin(azimuth, -kPi, kPi, options_.azimuthBins);
}

Estimate SkinTally::binomial(std::uint64_t count) const {
  if (rays_ == 0) return {0.0, 0.0};
  const double n = static_cast<double>(rays_);
  const double m = static_cast<double>(count) / n;
  if (rays_ < 2) return {m, 0.0};
  const double variance = std::fmax(0.0, m - m * m);  // E[x²] = E[x] for 0/1 scores
  return {m, std::sqrt(variance / (n - 1.0))};
}

void SkinTally::record(const SkinPath& path) {
  const bool surface = path.end == PathEnd::SurfaceReflection;
  const bool subsurface = path.end == PathEnd::SubsurfaceReflection;
  const bool transmitted = path.end == PathEnd::Transmitted;
  const bool absorbed = path.end == PathEnd::Absorbed;
  ++rays_;
  surface_ += surface;
  subsurface_ += subsurface;
  transmitted_ += transmitted;
  absorbed_ += absorbed;
  melanosomeAbsorbed_ += absorbed && path.absorbedInMelanosome;
  eventLimited_ += path.end == PathEnd::EventLimit;
  events_ += path.events;
  if (absorbed) ++absorbedByLayer_[index(path.layer)];
  if (surfaceDirections_) {
    surfaceDirections_->countPacket();
    subsurfaceDirections_->countPacket();
    transmittedDirections_->countPacket();
    if (surface) surfaceDirections_->addToBin(directionBin(path.exitDirection), 1.0);
    if (subsurface) subsurfaceDirections_->addToBin(directionBin(path.exitDirection), 1.0);
    if (transmitted) transmittedDirections_->addToBin(directionBin(path.exitDirection), 1.0);
  }
  if (radialExits_) {
    radialExits_->countPacket();
    if (subsurface) radialExits_->add(std::hypot(path.exitOffsetXCm, path.exitOffsetYCm), 1.0);
  }
}

void SkinTally::merge(const SkinTally& other) {
  rays_ += other.rays_;
  surface_ += other.surface_;
  subsurface_ += other.subsurface_;
  transmitted_ += other.transmitted_;
  absorbed_ += other.absorbed_;
  melanosomeAbsorbed_ += other.melanosomeAbsorbed_;
  eventLimited_ += other.eventLimited_;
  events_ += other.events_;
  for (std::size_t i = 0; i < kLayerCount; ++i) absorbedByLayer_[i] += other.absorbedByLayer_[i];
  if (surfaceDirections_) {
    surfaceDirections_->merge(*other.surfaceDirections_);
    subsurfaceDirections_->merge(*other.subsurfaceDirections_);
    transmittedDirections_->merge(*other.transmittedDirections_);
  }
  if (radialExits_) radialExits_->merge(*other.radialExits_);
}

}  // namespace hylios::skin
