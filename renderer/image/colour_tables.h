// Colour data from assets/colour/ (with provenance in assets/colour/SOURCES.md): CIE 1931 2°
// colour-matching functions, the CIE D65 illuminant, and a perceptual colour map for
// pseudo-colour previews. Loaded once; lookups interpolate linearly and return 0 outside the
// tables' ranges for the CMFs (they vanish there by definition) — D65 outside its table throws.
#pragma once
#include <array>

namespace hylios {

/// Wavelength range of the colour-matching function table (nm).
inline constexpr double kCie1931MinNm = 360.0;
inline constexpr double kCie1931MaxNm = 830.0;
/// Wavelength range of the D65 table (nm).
inline constexpr double kD65MinNm = 300.0;
inline constexpr double kD65MaxNm = 830.0;

/// x̄, ȳ, z̄ at a wavelength in nm (zero outside 360–830 nm).
std::array<double, 3> cie1931(double wavelengthNm);
/// Relative spectral power of D65 (100 at 560 nm). Throws std::out_of_range outside its table.
double d65(double wavelengthNm);
/// CIE XYZ → linear sRGB (IEC 61966-2-1 primaries, D65 white; unclamped, may be negative).
std::array<double, 3> xyzToLinearSrgb(const std::array<double, 3>& xyz);
/// The sRGB transfer function (IEC 61966-2-1) of one linear value, clamped to [0, 1] first:
/// out-of-gamut and over-exposed values cannot be shown on a display.
double srgbEncode(double linear);
/// The perceptual colour map at t in [0, 1] (clamped), as display sRGB in [0, 1].
std::array<double, 3> colourMap(double t);

}  // namespace hylios
