#include "app/spectral_table_spectrum.h"

#include <tbb/parallel_for.h>

#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/skin_table_cache.h"
#include "skin/skin_simulation.h"
#include "skin/spectral_bundle.h"

namespace hylios {

skin::SkinTally sampleTableTally(const skin::ExitTable& table, double incidenceDeg,
                                 std::uint64_t rays, std::uint64_t seed) {
  const skin::Vec3 incident = skin::incidentDirection(incidenceDeg);
  const std::uint64_t stream = skin::wavelengthStream(table.walk().optics().wavelengthNm);
  skin::SkinTally tally;
  for (std::uint64_t i = 0; i < rays; ++i) {
    skin::Rng rng(seed, stream, i);
    tally.record(table.sample(incident, rng));
  }
  return tally;
}

std::vector<skin::SkinTally> spectralTableTallies(const std::vector<skin::SkinOptics>& optics,
                                                  double incidenceDeg, std::uint64_t rays,
                                                  std::uint64_t seed) {
  std::vector<skin::SkinWalk> walks;  // the full model
  for (const skin::SkinOptics& o : optics) walks.emplace_back(o);
  std::vector<std::shared_ptr<const skin::ExitTable>> tables(optics.size());
  const auto bundles = skin::groupIntoBundles(optics);
  tbb::parallel_for(std::size_t{0}, bundles.size(), [&](std::size_t b) {
    std::vector<const skin::SkinWalk*> members;
    for (std::size_t i : bundles[b]) members.push_back(&walks[i]);
    const auto built = ExitTableCache::shared().getBundle(members, SkinTableCache::curveSettings());
    for (std::size_t j = 0; j < bundles[b].size(); ++j) tables[bundles[b][j]] = built[j];
  });
  std::vector<skin::SkinTally> tallies(optics.size());
  tbb::parallel_for(std::size_t{0}, optics.size(), [&](std::size_t i) {
    tallies[i] = sampleTableTally(*tables[i], incidenceDeg, rays, seed);
  });
  return tallies;
}

}  // namespace hylios
