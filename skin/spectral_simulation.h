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
  /// WalkOptions::splitFirstRayleigh in the bundles where Algorithm 2's θo is 0 (≥ 1400 nm):
  /// there a path's course after the event is a few straight flights, and the split halves the
  /// variance of the water bands for 1.3× the time; where θo > 0 the course goes on through tens
  /// of melanosome deflections and the split doubles the time for the same halving (docs/
  /// benchmarks.md, session 22). Needs tallies without histograms.
  bool splitRayleighWithoutDeflection = false;
};

/// The spectral estimator as the commands and the Python module run it (spectrum, brdf, the
/// profiles): run's incidence, rays, seed, walk and tally, with each melanosome's internal path
/// drawn from the path-length table, the surface reflection at entry scored as an expected
/// value, heroes in shares by law (WalkOptions::heroSharesByLaw), bundles bounded to a Rayleigh
/// spread of 2.6, a θo spread of 0.6 and 96 members (skin/spectral_bundle.h), no melanosome
/// absorptance (WalkOptions::melanosomeAbsorption: no command prints it), and, without
/// histograms, paths split at their first Rayleigh event where θo = 0 (SpectralRunOptions::
/// splitRayleighWithoutDeflection).
SpectralRunOptions commandSpectralRun(const WalkRunOptions& run);

/// The random stream of a bundle: a mix of its wavelengths' streams (skin_simulation.h).
std::uint64_t bundleStream(const std::vector<double>& wavelengthsNm);

/// One tally per entry of `optics` (same order). Throws std::invalid_argument for an incidence
/// outside [0°, 90°), zero rays, or optics that cannot share paths (skin/spectral_walk.h).
std::vector<SkinTally> simulateSkinSpectral(const std::vector<SkinOptics>& optics,
                                            const SpectralRunOptions& options);

/// The same run in its fixed chunks, for launchers that divide the chunks among processes
/// (app/mpi_spectral.h): chunk c (paths [first, last) of one bundle, in bundle order) is run only
/// when c % parts == part. mergeSpectralChunks of the chunks of every part, put together, is
/// exactly what simulateSkinSpectral returns (the same merge in chunk order).
struct SpectralChunks {
  std::vector<std::vector<std::size_t>> members;  ///< per chunk: its bundle's indices into optics
  std::vector<std::vector<SkinTally>> tallies;    ///< per chunk: one per member; empty if not run
};
SpectralChunks simulateSkinSpectralChunks(const std::vector<SkinOptics>& optics,
                                          const SpectralRunOptions& options, std::size_t part = 0,
                                          std::size_t parts = 1);
/// Merges every chunk's tallies in chunk order into one tally per optics entry (`count` of them);
/// throws std::invalid_argument when a chunk was not run.
std::vector<SkinTally> mergeSpectralChunks(const SpectralChunks& chunks, std::size_t count,
                                           const TallyOptions& tally);

}  // namespace hylios::skin
