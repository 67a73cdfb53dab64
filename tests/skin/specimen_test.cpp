// Specimen files (Tables 1–2) and overrides: values as in the paper, and every error with its
// file:line:col position.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "skin/specimen.h"

namespace hylios::skin {
namespace {

const std::filesystem::path kSpecimenDir =
    std::filesystem::path(HYLIOS_SOURCE_DIR) / "scenes" / "specimens";

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// S1.toml's text with the first occurrence of `from` replaced by `to`.
std::string editedS1(const std::string& from, const std::string& to) {
  std::string text = readFile(kSpecimenDir / "S1.toml");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// 1-based line of the first occurrence of `needle`.
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  int line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

/// "bad.toml:LINE", LINE the line of `text` holding `needle`.
std::string badTomlAt(const std::string& text, const std::string& needle) {
  return "bad.toml:" + std::to_string(lineOf(text, needle));
}

/// The SpecimenError message of parsing `text` as "bad.toml" (empty if it parses).
std::string parseError(const std::string& text) {
  try {
    parseSpecimen(text, "bad.toml");
  } catch (const SpecimenError& e) {
    return e.what();
  }
  return "";
}

TEST(Specimen, S1MatchesTables1And2) {
  const Specimen s = loadSpecimen("S1", kSpecimenDir);
  EXPECT_EQ(s.name, "S1");
  EXPECT_EQ(s.sourceFile, kSpecimenDir / "S1.toml");
  EXPECT_DOUBLE_EQ(s.surfaceFoldAspectRatio, 0.1);
  const std::array<double, kLayerCount> thickness = {0.001, 0.0017, 0.0017, 0.0017, 0.02, 0.1};
  EXPECT_EQ(s.thicknessCm, thickness);
  for (Layer l : {Layer::StratumGranulosum, Layer::StratumSpinosum, Layer::StratumBasale}) {
    EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(l)], 0.01);
    EXPECT_DOUBLE_EQ(s.colloidalMelaninFraction[index(l)], 0.008);
  }
  EXPECT_EQ(s.melanosomeFraction[index(Layer::StratumCorneum)], 0.0);
  EXPECT_DOUBLE_EQ(s.melanosomeEumelanin_mgPerMl, 90.0);
  EXPECT_DOUBLE_EQ(s.melanosomePheomelanin_mgPerMl, 4.0);
  EXPECT_DOUBLE_EQ(s.melanosomeMajorAxisUm, 0.41);
  EXPECT_DOUBLE_EQ(s.melanosomeMinorAxisUm, 0.17);
  EXPECT_EQ(s.arrangement, MelanosomeArrangement::LightComplexes);
  EXPECT_DOUBLE_EQ(s.bloodFraction[index(Layer::PapillaryDermis)], 0.002);
  EXPECT_DOUBLE_EQ(s.bloodFraction[index(Layer::ReticularDermis)], 0.002);
  EXPECT_EQ(s.bloodFraction[index(Layer::StratumBasale)], 0.0);
  EXPECT_DOUBLE_EQ(s.oxygenatedBloodFraction, 0.75);
  EXPECT_EQ(s.waterReduction, 0.0);

