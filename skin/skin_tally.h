// Tallies of HyLIoS walks: reflectance (total, surface, subsurface), transmittance, absorptance
// per layer, with standard errors; optionally exit-direction and radial exit-offset histograms.
// Mergeable in a fixed order, so parallel runs give identical results at any thread count.
#pragma once
#include <array>
#include <cstddef>
#include <optional>

#include "skin/layer.h"
#include "skin/skin_walk.h"
#include "skin/statistics.h"

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

  std::uint64_t rays() const { return total_.count(); }
  Estimate reflectance() const { return total_.estimate(); }
  Estimate surfaceReflectance() const { return surface_.estimate(); }
  Estimate subsurfaceReflectance() const { return subsurface_.estimate(); }
  Estimate transmittance() const { return transmitted_.estimate(); }
  Estimate absorptance() const { return absorbed_.estimate(); }
  Estimate absorptance(Layer layer) const { return absorbedByLayer_[index(layer)].estimate(); }
  Estimate melanosomeAbsorptance() const { return melanosomeAbsorbed_.estimate(); }
  /// Rays that hit SkinWalk::kMaxEvents (reported, never folded into another quantity).
  Estimate eventLimited() const { return eventLimited_.estimate(); }
  double meanEvents() const { return events_.mean(); }

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
  TallyOptions options_;
  RunningStatistic total_, surface_, subsurface_, transmitted_, absorbed_, melanosomeAbsorbed_, eventLimited_, events_;
  std::array<RunningStatistic, kLayerCount> absorbedByLayer_;
  std::optional<Histogram> surfaceDirections_, subsurfaceDirections_, transmittedDirections_, radialExits_;
};

}  // namespace hylios::skin
