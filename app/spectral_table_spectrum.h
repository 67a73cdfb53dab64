// Table mode of `hylios spectrum` with the spectral estimator (issue 11): the wavelengths are
// grouped by the bundle rule (skin/spectral_bundle.h), each bundle's exit tables come from one set
// of spectral walks of the full model (ExitTable::buildBundle, cached in ExitTableCache::shared()
// with the renderer's table settings), and every wavelength's rays are then sampled from its own
// table, ray i on Rng(seed, wavelengthStream(λ), i) as in the per-wavelength table mode.
#pragma once
#include <cstdint>
#include <vector>

#include "skin/exit_table.h"
#include "skin/skin_optics.h"
#include "skin/skin_tally.h"

namespace hylios {

/// `rays` rays sampled from `table`, arriving at `incidenceDeg`, on the random streams of the
/// table's wavelength.
skin::SkinTally sampleTableTally(const skin::ExitTable& table, double incidenceDeg,
                                 std::uint64_t rays, std::uint64_t seed);

/// One tally per entry of `optics` (same order), from the bundles' spectral tables.
std::vector<skin::SkinTally> spectralTableTallies(const std::vector<skin::SkinOptics>& optics,
                                                  double incidenceDeg, std::uint64_t rays,
                                                  std::uint64_t seed);

}  // namespace hylios
