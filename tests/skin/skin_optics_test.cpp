// Per-layer optical state (Sec. 4.1–4.2): layer composition, sums, melanosome geometry,
// refractive-index dispersion, with synthetic spectra (hand values) and with the real data.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <tuple>

#include "skin/layer_composition.h"
#include "skin/melanosome_scattering_angle.h"
#include "skin/rayleigh_coefficient.h"
#include "skin/skin_optics.h"

namespace hylios::skin {
namespace {

const std::filesystem::path kSourceDir = HYLIOS_SOURCE_DIR;

Specimen specimen(const std::string& name) {
  return loadSpecimen(name, kSourceDir / "scenes" / "specimens");
}

/// ζ(a) = 1 for every absorber; water's index 1.3 + 1e-5·(2000 − λ) (so 1.307 at 1300 nm).
SpectralSource unitSpectra() {
  return {[](Absorber, double) { return 1.0; },
          [](double nm) { return 1.3 + 1e-5 * (2000.0 - nm); }};
}

TEST(LayerComposition, StratumCorneumHoldsTable2Values) {
  const AbsorberConcentrations c =
      layerAbsorberConcentrations(specimen("S1"), Layer::StratumCorneum);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Keratin)], 0.65);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Water)], 0.35);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Lipid)], 0.35);
  EXPECT_DOUBLE_EQ(c[index(Absorber::UrocanicAcid)], 0.01);
  EXPECT_DOUBLE_EQ(c[index(Absorber::BetaCarotene)], 2.1e-4);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Dna)], 0.185);
  for (Absorber a : {Absorber::Eumelanin, Absorber::Pheomelanin, Absorber::Oxyhemoglobin,
                     Absorber::Deoxyhemoglobin, Absorber::Bilirubin})
    EXPECT_EQ(c[index(a)], 0.0) << absorberName(a);
}

TEST(LayerComposition, EpidermisHoldsColloidalMelaninAtMelanosomeConcentrations) {
  // S1: colloidal 0.8 % × (90 mg/mL eumelanin, 4 mg/mL pheomelanin) = 0.72 and 0.032 mg/mL.
  const AbsorberConcentrations c =
      layerAbsorberConcentrations(specimen("S1"), Layer::StratumBasale);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Eumelanin)], 0.72);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Pheomelanin)], 0.032);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Water)], 0.60);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Lipid)], 0.20);
  EXPECT_DOUBLE_EQ(c[index(Absorber::BetaCarotene)], 2.1e-4);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Dna)], 0.185);
  // The living cells' protein as keratin (the specimen file's [epidermis] keratin_percent = 20).
  EXPECT_DOUBLE_EQ(c[index(Absorber::Keratin)], 0.20);
  EXPECT_EQ(c[index(Absorber::UrocanicAcid)], 0.0);
  EXPECT_EQ(c[index(Absorber::Oxyhemoglobin)], 0.0);
}

TEST(LayerComposition, DermisHoldsBloodWeightedByBloodFraction) {
  // S1: 0.2 % blood; Hb 147 mg/mL split 75 % oxygenated: 0.002·147·0.75 = 0.2205 mg/mL HbO2,
  // 0.002·147·0.25 = 0.0735 mg/mL Hb; HbCO and MetHb 0.002·1.5 = 0.003; bilirubin 6e-6;
  // β-carotene 0.002·7e-5 = 1.4e-7 mg/mL.
  const AbsorberConcentrations c =
      layerAbsorberConcentrations(specimen("S1"), Layer::PapillaryDermis);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Oxyhemoglobin)], 0.2205);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Deoxyhemoglobin)], 0.0735);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Carboxyhemoglobin)], 0.003);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Methemoglobin)], 0.003);
  EXPECT_EQ(c[index(Absorber::Sulfhemoglobin)], 0.0);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Bilirubin)], 6e-6);
  EXPECT_DOUBLE_EQ(c[index(Absorber::BetaCarotene)], 1.4e-7);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Water)], 0.75);
  EXPECT_DOUBLE_EQ(c[index(Absorber::Lipid)], 0.151);
  EXPECT_EQ(c[index(Absorber::Dna)], 0.0);
  EXPECT_EQ(c[index(Absorber::Eumelanin)], 0.0);
  const AbsorberConcentrations reticular =
      layerAbsorberConcentrations(specimen("S1"), Layer::ReticularDermis);
  EXPECT_DOUBLE_EQ(reticular[index(Absorber::Lipid)], 0.1733);
}

