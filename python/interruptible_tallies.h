// The tallies of the commands' --estimator run (app/estimator_option.h) for the Python module,
// made interruptible: a stop request takes effect between bundles (spectral) or wavelengths.
#pragma once
#include <vector>

#include "app/progress_bar.h"
#include "python/interruptible.h"
#include "skin/estimator.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/skin_tally.h"

namespace hylios::python {

/// One tally per optics, as the commands' simulateWithEstimator (app/estimator_option.cpp): the
/// analog walk per wavelength (per-wavelength), or the spectral walk with tabulated melanosome
/// paths (spectral). The spectral walk is run one bundle at a time: a bundle's members regroup into
/// that one bundle and its random stream depends only on its wavelengths, so the tallies are those
/// of one simulateSkinSpectral call over all wavelengths, and a stop request takes effect between
/// bundles. The per-wavelength walk stops between wavelengths.
std::vector<skin::SkinTally> simulateTallies(skin::Estimator estimator,
                                             const std::vector<skin::SkinOptics>& optics,
                                             const skin::WalkRunOptions& run, const StopFlag& stop,
                                             ProgressBar* bar = nullptr);

}  // namespace hylios::python
