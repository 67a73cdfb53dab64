// The skin studies (spectrum, brdf, radial-profile, sweep cases) divided among MPI ranks
// (app/mpi_session.h) with the decomposition of one process: the spectral estimator's fixed
// chunks (skin/spectral_simulation.h) go to rank c % size, per-wavelength work to rank i % size;
// rank 0 gets every chunk's tallies and merges them in chunk order, so its tallies are those of
// the one-process run bit for bit. Without distribution these are the one-process calls.
#pragma once
#include <cstddef>
#include <vector>

#include "skin/skin_tally.h"
#include "skin/spectral_simulation.h"

namespace hylios {

/// skin::simulateSkinSpectral across the ranks: the whole result on rank 0, empty tallies (of
/// options.tally) elsewhere.
std::vector<skin::SkinTally> simulateSkinSpectralOnRanks(
    const std::vector<skin::SkinOptics>& optics, const skin::SpectralRunOptions& options);

/// Whether this rank computes item `i` of a list divided among the ranks (i % size == rank).
bool rankOwnsItem(std::size_t i);

/// Puts together on rank 0 the tallies each rank computed for the items it owns (rankOwnsItem);
/// the other entries of `tallies` are ignored, and on the other ranks `tallies` is left as is.
void gatherOwnedTallies(std::vector<skin::SkinTally>& tallies, const skin::TallyOptions& options);

}  // namespace hylios