TEST(LayerComposition, WaterReductionScalesEveryLayersWater) {
  Specimen s = specimen("S1");
  applyOverride(s, {"water_reduction_percent", 20.0, "test"});
  EXPECT_DOUBLE_EQ(layerAbsorberConcentrations(s, Layer::StratumCorneum)[index(Absorber::Water)],
                   0.28);
  EXPECT_DOUBLE_EQ(layerAbsorberConcentrations(s, Layer::StratumSpinosum)[index(Absorber::Water)],
                   0.48);
  EXPECT_DOUBLE_EQ(layerAbsorberConcentrations(s, Layer::ReticularDermis)[index(Absorber::Water)],
                   0.60);
}

TEST(SkinOptics, LayerTotalIsTheSumOfItsParts) {
  // Distinct ζ per absorber (10^(index/3)) so that any dropped or doubled term shows.
  const SpectralSource spectra{
      [](Absorber a, double) { return std::pow(10.0, static_cast<double>(index(a)) / 3.0); },
      [](double) { return 1.33; }};
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    const Specimen s = specimen(name);
    const SkinOptics optics = computeSkinOptics(s, spectra, 550.0);
    for (Layer l : kAllLayers) {
      const AbsorberConcentrations c = layerAbsorberConcentrations(s, l);
      double sum = 0;
      for (Absorber a : kAllAbsorbers) {
        const double expected = std::pow(10.0, static_cast<double>(index(a)) / 3.0) * c[index(a)];
        EXPECT_DOUBLE_EQ(optics[l].muA_perCm[index(a)], expected);
        sum += optics[l].muA_perCm[index(a)];
      }
      EXPECT_NEAR(optics[l].muATotal_perCm, sum, 1e-12 * sum) << name << " " << layerName(l);
      EXPECT_GT(optics[l].muATotal_perCm, 0.0);
    }
  }
}

TEST(SkinOptics, UnitSpectraGiveHandSums) {
  // ζ ≡ 1: stratum corneum μa = 0.65 + 0.35 + 0.35 + 0.01 + 2.1e-4 + 0.185 = 1.54521 cm⁻¹.
  const SkinOptics optics = computeSkinOptics(specimen("S1"), unitSpectra(), 600.0);
  EXPECT_NEAR(optics[Layer::StratumCorneum].muATotal_perCm, 1.54521, 1e-12);
  // Basale: 0.6 + 0.2 + 0.2 (keratin) + 2.1e-4 + 0.185 + 0.72 + 0.032 = 1.93721.
  EXPECT_NEAR(optics[Layer::StratumBasale].muATotal_perCm, 1.93721, 1e-12);
  // Melanosome interior: 1·90 + 1·4 = 94 cm⁻¹.
  EXPECT_DOUBLE_EQ(optics.melanosomeInteriorMuA_perCm, 94.0);
  EXPECT_DOUBLE_EQ(optics.surfaceAspectRatio, 0.1);
  EXPECT_DOUBLE_EQ(optics.wavelengthNm, 600.0);
}

TEST(SkinOptics, ThicknessesComeFromTheSpecimen) {
  const SkinOptics optics = computeSkinOptics(specimen("S3"), unitSpectra(), 600.0);
  EXPECT_DOUBLE_EQ(optics[Layer::StratumCorneum].thicknessCm, 0.0004);
  EXPECT_DOUBLE_EQ(optics[Layer::ReticularDermis].thicknessCm, 0.125);
}

