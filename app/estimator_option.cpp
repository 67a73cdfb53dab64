#include "app/estimator_option.h"

#include <tbb/parallel_for.h>

#include "skin/spectral_simulation.h"

namespace hylios {

void addEstimatorOption(CLI::App& command, std::string& estimator) {
  command
      .add_option(
          "--estimator", estimator,
          "spectral (default: one path carries a bundle of wavelengths, absorption as weight) or "
          "per-wavelength (one analog walk per wavelength and ray: the reference)")
      ->check(CLI::IsMember({"spectral", "per-wavelength"}));
}

std::vector<skin::SkinTally> simulateWithEstimator(const std::string& estimator,
                                                   const std::vector<skin::SkinOptics>& optics,
                                                   const skin::WalkRunOptions& run) {
  if (estimator == "spectral") {
    return skin::simulateSkinSpectral(optics, skin::commandSpectralRun(run));
  }
  std::vector<skin::SkinTally> tallies(optics.size());
  tbb::parallel_for(std::size_t{0}, optics.size(),
                    [&](std::size_t i) { tallies[i] = skin::simulateSkin(optics[i], run); });
  return tallies;
}

}  // namespace hylios
