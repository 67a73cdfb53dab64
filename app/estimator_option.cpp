#include "app/estimator_option.h"

#include <tbb/parallel_for.h>

#include "app/enum_option.h"
#include "app/mpi_spectral.h"
#include "skin/spectral_simulation.h"

namespace hylios {

void addEstimatorOption(CLI::App& command, skin::Estimator& estimator) {
  addEnumOption(
      command, "--estimator", estimator, skin::kEstimatorNames,
      "spectral (default: one path carries a bundle of wavelengths, absorption as "
      "weight) or per-wavelength (one analog walk per wavelength and ray: the reference)");
}

std::vector<skin::SkinTally> simulateWithEstimator(skin::Estimator estimator,
                                                   const std::vector<skin::SkinOptics>& optics,
                                                   const skin::WalkRunOptions& run) {
  // Under MPI (app/mpi_spectral.h): the spectral chunks, or the wavelengths, divided among the
  // ranks; the tallies of the one-process run on rank 0.
  if (estimator == skin::Estimator::Spectral)
    return simulateSkinSpectralOnRanks(optics, skin::commandSpectralRun(run));
  std::vector<skin::SkinTally> tallies(optics.size(), skin::SkinTally(run.tally));
  tbb::parallel_for(std::size_t{0}, optics.size(), [&](std::size_t i) {
    if (rankOwnsItem(i)) tallies[i] = skin::simulateSkin(optics[i], run);
  });
  gatherOwnedTallies(tallies, run.tally);
  return tallies;
}

}  // namespace hylios