TEST(SkinOptics, RefractiveIndicesDisperseLikeWater) {
  const Specimen s = specimen("S1");
  const SkinOptics at1300 = computeSkinOptics(s, unitSpectra(), 1300.0);
  const std::array<double, kLayerCount> table2 = {1.55, 1.4, 1.4, 1.4, 1.39, 1.41};
  for (Layer l : kAllLayers) EXPECT_DOUBLE_EQ(at1300[l].refractiveIndex, table2[index(l)]);
  EXPECT_DOUBLE_EQ(at1300.melaninRefractiveIndex, 1.7);
  // At 500 nm water's index is 1.315 against 1.307 at 1300 nm: 1.55·1.315/1.307 = 1.559487.
  const SkinOptics at500 = computeSkinOptics(s, unitSpectra(), 500.0);
  EXPECT_NEAR(at500[Layer::StratumCorneum].refractiveIndex, 1.559487, 1e-6);
  EXPECT_NEAR(at500.melaninRefractiveIndex, 1.7 * 1.315 / 1.307, 1e-12);
}

TEST(SkinOptics, RayleighOnlyInThePapillaryDermis) {
  const SkinOptics optics = computeSkinOptics(specimen("S2"), unitSpectra(), 500.0);
  for (Layer l : kAllLayers) {
    if (l == Layer::PapillaryDermis)
      EXPECT_NEAR(optics[l].muRayleigh_perCm, 2531.4, 0.1);  // rayleigh_coefficient_test
    else
      EXPECT_EQ(optics[l].muRayleigh_perCm, 0.0) << layerName(l);
  }
  SkinOpticsOptions textbook;
  textbook.rayleigh.form = RayleighPolarizabilityForm::Textbook;
  EXPECT_NEAR(
      computeSkinOptics(specimen("S2"), unitSpectra(), 500.0, textbook)[Layer::PapillaryDermis]
          .muRayleigh_perCm,
      1248.3, 0.1);
}

TEST(SkinOptics, MeanScatteringAngleFollowsWavelength) {
  EXPECT_DOUBLE_EQ(computeSkinOptics(specimen("S1"), unitSpectra(), 1090.0).meanScatteringAngleRad,
                   melanosomeMeanScatteringAngleRad(1090.0));
  EXPECT_EQ(computeSkinOptics(specimen("S1"), unitSpectra(), 2000.0).meanScatteringAngleRad, 0.0);
}

TEST(MelanosomeOptics, LightComplexesHandValues) {
  // S1 basale: full axes 0.41 × 0.17 µm; complex diameter 2 × 0.41 = 0.82 µm, r_s = 4.1e-5 cm;
  // μ = (3 / 4.1e-5 cm) · 0.01 / 4 = 182.927 cm⁻¹; 0.82 / 0.17 = 4.8235, so "at most m" is 4.
  const Specimen s = specimen("S1");
  const MelanosomeOptics basale = layerMelanosomeOptics(s, Layer::StratumBasale);
  EXPECT_TRUE(basale.inComplexes);
  EXPECT_DOUBLE_EQ(basale.semiMinorAxisCm, 0.085e-4);
  EXPECT_DOUBLE_EQ(basale.semiMajorAxisCm, 0.205e-4);
  EXPECT_DOUBLE_EQ(basale.complexRadiusCm, 4.1e-5);
  EXPECT_NEAR(basale.mu_perCm, 182.927, 1e-3);
  EXPECT_EQ(basale.melanosomesPerComplex, 4u);
  // Spinosum and granulosum: axes at 50 % and 25 %, so μ doubles and quadruples; m unchanged.
  const MelanosomeOptics spinosum = layerMelanosomeOptics(s, Layer::StratumSpinosum);
  const MelanosomeOptics granulosum = layerMelanosomeOptics(s, Layer::StratumGranulosum);
  EXPECT_DOUBLE_EQ(spinosum.semiMajorAxisCm, 0.1025e-4);
  EXPECT_DOUBLE_EQ(granulosum.semiMinorAxisCm, 0.02125e-4);
  EXPECT_NEAR(spinosum.mu_perCm, 365.854, 1e-3);
  EXPECT_NEAR(granulosum.mu_perCm, 731.707, 1e-3);
  EXPECT_EQ(granulosum.melanosomesPerComplex, 4u);
  const MelanosomeOptics corneum = layerMelanosomeOptics(s, Layer::StratumCorneum);
  EXPECT_EQ(corneum.mu_perCm, 0.0);
  EXPECT_EQ(corneum.semiMajorAxisCm, 0.0);
}

