// Evaluation of an EmissionDesc (renderer/scene/scene.h) at one wavelength: the relative spectral
// radiance of a light, or the reflectance spectrum of a diffuse material. Every shape is
// dimensionless and multiplied by EmissionDesc::scale:
//   Constant   1 at every wavelength.
//   D65        the CIE D65 illuminant (renderer/image/colour_tables.h) divided by 100, i.e. 1 at
//   560 nm;
//              defined only where the D65 table is.
//   Blackbody  Planck's law at temperatureK divided by its value at the Wien peak
//              λmax = b/T (the peak over all wavelengths, not only 250–2500 nm), so ≤ 1 everywhere.
//   Led        a Gaussian of peak 1 at centreNm with full width at half maximum fwhmNm.
//   Tabulated  linear interpolation between the table's rows; a wavelength outside the table is
//              an error, never an extrapolation.
// Errors (a wavelength a spectrum does not cover) throw SceneError at EmissionDesc::where.
#pragma once
#include "renderer/scene/scene.h"

namespace hylios {

/// Wien's displacement law: the wavelength (nm) at which Planck's spectral radiance per unit
/// wavelength peaks, b/T with b = 2.897771955e6 nm·K (CODATA 2018).
double blackbodyPeakNm(double temperatureK);
/// Planck's law B_λ(T) / B_λmax(T): 1 at the Wien peak, in (0, 1] elsewhere.
double normalisedBlackbody(double temperatureK, double wavelengthNm);
/// exp(−4 ln 2 · (λ − centre)² / fwhm²): 1 at the centre, 1/2 at centre ± fwhm/2.
double ledGaussian(double centreNm, double fwhmNm, double wavelengthNm);

/// The spectrum `emission` at `wavelengthNm` (scale included).
double evaluateEmission(const EmissionDesc& emission, double wavelengthNm);

}  // namespace hylios
