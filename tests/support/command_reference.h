// The library run a walk command's CSV must agree with (tests/app): a named specimen's optics
// from the project's data and the commands' default estimator (spectral) on them, with the same
// seed and random streams as the command.
#pragma once
#include <string>
#include <vector>

#include "app/estimator_option.h"
#include "renderer/scene/data_paths.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios::test {

/// The optics of specimen `name` (S1..S4 or a file) at `wavelengthNm`.
inline skin::SkinOptics specimenOptics(const std::string& name, double wavelengthNm) {
  return skin::computeSkinOptics(skin::loadSpecimen(name, specimenDir()),
                                 skin::SpectralDatabase::load(spectraDir()), wavelengthNm);
}

/// The commands' default run (the spectral estimator) at one wavelength.
inline skin::SkinTally spectralTally(const skin::SkinOptics& optics,
                                     const skin::WalkRunOptions& run) {
  return simulateWithEstimator(skin::Estimator::Spectral, {optics}, run).front();
}

}  // namespace hylios::test
