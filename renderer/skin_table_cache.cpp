#include "renderer/skin_table_cache.h"

#include <tbb/parallel_for.h>

namespace hylios {

skin::ExitTableSettings SkinTableCache::renderSettings() {
  skin::ExitTableSettings settings;
  settings.cosineBins = 12;
  settings.raysPerBin = 40000;
  return settings;
}

SkinTableCache::SkinTableCache(const SkinWalkCache& walks, ExitTableCache& cache, const skin::ExitTableSettings& settings)
    : channels_(walks.channels()) {
  tables_.resize(static_cast<std::size_t>(walks.levels()) * channels_);
  tbb::parallel_for(std::size_t{0}, tables_.size(), [&](std::size_t i) {
    tables_[i] = cache.get(walks.walk(i % channels_, static_cast<int>(i / channels_)), settings);
  });
}

}  // namespace hylios
