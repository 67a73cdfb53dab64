// The specimen writer: every specimen of Tables 1–2 written and read back is the same specimen,
// and a changed quantity survives the round trip.
#include <gtest/gtest.h>

#include <cmath>

#include "skin/specimen_writer.h"
#include "tests/support/test_spectra.h"

namespace hylios::skin {
namespace {

void expectNear(double a, double b, const std::string& what) {
  EXPECT_NEAR(a, b, 1e-12 * std::fmax(1.0, std::fabs(b))) << what;
}
void expectNear(const std::array<double, kLayerCount>& a, const std::array<double, kLayerCount>& b,
                const std::string& what) {
  for (Layer l : kAllLayers)
    expectNear(a[index(l)], b[index(l)], what + " " + std::string(layerName(l)));
}

void expectSameSpecimen(const Specimen& a, const Specimen& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.arrangement, b.arrangement);
  expectNear(a.surfaceFoldAspectRatio, b.surfaceFoldAspectRatio, "s");
  expectNear(a.thicknessCm, b.thicknessCm, "thickness");
  expectNear(a.melanosomeFraction, b.melanosomeFraction, "melanosomes");
  expectNear(a.colloidalMelaninFraction, b.colloidalMelaninFraction, "colloidal");
  expectNear(a.bloodFraction, b.bloodFraction, "blood");
  expectNear(a.melanosomeEumelanin_mgPerMl, b.melanosomeEumelanin_mgPerMl, "eumelanin");
  expectNear(a.melanosomePheomelanin_mgPerMl, b.melanosomePheomelanin_mgPerMl, "pheomelanin");
  expectNear(a.melanosomeMajorAxisUm, b.melanosomeMajorAxisUm, "major");
  expectNear(a.melanosomeMinorAxisUm, b.melanosomeMinorAxisUm, "minor");
  expectNear(a.oxygenatedBloodFraction, b.oxygenatedBloodFraction, "oxygenation");
  expectNear(a.waterReduction, b.waterReduction, "water reduction");
  const FixedParameters &f = a.fixed, &g = b.fixed;
  expectNear(f.refractiveIndexAt1300nm, g.refractiveIndexAt1300nm, "n");
  expectNear(f.waterFraction, g.waterFraction, "water");
  expectNear(f.lipidFraction, g.lipidFraction, "lipid");
  expectNear(f.melaninRefractiveIndex, g.melaninRefractiveIndex, "melanin n");
  expectNear(f.bloodHemoglobin_mgPerMl, g.bloodHemoglobin_mgPerMl, "Hb");
  expectNear(f.bloodMethemoglobin_mgPerMl, g.bloodMethemoglobin_mgPerMl, "MetHb");
  expectNear(f.bloodCarboxyhemoglobin_mgPerMl, g.bloodCarboxyhemoglobin_mgPerMl, "HbCO");
  expectNear(f.bloodSulfhemoglobin_mgPerMl, g.bloodSulfhemoglobin_mgPerMl, "SHb");
  expectNear(f.bloodBilirubin_mgPerMl, g.bloodBilirubin_mgPerMl, "bilirubin");
  expectNear(f.bloodBetaCarotene_mgPerMl, g.bloodBetaCarotene_mgPerMl, "blood carotene");
  expectNear(f.stratumCorneumBetaCarotene_mgPerMl, g.stratumCorneumBetaCarotene_mgPerMl,
             "SC carotene");
  expectNear(f.epidermisBetaCarotene_mgPerMl, g.epidermisBetaCarotene_mgPerMl,
             "epidermis carotene");
  expectNear(f.stratumCorneumKeratinFraction, g.stratumCorneumKeratinFraction, "keratin");
  expectNear(f.stratumCorneumUrocanicAcid_molPerL, g.stratumCorneumUrocanicAcid_molPerL, "UCA");
  expectNear(f.dna_mgPerMl, g.dna_mgPerMl, "DNA");
}

TEST(SpecimenWriter, TablesOneAndTwoSpecimensRoundTrip) {
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    SCOPED_TRACE(name);
    const Specimen s = loadSpecimen(name, test::specimenDir());
    const std::string text = formatSpecimenToml(s, "written by a test\nsecond line");
    EXPECT_EQ(text.rfind("# written by a test\n# second line\n", 0), 0u);
    expectSameSpecimen(parseSpecimen(text, "written.toml"), s);
  }
}

TEST(SpecimenWriter, ChangedQuantitiesRoundTrip) {
  Specimen s = loadSpecimen("S2", test::specimenDir());
  applyOverride(s, {"stratum_basale.melanosome_percent", 2.345678901, "test"});
  applyOverride(s, {"blood_percent", 0.123456789, "test"});
  applyOverride(s, {"water_reduction_percent", 17.5, "test"});
  applyOverride(s, {"stratum_corneum.thickness_cm", 0.00123456789, "test"});
  s.name = "S2 \"fitted\"";
  expectSameSpecimen(parseSpecimen(formatSpecimenToml(s), "written.toml"), s);
}

}  // namespace
}  // namespace hylios::skin
