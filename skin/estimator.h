// Which estimator a command or render uses for the skin (issue 11): today's analog walk, one
// wavelength and one outcome per path (the reference), or the spectral walk (skin/spectral_walk.h:
// one path for a bundle of wavelengths, absorption as weight), the default. Named "spectral" /
// "per-wavelength" in scene files (`estimator`), on the command line (`--estimator`) and in Python.
#pragma once
#include <optional>
#include <string_view>

#include "skin/core/enum_names.h"

namespace hylios::skin {

enum class Estimator { PerWavelength, Spectral };

inline constexpr EnumNames<Estimator, 2> kEstimatorNames{
    {{Estimator::Spectral, "spectral"}, {Estimator::PerWavelength, "per-wavelength"}}};

/// "per-wavelength" or "spectral"; nothing for any other text.
inline std::optional<Estimator> parseEstimator(std::string_view text) {
  return findEnum(text, kEstimatorNames);
}

inline const char* estimatorName(Estimator estimator) {
  return enumName(estimator, kEstimatorNames).data();  // the table's literals end in '\0'
}

}  // namespace hylios::skin