  const FixedParameters& f = s.fixed;  // Table 2
  const std::array<double, kLayerCount> n = {1.55, 1.4, 1.4, 1.4, 1.39, 1.41};
  EXPECT_EQ(f.refractiveIndexAt1300nm, n);
  EXPECT_DOUBLE_EQ(f.melaninRefractiveIndex, 1.7);
  EXPECT_DOUBLE_EQ(f.bloodHemoglobin_mgPerMl, 147.0);
  EXPECT_DOUBLE_EQ(f.bloodMethemoglobin_mgPerMl, 1.5);
  EXPECT_DOUBLE_EQ(f.bloodCarboxyhemoglobin_mgPerMl, 1.5);
  EXPECT_DOUBLE_EQ(f.bloodSulfhemoglobin_mgPerMl, 0.0);
  EXPECT_DOUBLE_EQ(f.bloodBilirubin_mgPerMl, 0.003);
  EXPECT_DOUBLE_EQ(f.bloodBetaCarotene_mgPerMl, 7.0e-5);
  EXPECT_DOUBLE_EQ(f.stratumCorneumBetaCarotene_mgPerMl, 2.1e-4);
  EXPECT_DOUBLE_EQ(f.epidermisBetaCarotene_mgPerMl, 2.1e-4);
  const std::array<double, kLayerCount> water = {0.35, 0.60, 0.60, 0.60, 0.75, 0.75};
  const std::array<double, kLayerCount> lipid = {0.35, 0.20, 0.20, 0.20, 0.151, 0.1733};
  for (Layer l : kAllLayers) {
    EXPECT_DOUBLE_EQ(f.waterFraction[index(l)], water[index(l)]) << layerName(l);
    EXPECT_DOUBLE_EQ(f.lipidFraction[index(l)], lipid[index(l)]) << layerName(l);
  }
  EXPECT_DOUBLE_EQ(f.stratumCorneumKeratinFraction, 0.65);
  EXPECT_DOUBLE_EQ(f.stratumCorneumUrocanicAcid_molPerL, 0.01);
  EXPECT_DOUBLE_EQ(f.dna_mgPerMl, 0.185);
}

TEST(Specimen, S2S3S4DifferWhereTable1Does) {
  const Specimen s2 = loadSpecimen("S2", kSpecimenDir);
  EXPECT_DOUBLE_EQ(s2.surfaceFoldAspectRatio, 0.25);
  EXPECT_EQ(s2.melanosomeFraction[index(Layer::StratumGranulosum)], 0.0);
  EXPECT_DOUBLE_EQ(s2.melanosomeFraction[index(Layer::StratumBasale)], 0.0375);
  EXPECT_DOUBLE_EQ(s2.oxygenatedBloodFraction, 0.95);
  EXPECT_DOUBLE_EQ(s2.thicknessCm[index(Layer::PapillaryDermis)], 0.01);

  const Specimen s3 = loadSpecimen("S3", kSpecimenDir);
  EXPECT_DOUBLE_EQ(s3.thicknessCm[index(Layer::StratumCorneum)], 0.0004);
  EXPECT_DOUBLE_EQ(s3.colloidalMelaninFraction[index(Layer::StratumSpinosum)], 0.0135);
  EXPECT_DOUBLE_EQ(s3.melanosomeEumelanin_mgPerMl, 32.0);
  EXPECT_DOUBLE_EQ(s3.thicknessCm[index(Layer::ReticularDermis)], 0.125);

  const Specimen s4 = loadSpecimen("S4", kSpecimenDir);
  EXPECT_EQ(s4.arrangement, MelanosomeArrangement::Dispersed);
  EXPECT_DOUBLE_EQ(s4.melanosomeMajorAxisUm, 0.69);
  EXPECT_DOUBLE_EQ(s4.melanosomeMinorAxisUm, 0.28);
  EXPECT_DOUBLE_EQ(s4.melanosomeFraction[index(Layer::StratumSpinosum)], 0.10);
  EXPECT_DOUBLE_EQ(s4.colloidalMelaninFraction[index(Layer::StratumBasale)], 0.15);
  EXPECT_DOUBLE_EQ(s4.bloodFraction[index(Layer::ReticularDermis)], 0.025);
  EXPECT_DOUBLE_EQ(s4.thicknessCm[index(Layer::StratumCorneum)], 0.0002);
}

TEST(Specimen, LoadsByPathToo) {
  const Specimen s = loadSpecimen((kSpecimenDir / "S3.toml").string(), "/nonexistent");
  EXPECT_EQ(s.name, "S3");
}

TEST(Specimen, UnknownNameSaysWhichFileIsMissing) {
  try {
    loadSpecimen("S9", kSpecimenDir);
    FAIL() << "no error";
  } catch (const SpecimenError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown specimen 'S9'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("S9.toml"), std::string::npos) << e.what();
  }
}

TEST(SpecimenErrors, UnknownKeyWithPosition) {
  const std::string text = editedS1("keratin_percent = 65.0", "keratin_percent = 65.0\nhair = 1");
  EXPECT_EQ(parseError(text).rfind(badTomlAt(text, "hair = 1") + ":1: unknown key 'hair'", 0), 0u)
      << parseError(text);
}

TEST(SpecimenErrors, WrongUnitSuffixNamesTheExpectedKey) {
  const std::string text = editedS1("thickness_cm = 0.001", "thickness_mm = 0.01");
  EXPECT_EQ(parseError(text), badTomlAt(text, "thickness_mm") +
                                  ":1: unknown key 'thickness_mm' (expected thickness_cm) in "
                                  "[stratum_corneum]");
  const std::string ratio = editedS1("blood_percent = 0.2", "blood_fraction = 0.002");
  EXPECT_NE(parseError(ratio).find("unknown key 'blood_fraction' (expected blood_percent)"),
            std::string::npos)
      << parseError(ratio);
}

