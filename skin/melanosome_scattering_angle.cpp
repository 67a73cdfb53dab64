#include "skin/melanosome_scattering_angle.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"

namespace hylios::skin {

double melanosomeMeanScatteringAngleRad(double wavelengthNm) {
  if (!std::isfinite(wavelengthNm) || !(wavelengthNm > 0))
    throw std::invalid_argument("melanosome scattering angle: wavelength " +
                                std::to_string(wavelengthNm) + " nm is not positive and finite");
  const double fullAngleRad = kMelanosomeMeanScatteringAngleDeg * kPi / 180.0;
  if (wavelengthNm <= kMelanosomeAngleFalloffStartNm) return fullAngleRad;
  if (wavelengthNm >= kMelanosomeAngleFalloffEndNm) return 0.0;
  const double remaining = (kMelanosomeAngleFalloffEndNm - wavelengthNm) /
                           (kMelanosomeAngleFalloffEndNm - kMelanosomeAngleFalloffStartNm);
  return fullAngleRad * remaining;
}

}  // namespace hylios::skin
