#include "renderer/tracing/skin_table_cache.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "skin/spectral_bundle.h"

namespace hylios {

skin::ExitTableSettings SkinTableCache::renderSettings(std::uint64_t raysPerBin) {
  skin::ExitTableSettings settings;
  settings.cosineBins = 12;
  settings.raysPerBin = raysPerBin;
  settings.raysByUse = true;  // a render's rays from air: the low bins get few walks
  return settings;
}

skin::ExitTableSettings SkinTableCache::curveSettings() {
  skin::ExitTableSettings settings = renderSettings();
  settings.raysPerBin = 40000;
  settings.raysByUse = false;  // a curve's number at any angle from equally built bins
  return settings;
}

namespace {
/// The settings of each level: `settings` with ⌈share·N⌉ walks per bin (at least 2).
std::vector<skin::ExitTableSettings> settingsByLevel(const skin::ExitTableSettings& settings,
                                                     int levels,
                                                     const std::vector<double>& shares) {
  if (!shares.empty() && shares.size() != static_cast<std::size_t>(levels))
    throw std::invalid_argument("SkinTableCache: " + std::to_string(shares.size()) +
                                " ray shares for " + std::to_string(levels) + " melanin levels");
  std::vector<skin::ExitTableSettings> byLevel(static_cast<std::size_t>(levels), settings);
  for (std::size_t l = 0; l < shares.size(); ++l) {
    if (!(shares[l] > 0 && shares[l] <= 1))
      throw std::invalid_argument("SkinTableCache: ray share " + std::to_string(shares[l]) +
                                  " of level " + std::to_string(l) + " is outside (0, 1]");
    const double rays = std::ceil(shares[l] * static_cast<double>(settings.raysPerBin));
    byLevel[l].raysPerBin = std::max<std::uint64_t>(2, static_cast<std::uint64_t>(rays));
  }
  return byLevel;
}
}  // namespace

SkinTableCache::SkinTableCache(const SkinWalkCache& walks, ExitTableCache& cache,
                               const skin::ExitTableSettings& settings, bool spectralBuild,
                               const std::vector<double>& levelRayShares)
    : channels_(walks.channels()) {
  const std::vector<skin::ExitTableSettings> byLevel =
      settingsByLevel(settings, walks.levels(), levelRayShares);
  for (const skin::ExitTableSettings& s : byLevel) raysPerBinByLevel_.push_back(s.raysPerBin);
  // Channels that share a wavelength share a walk (SkinWalkCache prepares each wavelength once):
  // fetch one table per distinct walk, so no table is built twice.
  std::vector<const skin::SkinWalk*> distinct;
  std::vector<int> levelOfDistinct;
  std::unordered_map<const skin::SkinWalk*, std::size_t> indexOfWalk;
  std::vector<std::size_t> distinctOfSlot;
  for (std::size_t i = 0; i < static_cast<std::size_t>(walks.levels()) * channels_; ++i) {
    const int level = static_cast<int>(i / channels_);
    const skin::SkinWalk* walk = &walks.walk(i % channels_, level);
    const auto [at, added] = indexOfWalk.emplace(walk, distinct.size());
    if (added) {
      distinct.push_back(walk);
      levelOfDistinct.push_back(level);
    }
    distinctOfSlot.push_back(at->second);
  }
  // The groups of distinct walks built together: single walks, or a level's bundles.
  std::vector<std::vector<std::size_t>> groups;
  if (!spectralBuild) {
    for (std::size_t d = 0; d < distinct.size(); ++d) groups.push_back({d});
  } else {
    for (int level = 0; level < walks.levels(); ++level) {
      std::vector<std::size_t> members;
      std::vector<skin::SkinOptics> optics;
      for (std::size_t d = 0; d < distinct.size(); ++d)
        if (levelOfDistinct[d] == level) {
          members.push_back(d);
          optics.push_back(distinct[d]->optics());
        }
      if (members.empty()) continue;
      for (const auto& bundle : skin::groupIntoBundles(optics, distinct[members[0]]->options())) {
        groups.emplace_back();
        for (std::size_t j : bundle) groups.back().push_back(members[j]);
      }
    }
  }
  std::vector<std::shared_ptr<const skin::ExitTable>> fetched(distinct.size());
  tbb::parallel_for(std::size_t{0}, groups.size(), [&](std::size_t g) {
    std::vector<const skin::SkinWalk*> bundle;
    for (std::size_t d : groups[g]) bundle.push_back(distinct[d]);
    // A group holds walks of one level (a level's bundle, or one walk).
    const skin::ExitTableSettings& levelSettings =
        byLevel[static_cast<std::size_t>(levelOfDistinct[groups[g].front()])];
    const auto tables = spectralBuild ? cache.getBundle(bundle, levelSettings)
                                      : std::vector{cache.get(*bundle[0], levelSettings)};
    for (std::size_t j = 0; j < groups[g].size(); ++j) fetched[groups[g][j]] = tables[j];
  });
  for (std::size_t d : distinctOfSlot) tables_.push_back(fetched[d]);
}

std::string SkinTableCache::describeRaysPerBin(const SkinWalkCache& walks) const {
  std::ostringstream text;
  for (std::size_t level = 0; level < raysPerBinByLevel_.size(); ++level)
    text << (level == 0 ? "" : ", ") << "x" << walks.levelMultiplier(static_cast<int>(level)) << " "
         << raysPerBinByLevel_[level];
  return text.str();
}

}  // namespace hylios
