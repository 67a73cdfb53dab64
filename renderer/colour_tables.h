// Colour data from assets/colour/ (with provenance in assets/colour/SOURCES.md): CIE 1931 2°
// colour-matching functions, the CIE D65 illuminant, and a perceptual colour map for
// pseudo-colour previews. Loaded once; lookups interpolate linearly and return 0 outside the
// tables' ranges for the CMFs (they vanish there by definition) — D65 outside its table throws.
#pragma once
#include <array>

namespace hylios {

/// x̄, ȳ, z̄ at a wavelength in nm (zero outside 360–830 nm).
std::array<double, 3> cie1931(double wavelengthNm);
/// Relative spectral power of D65 (100 at 560 nm). Throws std::out_of_range outside its table.
double d65(double wavelengthNm);
/// Linear sRGB (0..1, unclamped) → display sRGB (0..1) with the sRGB transfer function, clamped.
std::array<double, 3> xyzToLinearSrgb(const std::array<double, 3>& xyz);
/// The perceptual colour map at t in [0, 1] (clamped), as display sRGB in [0, 1].
std::array<double, 3> colourMap(double t);

}  // namespace hylios
