// Tallies of HyLIoS walks: reflectance (total, surface, subsurface), transmittance, absorptance
// per layer, with standard errors; optionally exit-direction and radial exit-offset histograms.
// Mergeable in a fixed order, so parallel runs give identical results at any thread count.
// Scores that carry a control weight (a spectral path's MIS ratio, E = 1 exactly) give the scalar
// quantities as control-variate means (skin/core/controlled_means.h); the histograms stay plain
// per-path means.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "skin/core/controlled_means.h"
#include "skin/core/statistics.h"
#include "skin/layer.h"
#include "skin/skin_walk.h"

namespace hylios::skin {

/// Which histograms to keep. Directions: exit polar angle θ in [0°, 90°] (from the surface
/// normal) × azimuth φ in [-180°, 180°) measured from the forward direction of the incident ray
/// (φ = 0: the specular side). Radial: subsurface exit distance from the entry point.
struct TallyOptions {
  std::size_t polarBins = 0;  ///< 0: no direction histograms
  std::size_t azimuthBins = 1;
  std::size_t radialBins = 0;  ///< 0: no radial histogram
  double maxRadiusCm = 0.5;
};

/// One path's scores for one wavelength: the analog walk's 0/1 outcomes, or a spectral walk's
/// weights (skin/spectral_walk.h). exitWeight leaves along exitDirection at the exit offset.
struct PathScore {
  PathEnd end = PathEnd::EventLimit;
  Vec3 exitDirection;
  double exitOffsetXCm = 0, exitOffsetYCm = 0;
  double exitWeight = 0;     ///< reflected, transmitted or event-limited
  double surfaceWeight = 0;  ///< reflected at entry by a path that went on (expected value)
  Vec3 surfaceDirection;
  double absorbed = 0;                                ///< total absorbed (all layers)
  std::array<double, kLayerCount> absorbedByLayer{};  ///< per layer (zeros when not booked)
  double absorbedInMelanosomes = 0;
  std::uint32_t events = 0;
  /// A weight with expectation exactly 1 whose fluctuation the scores share (the spectral walk's
  /// MIS ratio plus its split-entry surface weight); none for analog paths.
  bool hasControlWeight = false;
  double controlWeight = 1;
  unsigned fold = 0;  ///< 0 or 1: the path's parity (ControlledMeans' cross-fitting)
};

/// A score with the shared part of a path's outcome (end, exit direction and offset, events)
/// copied from any path type that has those fields (SkinPath, SpectralPath).
template <class Path>
PathScore pathScoreOf(const Path& path) {
  PathScore score;
  score.end = path.end;
  score.exitDirection = path.exitDirection;
  score.exitOffsetXCm = path.exitOffsetXCm;
  score.exitOffsetYCm = path.exitOffsetYCm;
  score.events = path.events;
  return score;
}

class SkinTally {
 public:
  /// The scalar quantities, in this order (ControlledMeans' quantity k; absorptance per layer at
  /// kFirstLayer + index(layer)).
  enum Quantity : std::size_t {
    kTotal,
    kSurface,
    kSubsurface,
    kTransmitted,
    kAbsorbed,
    kMelanosome,
    kEventLimited,
    kFirstLayer
  };
  static constexpr std::size_t kQuantities = kFirstLayer + kLayerCount;

  explicit SkinTally(const TallyOptions& options = {});
  /// The tally of control-weighted paths whose scalar sums are `means` (kQuantities quantities)
  /// and whose events add up to `events`, as recording them one by one would have made it
  /// (skin/spectral_bundle_tally.h). Throws std::invalid_argument for options with histograms
  /// (they are not in `means`) or another quantity count.
  static SkinTally fromControlledMeans(const TallyOptions& options, ControlledMeans means,
                                       std::uint64_t events);
  /// An analog path: weight 1 to its one outcome.
  void record(const SkinPath& path);
  /// A weighted path (every quantity scores, zeros included; standard errors from the scores).
  /// Every score of a tally carries a control weight or none does (std::logic_error otherwise).
  void record(const PathScore& score);
  /// std::logic_error when one tally has control weights and the other has paths without.
  void merge(const SkinTally& other);
  /// Appends the tally's exact state (sums, counts, histograms; native byte order) to `bytes`, for
  /// a tally computed in another process of the same machine type (app/mpi_session.h).
  void appendBytes(std::string& bytes) const;
  /// The tally appendBytes wrote at `offset` of `bytes` (offset is moved past it), for tallies of
  /// `options`. Throws std::invalid_argument when the bytes are too short for them.
  static SkinTally fromBytes(const TallyOptions& options, const std::string& bytes,
                             std::size_t& offset);

  std::uint64_t rays() const { return controlled_ ? controlled_->count() : plain_[kTotal].count(); }
  Estimate reflectance() const { return estimateOf(kTotal); }
  Estimate surfaceReflectance() const { return estimateOf(kSurface); }
  Estimate subsurfaceReflectance() const { return estimateOf(kSubsurface); }
  Estimate transmittance() const { return estimateOf(kTransmitted); }
  Estimate absorptance() const { return estimateOf(kAbsorbed); }
  Estimate absorptance(Layer layer) const { return estimateOf(kFirstLayer + index(layer)); }
  Estimate melanosomeAbsorptance() const { return estimateOf(kMelanosome); }
  /// Rays that hit SkinWalk::kMaxEvents (reported, never folded into another quantity).
  Estimate eventLimited() const { return estimateOf(kEventLimited); }
  /// Whether the scalar estimates are control-variate means (the scores carried control weights).
  bool controlled() const { return controlled_.has_value(); }
  double meanEvents() const {
    return rays() == 0 ? 0.0 : static_cast<double>(events_) / static_cast<double>(rays());
  }
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
  /// Per-path scores of analog paths (0/1: sums of 1.0 are exact, so merging stays order-free),
  /// or, for scores with control weights, the control-variate means (one of the two is used).
  std::array<RunningStatistic, kQuantities> plain_{};
  std::optional<ControlledMeans> controlled_;
  Estimate estimateOf(std::size_t k) const {
    return controlled_ ? controlled_->estimate(k) : plain_[k].estimate();
  }
  std::uint64_t events_ = 0;
  std::optional<Histogram> surfaceDirections_, subsurfaceDirections_, transmittedDirections_,
      radialExits_;
};

}  // namespace hylios::skin
