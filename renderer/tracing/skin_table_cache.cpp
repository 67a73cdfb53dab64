#include "renderer/tracing/skin_table_cache.h"

#include <tbb/parallel_for.h>

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

SkinTableCache::SkinTableCache(const SkinWalkCache& walks, ExitTableCache& cache,
                               const skin::ExitTableSettings& settings, bool spectralBuild)
    : channels_(walks.channels()) {
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
    const auto tables = spectralBuild ? cache.getBundle(bundle, settings)
                                      : std::vector{cache.get(*bundle[0], settings)};
    for (std::size_t j = 0; j < groups[g].size(); ++j) fetched[groups[g][j]] = tables[j];
  });
  for (std::size_t d : distinctOfSlot) tables_.push_back(fetched[d]);
}

}  // namespace hylios
