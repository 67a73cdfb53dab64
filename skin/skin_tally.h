// Tallies of HyLIoS walks: reflectance (total, surface, subsurface), transmittance, absorptance
// per layer, with standard errors; optionally exit-direction and radial exit-offset histograms.
// Mergeable in a fixed order, so parallel runs give identical results at any thread count.
#pragma once
#include <array>
#include <cstddef>
#include <optional>

#include "skin/layer.h"
#include "skin/skin_walk.h"
#include "skin/core/statistics.h"

namespace hylios::skin {

/// Which histograms to keep. Directions: exit polar angle θ in [0°, 90°] (from the surface
/// normal) × azimuth φ in [-180°, 180°) measured from the forward direction of the incident ray
/// (φ = 0: the specular side). Radial: subsurface exit distance from the entry point.
struct TallyOptions {
  std::size_t polarBins = 0;    ///< 0: no direction histograms
  std::size_t azimuthBins = 1;
  std::size_t radialBins = 0;   ///< 0: no radial histogram
  double maxRadiusCm = 0.5;
};

class SkinTally {
 public:
  explicit SkinTally(const TallyOptions& options = {});

  void record(const SkinPath& path);
  void merge(const SkinTally& other);

  std::uint64_t rays() const { return rays_; }
  Estimate reflectance() const { return binomial(surface_ + subsurface_); }
  Estimate surfaceReflectance() const { return binomial(surface_); }
  Estimate subsurfaceReflectance() const { return binomial(subsurface_); }
  Estimate transmittance() const { return binomial(transmitted_); }
  Estimate absorptance() const { return binomial(absorbed_); }
  Estimate absorptance(Layer layer) const { return binomial(absorbedByLayer_[index(layer)]); }
  Estimate melanosomeAbsorptance() const { return binomial(melanosomeAbsorbed_); }
  /// Rays that hit SkinWalk::kMaxEvents (reported, never folded into another quantity).
  Estimate eventLimited() const { return binomial(eventLimited_); }
  double meanEvents() const { return rays_ == 0 ? 0.0 : static_cast<double>(events_) / static_cast<double>(rays_); }

  const TallyOptions& options() const { return options_; }
  /// Fraction of rays per direction bin (flattened: polar-major), for surface or subsurface exits.
  const std::optional<Histogram>& surfaceDirections() const { return surfaceDirections_; }
  const std::optional<Histogram>& subsurfaceDirections() const { return subsurfaceDirections_; }
  /// The same for rays transmitted through a truncated stack (polar angle measured from +z).
  const std::optional<Histogram>& transmittedDirections() const { return transmittedDirections_; }
  /// Fraction of rays per radial bin of subsurface exits.
  const std::optional<Histogram>& radialExits() const { return radialExits_; }
  /// Flattened bin of an exit direction for the direction histograms (polar angle from the
  /// outward normal on its side: −z for reflection, +z for transmission).
  std::size_t directionBin(const Vec3& exitDirection) const;

 private:
  /// Mean and standard error of a 0/1 score that was 1 for `count` of the rays: the
  /// RunningStatistic formula sqrt((E[x²] − E[x]²)/(N − 1)) with E[x²] = E[x] = count/N.
  Estimate binomial(std::uint64_t count) const;

  TallyOptions options_;
  // Each ray ends one way, so the outcomes are integer counts (exact, order-free merging).
  std::uint64_t rays_ = 0, surface_ = 0, subsurface_ = 0, transmitted_ = 0, absorbed_ = 0,
                melanosomeAbsorbed_ = 0, eventLimited_ = 0, events_ = 0;
  std::array<std::uint64_t, kLayerCount> absorbedByLayer_{};
  std::optional<Histogram> surfaceDirections_, subsurfaceDirections_, transmittedDirections_, radialExits_;
};

}  // namespace hylios::skin
