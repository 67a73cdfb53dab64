// How much of a skin material each of its melanin levels covers (table mode), estimated before
// any ray from the material's own descriptions: the melanin map's texels uniformly over UV, the
// freckle field at points uniformly over a plane (the field's density is defined on a locally flat
// surface, renderer/tracing/freckle_field.h), their product rounded to a level as the render
// rounds it (SkinWalkCache::level). A level covering a small share of the skin gets fewer walks
// per table bin (levelRayShares, SkinTableCache): its tables' error touches only that share.
#pragma once
#include <cstddef>
#include <vector>

#include "renderer/scene/texture_map.h"
#include "renderer/tracing/freckle_field.h"
#include "renderer/tracing/skin_walk_cache.h"

namespace hylios {

/// Sample points of melaninLevelUse.
inline constexpr std::size_t kMelaninUseSamples = std::size_t{1} << 16;
/// The fewest walks a level keeps, as a share of the table's N (error at most ×2 per bin).
inline constexpr double kMinLevelRayShare = 0.25;

/// The share of the skin at each of walks.levels() levels (sums to 1): multiplier m = (mapMin +
/// (mapMax − mapMin)·texel) × freckles(point), without a map m = freckles(point). `samples`
/// points on fixed streams: the same shares in every run.
std::vector<double> melaninLevelUse(const SkinWalkCache& walks, const TextureMap* map,
                                    double mapMin, double mapMax, const FreckleField& freckles,
                                    std::size_t samples = kMelaninUseSamples);

/// Walks per bin of each level as a share of N: √(use / largest use), at least kMinLevelRayShare
/// (the most used level keeps N). The mean squared table error of a render, Σ_l use_l·σ²/N_l, is
/// least for a given total of walks when N_l ∝ √use_l.
std::vector<double> levelRayShares(const std::vector<double>& use);

}  // namespace hylios
