// Refractive indices away from 1300 nm. Table 2 gives the layers' indices (and melanin's 1.7)
// at 1300 nm only; the paper shows water's dispersion (Fig. 6). hylios disperses every index
// like water (docs/interpretations.md):
//
//   n(λ) = n(1300 nm) · n_water(λ) / n_water(1300 nm)
#pragma once

namespace hylios::skin {

inline constexpr double kRefractiveIndexReferenceNm = 1300.0;

/// n(λ) from the index at 1300 nm and water's index at λ and at 1300 nm. Throws
/// std::invalid_argument for a non-finite or non-positive input.
double dispersedRefractiveIndex(double indexAtReference, double waterIndexAtWavelength,
                                double waterIndexAtReference);

}  // namespace hylios::skin
