#include "app/estimator_option.h"

#include <tbb/parallel_for.h>

#include "app/enum_option.h"
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
  if (estimator == skin::Estimator::Spectral) {
    return skin::simulateSkinSpectral(optics, skin::commandSpectralRun(run));
  }
  std::vector<skin::SkinTally> tallies(optics.size());
  tbb::parallel_for(std::size_t{0}, optics.size(),
                    [&](std::size_t i) { tallies[i] = skin::simulateSkin(optics[i], run); });
  return tallies;
}

}  // namespace hylios
