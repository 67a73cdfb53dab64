// Per-layer optical state of a specimen at one wavelength (paper Sec. 4.1–4.2).
#pragma once
#include <array>

#include "skin/absorber.h"
#include "skin/layer.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios::skin {

/// Geometry of the melanin particles in a layer (Sec. 4.2.2).
struct MelanosomeOptics {
  double semiMinorAxisCm = 0;          ///< a of Eq. 7 (after the per-layer degradation scale)
  double semiMajorAxisCm = 0;          ///< c of Eq. 7
  bool inComplexes = false;            ///< true: complexes (spheres) hold the melanosomes
  double complexRadiusCm = 0;          ///< r_s; 0 when dispersed
  double melanosomesPerComplex = 0;    ///< m = complex diameter / minor axis (may be fractional)
  double mu_perCm = 0;                 ///< geometric attenuation coefficient, Eq. 6 (0 if no melanosomes)
};

struct LayerOptics {
  double thicknessCm = 0;
  double refractiveIndex = 0;
  std::array<double, kAbsorberCount> muA_perCm{};  ///< per absorber (colloidal melanin here)
  double muATotal_perCm = 0;                        ///< Σ muA_perCm (Eq. 3)
  double muRayleigh_perCm = 0;                      ///< Eq. 4–5; papillary dermis only
  MelanosomeOptics melanosome;
};

struct SkinOptics {
  double wavelengthNm = 0;
  std::array<LayerOptics, kLayerCount> layers;
  double melanosomeInteriorMuA_perCm = 0;  ///< melanin absorption inside a melanosome
  double melaninRefractiveIndex = 0;       ///< n inside melanosomes (Table 2: 1.7, dispersed like water)
  double meanScatteringAngleRad = 0;       ///< θo of Algorithm 2 at this wavelength
  double surfaceAspectRatio = 0;           ///< s of Sec. 4.3

  const LayerOptics& operator[](Layer l) const { return layers[index(l)]; }
};

/// Computes every layer's coefficients for `specimen` at `wavelengthNm`.
/// Throws SpectralDataError for a wavelength outside the data's coverage.
SkinOptics computeSkinOptics(const Specimen& specimen, const SpectralDatabase& spectra,
                             double wavelengthNm);

}  // namespace hylios::skin
