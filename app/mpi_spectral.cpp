#include "app/mpi_spectral.h"

#include <stdexcept>
#include <string>

#include "app/mpi_session.h"

namespace hylios {

std::vector<skin::SkinTally> simulateSkinSpectralOnRanks(
    const std::vector<skin::SkinOptics>& optics, const skin::SpectralRunOptions& options) {
  if (!MpiSession::distributed()) return skin::simulateSkinSpectral(optics, options);
  const auto parts = static_cast<std::size_t>(MpiSession::size());
  const auto part = static_cast<std::size_t>(MpiSession::rank());
  skin::SpectralChunks chunks = skin::simulateSkinSpectralChunks(optics, options, part, parts);
  // Each rank sends its chunks' tallies in chunk order (about 330 bytes per wavelength and chunk
  // of 1024 paths without histograms); rank 0 puts them back in their slots.
  std::string mine;
  for (std::size_t c = part; c < chunks.tallies.size(); c += parts)
    for (const skin::SkinTally& t : chunks.tallies[c]) t.appendBytes(mine);
  const std::vector<std::string> all = gatherToRoot(mine);
  if (!MpiSession::isRoot())
    return std::vector<skin::SkinTally>(optics.size(), skin::SkinTally(options.tally));
  for (std::size_t r = 1; r < parts; ++r) {
    std::size_t offset = 0;
    for (std::size_t c = r; c < chunks.tallies.size(); c += parts) {
      chunks.tallies[c].clear();
      for (std::size_t k = 0; k < chunks.members[c].size(); ++k)
        chunks.tallies[c].push_back(skin::SkinTally::fromBytes(options.tally, all[r], offset));
    }
    if (offset != all[r].size())
      throw std::runtime_error("rank " + std::to_string(r) + " sent " +
                               std::to_string(all[r].size()) + " bytes of tallies, expected " +
                               std::to_string(offset));
  }
  return skin::mergeSpectralChunks(chunks, optics.size(), options.tally);
}

bool rankOwnsItem(std::size_t i) {
  return i % static_cast<std::size_t>(MpiSession::size()) ==
         static_cast<std::size_t>(MpiSession::rank());
}

void gatherOwnedTallies(std::vector<skin::SkinTally>& tallies, const skin::TallyOptions& options) {
  if (!MpiSession::distributed()) return;
  const auto parts = static_cast<std::size_t>(MpiSession::size());
  std::string mine;
  for (std::size_t i = static_cast<std::size_t>(MpiSession::rank()); i < tallies.size(); i += parts)
    tallies[i].appendBytes(mine);
  const std::vector<std::string> all = gatherToRoot(mine);
  if (!MpiSession::isRoot()) return;
  for (std::size_t r = 1; r < parts; ++r) {
    std::size_t offset = 0;
    for (std::size_t i = r; i < tallies.size(); i += parts)
      tallies[i] = skin::SkinTally::fromBytes(options, all[r], offset);
    if (offset != all[r].size())
      throw std::runtime_error("rank " + std::to_string(r) + " sent " +
                               std::to_string(all[r].size()) + " bytes of tallies, expected " +
                               std::to_string(offset));
  }
}

}  // namespace hylios