TEST(SpecimenErrors, NegativeThickness) {
  const std::string text = editedS1("thickness_cm = 0.02 ", "thickness_cm = -0.02");
  EXPECT_EQ(parseError(text),
            badTomlAt(text, "thickness_cm = -0.02") + ":16: 'thickness_cm' = -0.02 must be >= 0");
}

TEST(SpecimenErrors, PercentAboveHundred) {
  const std::string text = editedS1("water_percent = 60.0", "water_percent = 160.0");
  EXPECT_EQ(parseError(text), badTomlAt(text, "water_percent = 160.0") +
                                  ":17: 'water_percent' = 160 must be in [0, 100]");
}

TEST(SpecimenErrors, WrongType) {
  const std::string text = editedS1("melanosome_percent = 1.0", "melanosome_percent = \"1\"");
  EXPECT_EQ(parseError(text), badTomlAt(text, "melanosome_percent = \"1\"") +
                                  ":22: 'melanosome_percent' must be a number, got a string");
  const std::string arrangement = editedS1("\"light_complexes\"", "2");
  EXPECT_NE(parseError(arrangement).find("'arrangement' must be a string, got an integer"),
            std::string::npos);
}

TEST(SpecimenErrors, IntegersAreAcceptedAsNumbers) {
  const Specimen s = parseSpecimen(editedS1("water_percent = 60.0", "water_percent = 60"), "x");
  EXPECT_DOUBLE_EQ(s.fixed.waterFraction[index(Layer::StratumBasale)], 0.6);
}

TEST(SpecimenErrors, MissingKeyPointsAtItsTable) {
  const std::string text = editedS1("lipid_percent = 17.33", "");
  EXPECT_EQ(parseError(text), badTomlAt(text, "[reticular_dermis]") +
                                  ":1: missing key 'lipid_percent' in [reticular_dermis]");
  // The living epidermis' keratin is not in the paper's tables but is required like the rest.
  const std::string noKeratin = editedS1("keratin_percent = 20.0", "");
  EXPECT_EQ(parseError(noKeratin), badTomlAt(noKeratin, "[epidermis]") +
                                       ":1: missing key 'keratin_percent' in [epidermis]");
  const std::string noName = editedS1("name = \"S1\"", "");
  EXPECT_NE(parseError(noName).find("bad.toml:1:1: missing key 'name' in the top level"),
            std::string::npos)
      << parseError(noName);
}

TEST(SpecimenErrors, MissingTable) {
  std::string text = editedS1("[blood]", "[blood_x]");
  EXPECT_NE(parseError(text).find("unknown key 'blood_x'"), std::string::npos) << parseError(text);
  const std::string full = readFile(kSpecimenDir / "S1.toml");
  const std::string truncated = full.substr(0, full.find("# Whole blood"));
  EXPECT_EQ(parseError(truncated), "bad.toml:1:1: missing table [blood]");
}

TEST(SpecimenErrors, NonFiniteAndBadArrangementAndAxes) {
  const std::string inf = editedS1("eumelanin_mg_per_ml = 90.0", "eumelanin_mg_per_ml = inf");
  EXPECT_NE(parseError(inf).find(":" + std::to_string(lineOf(inf, "= inf")) +
                                 ":23: 'eumelanin_mg_per_ml' = inf is not finite"),
            std::string::npos)
      << parseError(inf);
  const std::string arrangement = editedS1("\"light_complexes\"", "\"clumped\"");
  EXPECT_NE(parseError(arrangement).find("'arrangement' = \"clumped\" is not one of"),
            std::string::npos);
  const std::string axes = editedS1("minor_axis_um = 0.17", "minor_axis_um = 0.5");
  EXPECT_NE(parseError(axes).find(":" + std::to_string(lineOf(axes, "minor_axis_um")) +
                                  ":17: 'minor_axis_um' = 0.5 exceeds 'major_axis_um' = 0.41"),
            std::string::npos)
      << parseError(axes);
}

