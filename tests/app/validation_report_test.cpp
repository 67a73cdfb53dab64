// `hylios validate` (app/validation_report.h): the NCSU figures of Fig. 7 and the NIST UV figure of
// Fig. 9 reproduce those of the committed docs/validation.md within their statistical tolerance,
// and the command writes the report with its table and plots.
//
// Tolerance: for two model curves m1, m2 against the same data d, |RMS(m1 − d) − RMS(m2 − d)| ≤
// RMS(m1 − m2) (triangle inequality), whose expectation is ≤ sqrt(noise1² + noise2²) with noise
// the per-curve sqrt(mean σ²). We allow 4× that. The mean error's σ is at most the same noise
// (the spectral walk's wavelengths share paths, so their errors may be fully correlated).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "app/population_comparison.h"
#include "app/validation_report.h"
#include "tests/support/scratch_csv.h"
#include "tests/support/test_spectra.h"

namespace hylios {
namespace {

const std::filesystem::path kNcsu = std::filesystem::path(HYLIOS_SOURCE_DIR) / "tests" / "data" /
                                    "validation" / "ncsu_vrhel1994_skin.csv";

// docs/validation.md (hylios validate --rays 100000 --seed 1): RMS, mean error, MC σ of the RMS.
struct Reference {
  const char* specimen;
  const char* column;
  double rms, meanError, noise;
};
constexpr Reference kReferences[] = {
    {"S1", "obj117", 0.0151, -0.0094, 0.0011},
    {"S2", "obj113", 0.0290, -0.0179, 0.0010},
};

TEST(ValidationReport, NcsuFiguresMatchTheCommittedReport) {
  std::vector<double> wavelengths;
  for (double w = 400; w <= 700; w += 10) wavelengths.push_back(w);
  for (const Reference& ref : kReferences) {
    const CurveComparison c = compareWithMeasured(ref.specimen, kNcsu, ref.column, wavelengths, 45,
                                                  10000, 7, test::spectra());
    std::cout << ref.specimen << " vs " << ref.column << ": RMS " << c.rms << " (docs " << ref.rms
              << "), mean error " << c.meanError << ", noise " << c.noiseRms << ", max "
              << c.maxAbsError << " at " << c.worstWavelengthNm << " nm\n";
    ASSERT_EQ(c.wavelengthNm.size(), 31u);
    const double noise = std::hypot(c.noiseRms, ref.noise);
    EXPECT_NEAR(c.rms, ref.rms, 4 * noise) << ref.specimen;
    EXPECT_NEAR(c.meanError, ref.meanError, 4 * noise) << ref.specimen;
    EXPECT_GE(c.maxAbsError, c.rms);
  }
}

// docs/validation.md, Fig. 9: S3 at 8° against the lightest quarter of the NIST set, the excess of
// the model over the group's highest measured reflectance at 300 nm (the largest of 250–310 nm),
// with the model's σ there at 10^5 rays.
constexpr double kS3ExcessAt300Nm = 0.0246, kS3SigmaAt300Nm = 0.00029;

TEST(ValidationReport, NistUvFigureMatchesTheCommittedReport) {
  const SkinPopulation nist = loadSkinPopulation(kNcsu.parent_path() / "nist_cooksey2017_skin.csv");
  const skin::Specimen s3 = skin::loadSpecimen("S3", test::specimenDir());
  const std::vector<skin::Estimate> model =
      modelReflectanceCurve(s3, {300}, 8, 40000, 7, test::spectra());
  const PopulationComparison c =
      compareWithPopulation("S3", {300}, model, 8, nist, nist.quantileGroup(0.25, true), "light");
  const double excess = c.regions.back().worstExcess;
  std::cout << "S3 at 300 nm: " << model[0].mean << " ± " << model[0].standardError
            << ", excess over the lightest quarter " << excess << " (docs " << kS3ExcessAt300Nm
            << ")\n";
  // 4σ of the difference of two independent estimates, plus the report's rounding (5e-5).
  EXPECT_NEAR(excess, kS3ExcessAt300Nm,
              4 * std::hypot(model[0].standardError, kS3SigmaAt300Nm) + 5e-5);
}

/// Whether `specimen` at 8° lies inside the lightest NIST quarter's measured range (within 2σ of
/// the model, 40 000 rays) at every one of `nm`.
::testing::AssertionResult insideTheLightestQuarter(const skin::Specimen& specimen,
                                                    const std::vector<double>& nm) {
  const SkinPopulation nist = loadSkinPopulation(kNcsu.parent_path() / "nist_cooksey2017_skin.csv");
  const std::vector<skin::Estimate> model =
      modelReflectanceCurve(specimen, nm, 8, 40000, 7, test::spectra());
  const PopulationComparison c = compareWithPopulation(specimen.name, nm, model, 8, nist,
                                                       nist.quantileGroup(0.25, true), "light");
  if (c.regions.front().inside == nm.size()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << specimen.name << ": " << c.regions.front().inside << " of " << nm.size()
         << " inside, worst excess " << c.regions.front().worstExcess << " at "
         << c.regions.front().worstExcessNm << " nm";
}

// docs/validation.md, Fig. 9: with the living epidermis' protein (keratin_percent in [epidermis],
// docs/interpretations.md) S3 lies inside the lightest quarter's measured range at 250–290 nm.
// There the model is 0.052–0.060 against highs of 0.062–0.069 (σ ≤ 0.0002 at 40 000 rays), the
// surface alone 0.051–0.052; without that protein it was 0.066–0.092 and 0 of them were inside.
TEST(ValidationReport, NistUvBelow300NmInsideTheLightestQuarter) {
  EXPECT_TRUE(insideTheLightestQuarter(skin::loadSpecimen("S3", test::specimenDir()),
                                       {250, 260, 270, 280, 290}));
}

const std::vector<double> k250To310Nm{250, 260, 270, 280, 290, 300, 310};

// docs/validation.md, Fig. 9's UV rows (issue 14's goal). S2, lightly pigmented, with Table 1's own
// values: 0.048–0.068 at 250–310 nm, the nearest edge 0.0014 away at 250 nm (σ 0.0003 there at
// 40 000 rays). S3 with the stratum corneum measured at the NIST site (20 µm; Table 1: 4 µm):
// 0.051–0.082, the nearest edge 0.004 away at 250 nm (σ 0.0001). S3 as in Table 1 is inside at 5
// of the 7 (0.095 at 300 nm against a highest measured 0.071).
TEST(ValidationReport, NistUvOfS2AndOfS3WithTheSitesStratumCorneumInsideTheLightestQuarter) {
  EXPECT_TRUE(insideTheLightestQuarter(skin::loadSpecimen("S2", test::specimenDir()), k250To310Nm));
  skin::Specimen s3 = skin::loadSpecimen("S3", test::specimenDir());
  s3.thicknessCm[skin::index(skin::Layer::StratumCorneum)] = kNistSiteStratumCorneumCm;
  EXPECT_TRUE(insideTheLightestQuarter(s3, k250To310Nm));
}

TEST(ValidationReport, CommandWritesTheReportAndItsPlots) {
  test::ScratchFolder scratch("validate");
  test::runCommandLine(registerValidateCommand,
                       "validate --rays 1000 --out " + scratch.path.string());
  std::ifstream in(scratch.path / "validation.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string md = text.str();
  EXPECT_NE(md.find("| S1 vs NCSU obj117, 45° (Fig. 7) |"), std::string::npos);
  EXPECT_NE(md.find("| S2 vs NCSU obj113, 45° (Fig. 7) |"), std::string::npos);
  EXPECT_NE(md.find("| S3 vs NIST lightest quarter, 8° |"), std::string::npos);
  EXPECT_NE(md.find("| S4 vs NIST darkest quarter, 8° |"), std::string::npos);
  EXPECT_NE(md.find("| S2 vs NIST lightest quarter, 8° |"), std::string::npos);
  EXPECT_NE(md.find("| S3, stratum corneum 20 µm vs NIST lightest quarter, 8° |"),
            std::string::npos);
  EXPECT_NE(md.find("| 8 | half width"), std::string::npos);
  EXPECT_NE(md.find("| 11 | subsurface share"), std::string::npos);
  for (const char* png : {"fig7_ncsu.png", "fig9_nist.png", "fig9_nist_uv.png",
                          "fig8_forward_profile.png", "fig10_brdf.png", "fig11_uv_ir.png"}) {
    EXPECT_GT(std::filesystem::file_size(scratch.path / "validation" / png), 1000u) << png;
    EXPECT_NE(md.find(std::string("](validation/") + png + ")"), std::string::npos) << png;
  }
}

}  // namespace
}  // namespace hylios