TEST(MelanosomeOptics, ModerateComplexesHalveTheDiameter) {
  Specimen s = specimen("S1");
  s.arrangement = MelanosomeArrangement::ModerateComplexes;
  const MelanosomeOptics basale = layerMelanosomeOptics(s, Layer::StratumBasale);
  EXPECT_DOUBLE_EQ(basale.complexRadiusCm, 2.05e-5);
  EXPECT_NEAR(basale.mu_perCm, 365.854, 1e-3);
  EXPECT_EQ(basale.melanosomesPerComplex, 2u);  // 0.41 / 0.17 = 2.41
}

TEST(MelanosomeOptics, ComplexCountIsTheWholePartOfTheRatio) {
  // m counts melanosomes: a ratio that is whole on paper stays whole whatever its rounding in
  // binary (0.51 / 0.17 and 0.3 / 0.1 are not exactly 3), and 2.99 gives 2.
  Specimen s = specimen("S1");
  s.arrangement = MelanosomeArrangement::ModerateComplexes;  // diameter = major axis
  for (const auto& [majorUm, minorUm, count] :
       {std::tuple{0.51, 0.17, 3u}, std::tuple{0.3, 0.1, 3u}, std::tuple{0.299, 0.1, 2u},
        std::tuple{0.17, 0.17, 1u}}) {
    s.melanosomeMajorAxisUm = majorUm;
    s.melanosomeMinorAxisUm = minorUm;
    EXPECT_EQ(layerMelanosomeOptics(s, Layer::StratumBasale).melanosomesPerComplex, count)
        << majorUm << " / " << minorUm;
  }
}

TEST(MelanosomeOptics, DispersedSpheroidsHandValues) {
  // S4 basale: a = 0.14 µm, c = 0.345 µm; b² = 1 − 0.164671 = 0.835329, b = 0.913963,
  // arcsin(b)/b = 1.261479; S/V = 3/(2·1.4e-5 cm)·(0.405797 + 1.261479) = 1.786367e5 cm⁻¹;
  // μ = S/V · 0.10 / 4 = 4465.92 cm⁻¹; granulosum (axes × 0.25) 4× that.
  const Specimen s = specimen("S4");
  const MelanosomeOptics basale = layerMelanosomeOptics(s, Layer::StratumBasale);
  EXPECT_FALSE(basale.inComplexes);
  EXPECT_EQ(basale.complexRadiusCm, 0.0);
  EXPECT_EQ(basale.melanosomesPerComplex, 0u);
  EXPECT_NEAR(basale.mu_perCm, 4465.92, 0.01);
  EXPECT_NEAR(layerMelanosomeOptics(s, Layer::StratumGranulosum).mu_perCm, 4.0 * 4465.92, 0.04);
}

TEST(MelanosomeOptics, NoMelanosomesNoAttenuationButGeometryKept) {
  const MelanosomeOptics g = layerMelanosomeOptics(specimen("S2"), Layer::StratumGranulosum);
  EXPECT_EQ(g.mu_perCm, 0.0);
  EXPECT_GT(g.semiMajorAxisCm, 0.0);
}

