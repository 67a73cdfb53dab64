// The checks of the Python module's arguments, with the ranges of the commands' options
// (app/common_options.h, app/option_checks.h) and messages that name the keyword argument.
// Each throws std::invalid_argument (Python: ValueError).
#pragma once
#include <cstdint>
#include <string>

#include "skin/estimator.h"
#include "skin/skin_mode.h"

namespace hylios::python {

/// The commands' --rays bound.
inline constexpr std::uint64_t kMaxRays = std::uint64_t{1} << 40;

/// angle_deg in [0, 90).
void requireAngle(double angleDeg);
/// rays in [1, 2^40].
void requireRays(std::uint64_t rays);
/// threads 0 (all cores) or positive.
void requireThreads(int threads);
/// epsilon in [0, 1].
void requireEpsilon(double epsilon);
/// "spectral" or "per-wavelength" (parseEnum's message, as --estimator).
skin::Estimator estimatorNamed(const std::string& estimator);
/// "walk" or "table" (parseEnum's message, as --skin-model).
skin::SkinMode skinModeNamed(const std::string& skinModel);

}  // namespace hylios::python
