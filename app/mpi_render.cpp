#include "app/mpi_render.h"

#include <string>
#include <vector>

#include "app/mpi_session.h"
#include "renderer/image/film_output.h"
#include "skin/core/state_bytes.h"

namespace hylios {
namespace {

/// The film's state summed over the ranks (every rank's sums of its own tiles) into `whole` on
/// rank 0 (may be `film` itself; ignored on the other ranks).
void sumFilmOnRoot(const Film& film, Film* whole) {
  std::vector<double> sums = film.sums(), secondHalfSums = film.secondHalfSums();
  std::vector<std::uint32_t> counts = film.counts(), secondHalfCounts = film.secondHalfCounts();
  sumToRoot(sums);
  sumToRoot(secondHalfSums);
  sumToRoot(counts);
  sumToRoot(secondHalfCounts);
  if (MpiSession::isRoot())
    whole->restoreState(std::move(sums), std::move(counts), std::move(secondHalfSums),
                        std::move(secondHalfCounts), film.samplesPerPixelDone());
}

std::string noiseBytes(const std::vector<GroupNoise>& noise) {
  std::string bytes;
  skin::putBytes(bytes, static_cast<std::uint64_t>(noise.size()));
  for (const GroupNoise& g : noise) {
    skin::putBytes(bytes, static_cast<std::uint64_t>(g.group.size()));
    bytes += g.group;
    skin::putBytes(bytes, g.medianRelative);
    skin::putBytes(bytes, static_cast<std::uint64_t>(g.pixels));
  }
  return bytes;
}

std::vector<GroupNoise> noiseFromBytes(const std::string& bytes) {
  std::size_t offset = 0;
  std::vector<GroupNoise> noise(skin::takeBytes<std::uint64_t>(bytes, offset, "noiseFromBytes"));
  for (GroupNoise& g : noise) {
    const auto length = skin::takeBytes<std::uint64_t>(bytes, offset, "noiseFromBytes");
    g.group = bytes.substr(offset, length);
    offset += length;
    g.medianRelative = skin::takeBytes<double>(bytes, offset, "noiseFromBytes");
    g.pixels = skin::takeBytes<std::uint64_t>(bytes, offset, "noiseFromBytes");
  }
  return noise;
}

}  // namespace

RenderDivision renderDivisionAcrossRanks() {
  RenderDivision division;
  if (!MpiSession::distributed()) return division;
  division.part = static_cast<std::size_t>(MpiSession::rank());
  division.parts = static_cast<std::size_t>(MpiSession::size());
  division.wholeFilmNoise = [](const Film& film) {
    std::string bytes;
    if (MpiSession::isRoot()) {
      Film whole = film;
      sumFilmOnRoot(film, &whole);
      bytes = noiseBytes(filmNoise(whole));
    } else {
      sumFilmOnRoot(film, nullptr);
    }
    broadcastFromRoot(bytes);
    return noiseFromBytes(bytes);
  };
  division.gather = [](Film& film, RenderStats& stats) {
    sumFilmOnRoot(film, &film);
    std::vector<std::uint64_t> counters = {stats.paths,
                                           stats.skinWalks,
                                           stats.skinAbsorbed,
                                           stats.skinSurfaceExits,
                                           stats.skinSubsurfaceExits,
                                           stats.skinEventLimited,
                                           stats.exitFallbacks,
                                           stats.belowSurface};
    sumToRoot(counters);
    std::uint64_t* fields[] = {&stats.paths,
                               &stats.skinWalks,
                               &stats.skinAbsorbed,
                               &stats.skinSurfaceExits,
                               &stats.skinSubsurfaceExits,
                               &stats.skinEventLimited,
                               &stats.exitFallbacks,
                               &stats.belowSurface};
    for (std::size_t i = 0; i < counters.size(); ++i) *fields[i] = counters[i];
  };
  return division;
}

}  // namespace hylios
