// The --estimator option of the commands that walk skin (spectrum, brdf, forward-profile,
// radial-profile), and the run it selects (skin/estimator.h).
#pragma once
#include <CLI/CLI.hpp>

#include <vector>

#include "skin/estimator.h"
#include "skin/skin_simulation.h"

namespace hylios {

/// Adds --estimator spectral|per-wavelength (default: `estimator` as it is, spectral in the
/// commands) writing into `estimator`; other text is refused with parseEnum's message.
void addEstimatorOption(CLI::App& command, skin::Estimator& estimator);

/// One tally per optics: the analog walk per wavelength (per-wavelength), or the spectral walk
/// with internal melanosome paths drawn from its table (spectral; skin/spectral_simulation.h).
std::vector<skin::SkinTally> simulateWithEstimator(skin::Estimator estimator,
                                                   const std::vector<skin::SkinOptics>& optics,
                                                   const skin::WalkRunOptions& run);

}  // namespace hylios
