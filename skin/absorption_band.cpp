#include "skin/absorption_band.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace hylios::skin {

double AbsorptionBand::relativeShape(double wavelengthNm) const {
  if (wavelengthNm >= zeroFromNm) return 0.0;
  const double deltaEv = photonEnergyEv(wavelengthNm) - photonEnergyEv(peakNm);
  const double sigma = deltaEv > 0 ? sigmaBlueEv : sigmaRedEv;
  return std::exp(-0.5 * (deltaEv / sigma) * (deltaEv / sigma));
}

double AbsorptionBand::naturalLogAbsorption(double wavelengthNm) const {
  return std::log(10.0) * referenceValue * multiplier * relativeShape(wavelengthNm) /
         relativeShape(referenceNm);
}

void AbsorptionBand::validate(const char* substance) const {
  const bool positive = peakNm > 0 && sigmaBlueEv > 0 && sigmaRedEv > 0 && referenceNm > 0 &&
                        referenceValue > 0 && multiplier > 0;
  if (!positive || !(zeroFromNm > peakNm) || !(referenceNm < zeroFromNm))
    throw std::invalid_argument(fmt::format(
        "{} band: needs positive peak, widths, reference and multiplier, and zero_from_nm beyond "
        "both the peak and the reference wavelength",
        substance));
  // The declared zero must cut only a negligible tail, or it would be a visible step.
  if (relativeShape(std::nextafter(zeroFromNm, 0.0)) > 1e-5)
    throw std::invalid_argument(fmt::format(
        "{} band: zero_from_nm = {} nm cuts the band where it is still {:.3g} of its peak (> 1e-5)",
        substance, zeroFromNm, relativeShape(std::nextafter(zeroFromNm, 0.0))));
}

}  // namespace hylios::skin
