#include "renderer/tracing/skin_table_cache.h"

#include <tbb/parallel_for.h>

#include <unordered_map>

namespace hylios {

skin::ExitTableSettings SkinTableCache::renderSettings() {
  skin::ExitTableSettings settings;
  settings.cosineBins = 12;
  settings.raysPerBin = 40000;
  return settings;
}

SkinTableCache::SkinTableCache(const SkinWalkCache& walks, ExitTableCache& cache,
                               const skin::ExitTableSettings& settings)
    : channels_(walks.channels()) {
  // Channels that share a wavelength share a walk (SkinWalkCache prepares each wavelength once):
  // fetch one table per distinct walk, so no table is built twice.
  std::vector<const skin::SkinWalk*> distinct;
  std::unordered_map<const skin::SkinWalk*, std::size_t> indexOfWalk;
  std::vector<std::size_t> distinctOfSlot;
  for (std::size_t i = 0; i < static_cast<std::size_t>(walks.levels()) * channels_; ++i) {
    const skin::SkinWalk* walk = &walks.walk(i % channels_, static_cast<int>(i / channels_));
    const auto [at, added] = indexOfWalk.emplace(walk, distinct.size());
    if (added) distinct.push_back(walk);
    distinctOfSlot.push_back(at->second);
  }
  std::vector<std::shared_ptr<const skin::ExitTable>> fetched(distinct.size());
  tbb::parallel_for(std::size_t{0}, distinct.size(),
                    [&](std::size_t d) { fetched[d] = cache.get(*distinct[d], settings); });
  for (std::size_t d : distinctOfSlot) tables_.push_back(fetched[d]);
}

}  // namespace hylios