TEST(SkinOptics, RejectsBadSpectraAndWavelengths) {
  const SpectralSource negative{
      [](Absorber a, double) { return a == Absorber::Lipid ? -1.0 : 1.0; },
      [](double) { return 1.33; }};
  EXPECT_THROW(computeSkinOptics(specimen("S1"), negative, 500.0), SpectralDataError);
  const SpectralSource nan{[](Absorber, double) { return std::nan(""); },
                           [](double) { return 1.33; }};
  EXPECT_THROW(computeSkinOptics(specimen("S1"), nan, 500.0), SpectralDataError);
  EXPECT_THROW(computeSkinOptics(specimen("S1"), unitSpectra(), -5.0), SpectralDataError);
}

// ---- with the real spectral data (assets/spectra) ---------------------------------------------

/// The database, or nullopt with the reason in `why`.
std::optional<SpectralDatabase> loadDatabase(std::string& why) {
  try {
    return SpectralDatabase::load(kSourceDir / "assets" / "spectra");
  } catch (const std::exception& e) {
    why = e.what();
    return std::nullopt;
  }
}

TEST(SkinOpticsWithData, FiniteNonNegativeOver250To2500nmForAllSpecimens) {
  std::string why;
  const auto database = loadDatabase(why);
  ASSERT_TRUE(database.has_value()) << "assets/spectra does not load: " << why;
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    const Specimen s = specimen(name);
    for (double nm = 250.0; nm <= 2500.0; nm += 5.0) {
      const SkinOptics optics = computeSkinOptics(s, *database, nm);
      for (Layer l : kAllLayers) {
        const LayerOptics& o = optics[l];
        ASSERT_TRUE(std::isfinite(o.muATotal_perCm) && o.muATotal_perCm > 0)
            << name << " " << layerName(l) << " " << nm;
        ASSERT_TRUE(std::isfinite(o.refractiveIndex) && o.refractiveIndex > 1.0)
            << name << " " << layerName(l) << " " << nm;
        double sum = 0;
        for (double mu : o.muA_perCm) sum += mu;
        ASSERT_NEAR(o.muATotal_perCm, sum, 1e-12 * sum);
      }
      ASSERT_TRUE(std::isfinite(optics.melanosomeInteriorMuA_perCm) &&
                  optics.melanosomeInteriorMuA_perCm > 0)
          << name << " " << nm;
    }
  }
}

TEST(SkinOpticsWithData, OxyhemoglobinInS1DermisAt550nm) {
  // Prahl's ε(HbO2, 550 nm) = 43016 cm⁻¹/M, 64500 g/mol: μa = ln 10 · 43016 · 0.2205 g/L / 64500
  // = 0.33861 cm⁻¹; Hb: ln 10 · 53412 · 0.0735 / 64500 = 0.14015 cm⁻¹.
  std::string why;
  const auto database = loadDatabase(why);
  ASSERT_TRUE(database.has_value()) << "assets/spectra does not load: " << why;
  const SkinOptics optics = computeSkinOptics(specimen("S1"), *database, 550.0);
  const LayerOptics& dermis = optics[Layer::PapillaryDermis];
  EXPECT_NEAR(dermis.muA_perCm[index(Absorber::Oxyhemoglobin)], 0.33861, 1e-4);
  EXPECT_NEAR(dermis.muA_perCm[index(Absorber::Deoxyhemoglobin)], 0.14015, 1e-4);
}

TEST(SkinOpticsWithData, WaterDominatesTheDermisAt1450And1940nm) {
  std::string why;
  const auto database = loadDatabase(why);
  ASSERT_TRUE(database.has_value()) << "assets/spectra does not load: " << why;
  for (double nm : {1450.0, 1940.0}) {
    const SkinOptics optics = computeSkinOptics(specimen("S1"), *database, nm);
    const LayerOptics& dermis = optics[Layer::ReticularDermis];
    EXPECT_GT(dermis.muA_perCm[index(Absorber::Water)], 0.5 * dermis.muATotal_perCm) << nm;
  }
}

}  // namespace
}  // namespace hylios::skin
