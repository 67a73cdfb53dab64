// Rayleigh scattering coefficient of the papillary dermis' connective fibres (paper Sec. 4.2.1,
// Eq. 4–5).
//
//   μs = 128 π⁵ r⁶ D / (3 λ⁴) · K²,   D = 0.22 / ((4/3) π r³)   (Eq. 4, 5)
//
// with K = (η² − 1)/(η² + 1) as printed in the paper (default), or the textbook Rayleigh factor
// K = (η² − 1)/(η² + 2) as an option. λ is the vacuum wavelength, as the paper gives no medium
// index for it (docs/interpretations.md).
#pragma once

namespace hylios::skin {

enum class RayleighPolarizabilityForm {
  Paper,     ///< (η² − 1)/(η² + 1), Eq. 4 as printed
  Textbook,  ///< (η² − 1)/(η² + 2), Clausius–Mossotti / Lorentz–Lorenz factor
};

struct RayleighParameters {
  double radiusNm = 100.0;             ///< r, scatterer radius [Jac96]
  double relativeIndex = 1.55 / 1.33;  ///< η, scatterer index over medium index [Jac96]
  double volumeFraction = 0.22;        ///< the 0.22 of Eq. 5 (so D = 0.22 / particle volume)
  RayleighPolarizabilityForm form = RayleighPolarizabilityForm::Paper;
};

/// Number density D of Eq. 5 in cm⁻³.
double rayleighNumberDensity_perCm3(const RayleighParameters& parameters);

/// The factor K of Eq. 4 (before squaring) for the chosen form.
double rayleighPolarizabilityFactor(const RayleighParameters& parameters);

/// μs^R(λ) of Eq. 4 in cm⁻¹ for a wavelength in nm. Throws std::invalid_argument for a
/// non-positive or non-finite wavelength or parameter.
double rayleighScatteringCoefficient_perCm(double wavelengthNm,
                                           const RayleighParameters& parameters = {});

}  // namespace hylios::skin