TEST(SpecimenErrors, TomlSyntaxErrorHasPosition) {
  const std::string text = editedS1("water_reduction_percent = 0.0", "water_reduction_percent = ");
  EXPECT_EQ(parseError(text).rfind(badTomlAt(text, "water_reduction_percent =") + ":", 0), 0u)
      << parseError(text);
}

TEST(SpecimenOverrides, GroupKeysSetEveryLayerTheyName) {
  Specimen s = loadSpecimen("S1", kSpecimenDir);
  applyOverride(s, {"melanosome_percent", 3.0, "--set"});
  applyOverride(s, {"colloidal_melanin_percent", 2.0, "--set"});
  applyOverride(s, {"blood_percent", 1.5, "--set"});
  applyOverride(s, {"water_reduction_percent", 20.0, "--set"});
  applyOverride(s, {"oxygenation_percent", 50.0, "--set"});
  for (Layer l : {Layer::StratumGranulosum, Layer::StratumSpinosum, Layer::StratumBasale}) {
    EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(l)], 0.03);
    EXPECT_DOUBLE_EQ(s.colloidalMelaninFraction[index(l)], 0.02);
  }
  EXPECT_DOUBLE_EQ(s.bloodFraction[index(Layer::PapillaryDermis)], 0.015);
  EXPECT_DOUBLE_EQ(s.bloodFraction[index(Layer::ReticularDermis)], 0.015);
  EXPECT_DOUBLE_EQ(s.waterReduction, 0.2);
  EXPECT_DOUBLE_EQ(s.oxygenatedBloodFraction, 0.5);
  applyOverride(s, {"stratum_basale.melanosome_percent", 7.0, "--set"});
  EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(Layer::StratumBasale)], 0.07);
  EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(Layer::StratumSpinosum)], 0.03);
  applyOverride(s, {"reticular_dermis.thickness_cm", 0.0, "--set"});
  EXPECT_EQ(s.thicknessCm[index(Layer::ReticularDermis)], 0.0);
  EXPECT_NO_THROW(validateSpecimen(s));
}

TEST(SpecimenOverrides, RangeErrorsNameTheOrigin) {
  Specimen s = loadSpecimen("S2", kSpecimenDir);
  const auto message = [&](const SpecimenOverride& o) {
    try {
      applyOverride(s, o);
    } catch (const SpecimenError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message({"melanosome_percent", 120.0, "scene.toml:12:5"}),
            "scene.toml:12:5: melanosome_percent = 120 must be in [0, 100]");
  EXPECT_EQ(message({"water_reduction_percent", -1.0, "--set"}),
            "--set: water_reduction_percent = -1 must be in [0, 100]");
  EXPECT_EQ(message({"blood_percent", NAN, "--set"}), "--set: blood_percent = nan is not finite");
  EXPECT_EQ(message({"surface_fold_aspect_ratio", 0.0, "--set"}),
            "--set: surface_fold_aspect_ratio = 0 must be > 0");
  EXPECT_EQ(message({"stratum_corneum.thickness_cm", -1e-3, "--set"}),
            "--set: stratum_corneum.thickness_cm = -0.001 must be >= 0");
  EXPECT_EQ(
      message({"melanin", 1.0, "--set"}).rfind("--set: unknown specimen override 'melanin'", 0),
      0u);
  // A rejected override leaves the specimen unchanged.
  EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(Layer::StratumBasale)], 0.0375);
  EXPECT_DOUBLE_EQ(s.waterReduction, 0.0);
}

TEST(SpecimenOverrides, KeysAreListed) {
  const auto keys = overrideKeys();
  for (const char* k : {"melanosome_percent", "colloidal_melanin_percent",
                        "water_reduction_percent", "blood_percent", "oxygenation_percent"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
}

TEST(SpecimenValidation, RejectsOutOfRangeFieldsBuiltInCode) {
  Specimen s = loadSpecimen("S1", kSpecimenDir);
  s.thicknessCm[index(Layer::PapillaryDermis)] = -1.0;
  EXPECT_THROW(validateSpecimen(s), SpecimenError);
  s = loadSpecimen("S1", kSpecimenDir);
  s.bloodFraction[index(Layer::StratumCorneum)] = 0.01;
  EXPECT_THROW(validateSpecimen(s), SpecimenError);
  s = loadSpecimen("S1", kSpecimenDir);
  s.melanosomeMinorAxisUm = 0.5;
  EXPECT_THROW(validateSpecimen(s), SpecimenError);
}

}  // namespace
}  // namespace hylios::skin
