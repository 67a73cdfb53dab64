// Runs spectral walks (skin/spectral_walk.h) for one specimen over many wavelengths, in parallel
// and deterministically: the wavelengths are grouped into bundles (skin/spectral_bundle.h), path i
// of a bundle uses Rng(seed, bundleStream(bundle), i), and paths are grouped in fixed-size chunks
// merged in chunk order, so results are identical at any thread count. Every wavelength gets
// `rays` paths (its weight from each path of its bundle).
#pragma once
#include <cstdint>
#include <vector>

#include "skin/skin_simulation.h"
#include "skin/spectral_bundle.h"

namespace hylios::skin {

struct SpectralRunOptions {
  double incidenceDeg = 0;  ///< polar angle of the incident ray from the surface normal, [0, 90)
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  WalkOptions walk;
  TallyOptions tally;
  BundleRule bundles;
};

/// The spectral estimator as the commands and the Python module run it (spectrum, brdf, the
/// profiles): run's incidence, rays, seed, walk and tally, with each melanosome's internal path
/// drawn from the path-length table and the surface reflection at entry scored as an expected
/// value.
SpectralRunOptions commandSpectralRun(const WalkRunOptions& run);

/// The random stream of a bundle: a mix of its wavelengths' streams (skin_simulation.h).
std::uint64_t bundleStream(const std::vector<double>& wavelengthsNm);

/// One tally per entry of `optics` (same order). Throws std::invalid_argument for an incidence
/// outside [0°, 90°), zero rays, or optics that cannot share paths (skin/spectral_walk.h).
std::vector<SkinTally> simulateSkinSpectral(const std::vector<SkinOptics>& optics,
                                            const SpectralRunOptions& options);

}  // namespace hylios::skin
