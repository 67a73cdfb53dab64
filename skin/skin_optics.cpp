#include "skin/skin_optics.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "skin/layer_composition.h"
#include "skin/layer_refractive_index.h"
#include "skin/melanosome_scattering_angle.h"
#include "skin/spheroid.h"

namespace hylios::skin {
namespace {

constexpr double kCmPerUm = 1e-4;

/// Complex diameter over the (scaled) full major axis (Sec. 4.2.2 [SGPF69]).
double complexDiameterOverMajorAxis(MelanosomeArrangement arrangement) {
  switch (arrangement) {
    case MelanosomeArrangement::LightComplexes:
      return 2.0;
    case MelanosomeArrangement::ModerateComplexes:
      return 1.0;
    case MelanosomeArrangement::Dispersed:
      return 0.0;
  }
  throw std::logic_error("unknown melanosome arrangement");
}

double checkedSpecificAbsorption(const SpectralSource& spectra, Absorber a, double nm) {
  const double zeta = spectra.specificAbsorption(a, nm);
  if (!std::isfinite(zeta) || zeta < 0)
    throw SpectralDataError(
        fmt::format("specific absorption of {} at {} nm is {}", absorberName(a), nm, zeta));
  return zeta;
}

}  // namespace

SpectralSource spectralSourceOf(const SpectralDatabase& spectra) {
  // The data's concentration units are layer_composition.h's (SpectralDatabase::concentrationUnit
  // is absorberConcentrationUnit), so the specific absorptions multiply its concentrations.
  return {[&spectra](Absorber a, double nm) { return spectra.specificAbsorption(a, nm); },
          [&spectra](double nm) { return spectra.waterRefractiveIndex(nm); }};
}

double melanosomeAxisScale(Layer layer) {
  switch (layer) {
    case Layer::StratumGranulosum:
      return 0.25;  // Sec. 5, degradation [NZS*06]
    case Layer::StratumSpinosum:
      return 0.5;
    case Layer::StratumBasale:
      return 1.0;
    default:
      return 0.0;
  }
}

MelanosomeOptics layerMelanosomeOptics(const Specimen& s, Layer layer) {
  MelanosomeOptics m;
  const double scale = melanosomeAxisScale(layer);
  if (scale == 0.0) return m;
  // Table 1 gives full axis lengths; Eq. 7 wants semi-axes.
  m.semiMinorAxisCm = 0.5 * s.melanosomeMinorAxisUm * scale * kCmPerUm;
  m.semiMajorAxisCm = 0.5 * s.melanosomeMajorAxisUm * scale * kCmPerUm;
  const double v = s.melanosomeFraction[index(layer)];
  const double diameterRatio = complexDiameterOverMajorAxis(s.arrangement);
  m.inComplexes = diameterRatio > 0;
  if (m.inComplexes) {
    const double diameterCm = diameterRatio * 2.0 * m.semiMajorAxisCm;
    m.complexRadiusCm = 0.5 * diameterCm;
    // "At most m" melanosomes, m the diameter over the minor axis: a count, so its whole part
    // (the 1e-9 keeps a ratio that is whole on paper, e.g. 0.34 / 0.17, from rounding down).
    m.melanosomesPerComplex =
        static_cast<unsigned>(std::floor(diameterCm / (2.0 * m.semiMinorAxisCm) + 1e-9));
    m.mu_perCm = 3.0 / m.complexRadiusCm * v / 4.0;  // Eq. 6 with S/V = 3/r_s
  } else {
    const double surfaceToVolume =
        surfaceToVolumeRatio({m.semiMinorAxisCm, m.semiMajorAxisCm});  // Eq. 7
    m.mu_perCm = surfaceToVolume * v / 4.0;                            // Eq. 6
  }
  return m;
}

SkinOptics computeSkinOptics(const Specimen& specimen, const SpectralDatabase& spectra,
                             double wavelengthNm, const SkinOpticsOptions& options) {
  return computeSkinOptics(specimen, spectralSourceOf(spectra), wavelengthNm, options);
}

SkinOptics computeSkinOptics(const Specimen& specimen, const SpectralSource& spectra,
                             double wavelengthNm, const SkinOpticsOptions& options) {
  if (!std::isfinite(wavelengthNm) || !(wavelengthNm > 0))
    throw SpectralDataError(
        fmt::format("wavelength {} nm is not positive and finite", wavelengthNm));
  std::array<double, kAbsorberCount> zeta{};
  for (Absorber a : kAllAbsorbers)
    zeta[index(a)] = checkedSpecificAbsorption(spectra, a, wavelengthNm);
  const double waterIndex = spectra.waterRefractiveIndex(wavelengthNm);
  const double waterIndexAtReference = spectra.waterRefractiveIndex(kRefractiveIndexReferenceNm);

  SkinOptics optics;
  optics.wavelengthNm = wavelengthNm;
  for (Layer layer : kAllLayers) {
    LayerOptics& out = optics.layers[index(layer)];
    out.thicknessCm = specimen.thicknessCm[index(layer)];
    out.refractiveIndex = dispersedRefractiveIndex(
        specimen.fixed.refractiveIndexAt1300nm[index(layer)], waterIndex, waterIndexAtReference);
    const AbsorberConcentrations concentration = layerAbsorberConcentrations(specimen, layer);
    out.muATotal_perCm = 0;
    for (Absorber a : kAllAbsorbers) {
      out.muA_perCm[index(a)] = zeta[index(a)] * concentration[index(a)];  // Eq. 3 term
      out.muATotal_perCm += out.muA_perCm[index(a)];
    }
    if (layer == Layer::PapillaryDermis)
      out.muRayleigh_perCm = rayleighScatteringCoefficient_perCm(wavelengthNm, options.rayleigh);
    out.melanosome = layerMelanosomeOptics(specimen, layer);
  }
  optics.melanosomeInteriorMuA_perCm =
      zeta[index(Absorber::Eumelanin)] * specimen.melanosomeEumelanin_mgPerMl +
      zeta[index(Absorber::Pheomelanin)] * specimen.melanosomePheomelanin_mgPerMl;
  optics.melaninRefractiveIndex = dispersedRefractiveIndex(specimen.fixed.melaninRefractiveIndex,
                                                           waterIndex, waterIndexAtReference);
  optics.meanScatteringAngleRad = melanosomeMeanScatteringAngleRad(wavelengthNm);
  optics.surfaceAspectRatio = specimen.surfaceFoldAspectRatio;
  return optics;
}

}  // namespace hylios::skin
