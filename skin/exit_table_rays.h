// How many walks each cosine bin of an exit table gets (ExitTableSettings::raysByUse).
//
// A table's bin k holds the walks that start inside the skin along μ_k = (k + 1)/K
// (skin/exit_table.h), and a ray from air uses the bins around its transmitted cosine μ_t. Snell's
// law keeps μ_t of a smooth surface above √(1 − 1/n²) ≈ 0.76 (n ≈ 1.55), so the low bins are
// reached only through the rough surface's tilted facets: on S1 (s = 0.1) bins 0–6 together take
// 1.5 % of a render's entries. Every bin built with the same N spends most of the walks where
// almost no ray goes.
//
// The rule: a bin's worst-case use u_k = max over incidence angles θ of P(bin k | θ, entered) is
// estimated from entries through the walk's own rough surface (SkinWalk::enterFromAir, the
// interpolation weights of ExitTable::chooseBin, kUseAngles angles, kUseEntriesPerAngle entries
// each on fixed random streams), and bin k gets
//     N_k = ceil(N · clamp((u_k / kFullUse)², kLeastRaysFraction, 1))
// walks: the first N_k of the walks the bin would get with N. A bin that some incidence uses with
// probability ≥ kFullUse keeps all N. The errors of different bins are independent, so a ray at θ
// sees table noise of variance Σ_k u_k(θ)² σ²/N_k; for a reduced bin u_k(θ)²/N_k ≤ kFullUse²/N,
// a small addition to the full bins' Σ u_k²/N (docs/interpretations.md, "Walks per cosine bin",
// gives the measured worst case). The allocation is a cost choice only: every bin's estimates stay
// exact in expectation, from fewer walks.
#pragma once
#include <cstdint>
#include <vector>

#include "skin/skin_walk.h"

namespace hylios::skin {

/// A bin some incidence uses at least this often keeps every walk.
inline constexpr double kFullUse = 0.1;
/// The fewest walks a bin keeps, as a fraction of N.
inline constexpr double kLeastRaysFraction = 1.0 / 64;
/// Incidence angles (θ_g = 90° (g + ½)/kUseAngles) and entries per angle of the use estimate.
inline constexpr int kUseAngles = 24;
inline constexpr int kUseEntriesPerAngle = 2000;

/// Worst-case use of each of `cosineBins` bins over incidence from air, through `walk`'s surface.
/// Deterministic (its own random streams, `seed`).
std::vector<double> worstCaseBinUse(const SkinWalk& walk, int cosineBins, std::uint64_t seed);

/// N_k for each bin from the worst-case use (the rule above); each in [2, raysPerBin].
std::vector<std::uint64_t> raysByUse(const std::vector<double>& worstUse, std::uint64_t raysPerBin);

}  // namespace hylios::skin
