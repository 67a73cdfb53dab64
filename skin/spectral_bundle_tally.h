// The tallies of one bundle's wavelengths over spectral paths (skin/spectral_walk.h): path number
// `ray` scores for every wavelength, each score with its control weight U = the MIS ratio plus the
// split entry's surface weight (expectation exactly 1), cross-fitted by the ray's parity
// (skin/core/controlled_means.h).
//
// Without histograms (TallyOptions with no direction or radial bins: the curves of `spectrum`),
// the scalar sums of all wavelengths are kept in arrays (skin/core/controlled_means_array.h) and a
// path is recorded by a few vectorised loops over the wavelengths, instead of one SkinTally::record
// per wavelength; tallies() gives exactly the tallies the per-wavelength records would have made
// (the same sums in the same order). With histograms every wavelength keeps its own SkinTally.
// A path split at a Rayleigh event (SpectralPath::split) is one sample: its branches' scores and
// control weights are added (scalar tallies only).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "skin/core/controlled_means_array.h"
#include "skin/skin_tally.h"
#include "skin/spectral_walk.h"

namespace hylios::skin {

class SpectralBundleTally {
 public:
  SpectralBundleTally(std::size_t wavelengths, const TallyOptions& options);

  /// Records spectral path number `ray` (its arrays hold one value per wavelength; std::
  /// invalid_argument otherwise).
  void record(const SpectralPath& path, std::uint64_t ray);
  /// One tally per wavelength, in the bundle's order.
  std::vector<SkinTally> tallies() const;

 private:
  void recordEach(const SpectralPath& path, std::uint64_t ray);
  void recordSums(const SpectralPath& path, std::uint64_t ray);
  /// Quantity k's scores (SkinTally::Quantity) of one path or branch, in its arrays or `scratch`;
  /// null when they are 0 at every wavelength.
  const double* scoresOf(const SpectralPath& path, std::size_t k, double* scratch) const;

  TallyOptions options_;
  std::size_t wavelengths_;
  std::vector<SkinTally> each_;               ///< with histograms
  std::optional<ControlledMeansArray> sums_;  ///< without
  std::uint64_t events_ = 0;
  /// Per wavelength: U, one quantity's scores, and those of a split path's backward branch.
  std::vector<double> control_, score_, backwardScore_;
};

}  // namespace hylios::skin
