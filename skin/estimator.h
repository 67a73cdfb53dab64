// Which estimator a command or render uses for the skin (issue 11): today's analog walk, one
// wavelength and one outcome per path (the reference), or the spectral walk (skin/spectral_walk.h:
// one path for a bundle of wavelengths, absorption as weight), the default.
#pragma once
#include <optional>
#include <string_view>

namespace hylios::skin {

enum class Estimator { PerWavelength, Spectral };

/// "per-wavelength" or "spectral"; nothing for any other text.
inline std::optional<Estimator> parseEstimator(std::string_view text) {
  if (text == "per-wavelength") return Estimator::PerWavelength;
  if (text == "spectral") return Estimator::Spectral;
  return std::nullopt;
}

inline const char* estimatorName(Estimator estimator) {
  return estimator == Estimator::Spectral ? "spectral" : "per-wavelength";
}

}  // namespace hylios::skin
