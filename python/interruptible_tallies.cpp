#include "python/interruptible_tallies.h"

#include <tbb/parallel_for.h>

#include <utility>

#include "skin/spectral_bundle.h"
#include "skin/spectral_simulation.h"

namespace hylios::python {

std::vector<skin::SkinTally> simulateTallies(skin::Estimator estimator,
                                             const std::vector<skin::SkinOptics>& optics,
                                             const skin::WalkRunOptions& run, const StopFlag& stop,
                                             ProgressBar* bar) {
  std::vector<skin::SkinTally> tallies(optics.size(), skin::SkinTally(run.tally));
  if (estimator == skin::Estimator::Spectral) {
    const skin::SpectralRunOptions spectral = skin::commandSpectralRun(run);
    const auto bundles = skin::groupIntoBundles(optics, spectral.walk, spectral.bundles);
    tbb::parallel_for(std::size_t{0}, bundles.size(), [&](std::size_t b) {
      if (stop()) return;
      std::vector<skin::SkinOptics> members;
      for (std::size_t i : bundles[b]) members.push_back(optics[i]);
      std::vector<skin::SkinTally> result = skin::simulateSkinSpectral(members, spectral);
      for (std::size_t k = 0; k < bundles[b].size(); ++k)
        tallies[bundles[b][k]] = std::move(result[k]);
      if (bar) bar->advance(bundles[b].size());
    });
  } else {
    tbb::parallel_for(std::size_t{0}, optics.size(), [&](std::size_t i) {
      if (stop()) return;
      tallies[i] = skin::simulateSkin(optics[i], run);
      if (bar) bar->advance();
    });
  }
  return tallies;
}

}  // namespace hylios::python
