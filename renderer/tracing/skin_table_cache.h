// Exit tables (skin/exit_table.h) for the `table` skin mode: one per film channel and melanin level
// of a skin material's SkinWalkCache, obtained from an ExitTableCache (loaded from disk or built,
// in parallel) before the first ray.
//
// Table mode uses kTableMelaninLevels levels instead of SkinWalkCache::kMelaninLevels: the
// stochastic rounding between levels already interpolates the response linearly in the multiplier
// (skin_walk_cache.h), and every level costs channels × K × N walks to build.
//
// With spectral building (the spectral estimator, issue 11) the channels of a level are grouped by
// the bundle rule (skin/spectral_bundle.h) and every bundle's tables come from one set of
// spectral walks (ExitTable::buildBundle): levels × bundles × K × N walks in all instead of levels
// × channels × K × N. The walks must then be the full model (no effect plan). A render samples a
// band's tables at once (skin/exit_table_bundle.h, SkinMaterial).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"
#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/skin_walk_cache.h"
#include "skin/exit_table.h"

namespace hylios {

class SkinTableCache {
 public:
  static constexpr int kTableMelaninLevels = 7;
  /// The settings the renderer builds its tables with (K = 12 cosine bins, N = 10 000 rays per
  /// bin by default: a table's sampling error, 1–2 % of P(subsurface) per bin, is a fixed bias of
  /// the render: a few tenths of a percent where many bins share the image, up to ≈ 3 % per
  /// channel under a narrow light facing the camera; docs/interpretations.md, "Render tables").
  /// Bins that rays from air seldom reach get fewer walks (ExitTableSettings::raysByUse,
  /// skin/exit_table_rays.h). `raysPerBin`: the scene's integrator.table_rays_per_bin.
  static skin::ExitTableSettings renderSettings(std::uint64_t raysPerBin = kDefaultTableRaysPerBin);
  /// The settings of a reflectance curve's tables (`spectrum --skin-model table`, Python): K = 12,
  /// N = 40 000 rays per bin, since a curve has no per-pixel noise to hide a table's error in.
  static skin::ExitTableSettings curveSettings();

  /// `levelRayShares` (empty: 1 for every level; else one share in (0, 1] per level of `walks`):
  /// level l's tables get ⌈share_l·N⌉ walks per bin (at least 2), N = settings.raysPerBin
  /// (melanin_level_use.h). Throws std::invalid_argument for a wrong count or share.
  SkinTableCache(const SkinWalkCache& walks, ExitTableCache& cache,
                 const skin::ExitTableSettings& settings, bool spectralBuild = false,
                 const std::vector<double>& levelRayShares = {});

  /// N of each melanin level's tables (walks per bin before the cosine bins' thinning).
  const std::vector<std::uint64_t>& raysPerBinByLevel() const { return raysPerBinByLevel_; }
  /// "x<multiplier> <N>, …" for each level of `walks` (the cache's own), for the render's log.
  std::string describeRaysPerBin(const SkinWalkCache& walks) const;

  const skin::ExitTable& table(std::size_t channel, int level) const {
    return *tables_[static_cast<std::size_t>(level) * channels_ + channel];
  }

 private:
  std::size_t channels_;
  std::vector<std::uint64_t> raysPerBinByLevel_;
  std::vector<std::shared_ptr<const skin::ExitTable>> tables_;  ///< [level * channels + channel]
};

}  // namespace hylios
