// Per-layer optical state of a specimen at one wavelength (paper Sec. 4.1–4.2).
//
// The layers' absorption comes from skin/layer_composition.h, the Rayleigh term from
// skin/rayleigh_coefficient.h, melanosome geometry from skin/spheroid.h, θo from
// skin/melanosome_scattering_angle.h and the dispersion of the indices from
// skin/layer_refractive_index.h.
#pragma once
#include <array>
#include <functional>

#include "skin/absorber.h"
#include "skin/layer.h"
#include "skin/rayleigh_coefficient.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios::skin {

/// Geometry of the melanin particles in a layer (Sec. 4.2.2).
struct MelanosomeOptics {
  double semiMinorAxisCm = 0;  ///< a of Eq. 7 (after the per-layer degradation scale)
  double semiMajorAxisCm = 0;  ///< c of Eq. 7
  bool inComplexes = false;    ///< true: complexes (spheres) hold the melanosomes
  double complexRadiusCm = 0;  ///< r_s; 0 when dispersed
  /// m: the most melanosomes a ray meets in a complex, the whole part of complex diameter /
  /// minor axis (Sec. 4.2.2: "at most m"; docs/interpretations.md); 0 when dispersed.
  unsigned melanosomesPerComplex = 0;
  double mu_perCm = 0;  ///< geometric attenuation coefficient, Eq. 6 (0 if no melanosomes)
};

struct LayerOptics {
  double thicknessCm = 0;
  double refractiveIndex = 0;
  std::array<double, kAbsorberCount> muA_perCm{};  ///< per absorber (colloidal melanin here)
  double muATotal_perCm = 0;                       ///< Σ muA_perCm (Eq. 3)
  double muRayleigh_perCm = 0;                     ///< Eq. 4–5; papillary dermis only
  MelanosomeOptics melanosome;
};

struct SkinOptics {
  double wavelengthNm = 0;
  std::array<LayerOptics, kLayerCount> layers;
  double melanosomeInteriorMuA_perCm = 0;  ///< melanin absorption inside a melanosome
  double melaninRefractiveIndex = 0;  ///< n inside melanosomes (Table 2: 1.7, dispersed like water)
  double meanScatteringAngleRad = 0;  ///< θo of Algorithm 2 at this wavelength
  double surfaceAspectRatio = 0;      ///< s of Sec. 4.3

  const LayerOptics& operator[](Layer l) const { return layers[index(l)]; }
};

/// Choices that the paper leaves open and that a caller may change.
struct SkinOpticsOptions {
  RayleighParameters rayleigh;  ///< Eq. 4–5; paper values and the paper's (η²−1)/(η²+1) form
};

/// The spectral data computeSkinOptics reads. spectralSourceOf(database) gives the real data;
/// tests may supply synthetic spectra. specificAbsorption is in cm⁻¹ per unit of
/// absorberConcentrationUnit(absorber) (skin/layer_composition.h).
struct SpectralSource {
  std::function<double(Absorber, double wavelengthNm)> specificAbsorption;
  std::function<double(double wavelengthNm)> waterRefractiveIndex;
};
/// Wraps `spectra` (kept by reference). Throws std::logic_error if the database's concentration
/// unit of an absorber differs from the one layer_composition.h uses.
SpectralSource spectralSourceOf(const SpectralDatabase& spectra);

/// Computes every layer's coefficients for `specimen` at `wavelengthNm`.
/// Throws SpectralDataError for a wavelength outside the data's coverage, or for a spectrum
/// value that is negative or not finite.
SkinOptics computeSkinOptics(const Specimen& specimen, const SpectralDatabase& spectra,
                             double wavelengthNm, const SkinOpticsOptions& options = {});
SkinOptics computeSkinOptics(const Specimen& specimen, const SpectralSource& spectra,
                             double wavelengthNm, const SkinOpticsOptions& options = {});

/// Per-layer scale of the melanosome axes (Sec. 5: 25 % granulosum, 50 % spinosum, 100 % basale;
/// 0 outside the pigmented epidermis).
double melanosomeAxisScale(Layer layer);
/// The melanosome geometry and Eq. 6 coefficient of `layer` (all zero outside the pigmented
/// epidermis). Independent of the wavelength.
MelanosomeOptics layerMelanosomeOptics(const Specimen& specimen, Layer layer);

}  // namespace hylios::skin
