// Tests of the spectral database: hand-computed values from table rows, the declared extensions
// (continuity, the urocanic acid band's constraints, zero beyond bands), coverage errors, and load
// errors. Keratin, DNA and the water index: uv_absorber_tables_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "skin/spectral_database.h"
#include "tests/support/test_folder.h"

namespace hylios::skin {
namespace {

namespace fs = std::filesystem;
const double kLn10 = std::log(10.0);

fs::path spectraDir() {
  const char* env = std::getenv("HYLIOS_DATA_DIR");
  return fs::path(env != nullptr && *env != '\0' ? env : HYLIOS_SOURCE_DIR) / "assets" / "spectra";
}

const SpectralDatabase& database() {
  static const SpectralDatabase db = SpectralDatabase::load(spectraDir());
  return db;
}

double mu(Absorber a, double nm) { return database().specificAbsorption(a, nm); }

std::string errorAt(Absorber a, double nm) {
  try {
    database().specificAbsorption(a, nm);
  } catch (const SpectralDataError& e) {
    return e.what();
  }
  return "";
}

TEST(SpectralDatabase, WholeBloodOxyhemoglobinAt550nm) {
  // Prahl table row "550,43016,53412": ε(HbO2) = 43016 cm⁻¹/M (decadic, per tetramer, MW 64,500).
  // Whole blood at 150 g/L: μa = ln10 · 43016 · 150 / 64500 = 230.3442 cm⁻¹.
  EXPECT_NEAR(mu(Absorber::Oxyhemoglobin, 550.0) * 150.0, 230.3442, 1e-3);
  // Deoxy from the same row: ln10 · 53412 · 150 / 64500 = 286.0.
  EXPECT_NEAR(mu(Absorber::Deoxyhemoglobin, 550.0) * 150.0, kLn10 * 53412 * 150 / 64500, 1e-9);
}

TEST(SpectralDatabase, WaterAt1450nmFromSegelsteinK) {
  // Segelstein rows 1449 nm (k = 3.637e-4) and 1459 nm (k = 3.604e-4): k(1450) = 3.6337e-4,
  // μa = 4π k / λ = 4π · 3.6337e-4 / 1.450e-4 cm = 31.491 cm⁻¹.
  EXPECT_NEAR(mu(Absorber::Water, 1450.0), 31.491, 1e-3);
  // The real index is Hale & Querry's (uv_absorber_tables_test.cpp), not Segelstein's.
}

TEST(SpectralDatabase, MelaninPowerLawsAreContinuousAtTheTableEdge) {
  for (auto [a, edgeNm] :
       {std::pair{Absorber::Eumelanin, 820.26}, std::pair{Absorber::Pheomelanin, 829.42}}) {
    const double below = mu(a, edgeNm - 1e-6), above = mu(a, edgeNm + 1e-6);
    EXPECT_LT(std::abs(above - below) / below, 0.01) << absorberName(a);
    EXPECT_GT(mu(a, 1000.0), mu(a, 2000.0)) << absorberName(a);
  }
  // Last table points: eumelanin 1.494 at 820.26 nm, pheomelanin 0.163 at 829.42 nm (decadic).
  EXPECT_NEAR(mu(Absorber::Eumelanin, 820.26), kLn10 * 1.494, 1e-9);
  EXPECT_NEAR(mu(Absorber::Pheomelanin, 829.42), kLn10 * 0.163, 1e-9);
  // Fits made offline over the rows ≥ 600 nm (slopes −3.4667 and −6.6759) give at 1000 nm
  // decadic 0.75170 and 0.046766 cm⁻¹/(mg/mL), i.e. natural 1.73085 and 0.107684.
  EXPECT_NEAR(mu(Absorber::Eumelanin, 1000.0), 1.73085, 2e-4);
  EXPECT_NEAR(mu(Absorber::Pheomelanin, 1000.0), 0.107684, 2e-5);
}

TEST(SpectralDatabase, EveryAbsorberIsFiniteAndNonNegativeOver250To2500nm) {
  for (Absorber a : kAllAbsorbers) {
    for (int nm = 250; nm <= 2500; ++nm) {
      const double v = mu(a, nm);
      ASSERT_TRUE(std::isfinite(v) && v >= 0) << absorberName(a) << " at " << nm << " nm: " << v;
    }
    const SpectralCoverage c = database().coverage(a);
    EXPECT_EQ(c.minNm, 250.0) << absorberName(a);
    EXPECT_EQ(c.maxNm, 2500.0) << absorberName(a);
  }
}

TEST(SpectralDatabase, OutsideCoverageThrowsNamingSubstanceAndRange) {
  for (Absorber a : kAllAbsorbers) {
    for (double nm : {249.0, 2501.0}) {
      const std::string message = errorAt(a, nm);
      EXPECT_NE(message.find(std::string(absorberName(a)) + ":"), std::string::npos) << message;
      EXPECT_NE(message.find("250–2500 nm"), std::string::npos) << message;
    }
  }
  EXPECT_THROW(database().waterRefractiveIndex(249.0), SpectralDataError);
  EXPECT_THROW(database().waterRefractiveIndex(2501.0), SpectralDataError);
  EXPECT_THROW(database().specificAbsorption(Absorber::Water, std::nan("")), SpectralDataError);
}

TEST(SpectralDatabase, ConcentrationUnits) {
  using U = ConcentrationUnit;
  EXPECT_EQ(SpectralDatabase::concentrationUnit(Absorber::Keratin), U::VolumeFraction);
  EXPECT_EQ(SpectralDatabase::concentrationUnit(Absorber::Water), U::VolumeFraction);
  EXPECT_EQ(SpectralDatabase::concentrationUnit(Absorber::Lipid), U::VolumeFraction);
  EXPECT_EQ(SpectralDatabase::concentrationUnit(Absorber::UrocanicAcid), U::MolarConcentration);
  for (Absorber a :
       {Absorber::Dna, Absorber::Eumelanin, Absorber::Pheomelanin, Absorber::Oxyhemoglobin,
        Absorber::Deoxyhemoglobin, Absorber::Carboxyhemoglobin, Absorber::Methemoglobin,
        Absorber::Sulfhemoglobin, Absorber::Bilirubin, Absorber::BetaCarotene})
    EXPECT_EQ(SpectralDatabase::concentrationUnit(a), U::MassConcentration) << absorberName(a);
}

TEST(SpectralDatabase, UrocanicAcidBandMeetsItsCitedConstraints) {
  // trans-urocanic acid (band model, no table found): peak 280 nm in the stratum corneum,
  // ε = 18,800 M⁻¹cm⁻¹ there; the in-vitro width (1 % of the peak 340 − 268 nm away, i.e.
  // ΔE = 4.62627 − 3.64659 = 0.97968 eV) moved with the peak: 1 % at 1239.84 / (4.42800 − 0.97968)
  // = 359.55 nm; at 300 nm exp(−½ ((4.42800 − 4.13280) / 0.32281)²) = 0.65828. Zero from 440 nm.
  // Keratin and DNA are tables: uv_absorber_tables_test.cpp.
  const double peak = mu(Absorber::UrocanicAcid, 280.0);
  EXPECT_NEAR(peak, kLn10 * 18800.0, 1e-6);
  EXPECT_NEAR(mu(Absorber::UrocanicAcid, 359.55) / peak, 0.01, 2e-5);
  EXPECT_NEAR(mu(Absorber::UrocanicAcid, 300.0) / peak, 0.65828, 1e-5);
  EXPECT_LT(mu(Absorber::UrocanicAcid, 268.0), peak);
  EXPECT_EQ(mu(Absorber::UrocanicAcid, 440.0), 0.0);
  EXPECT_EQ(mu(Absorber::UrocanicAcid, 1000.0), 0.0);
  EXPECT_GT(mu(Absorber::UrocanicAcid, 439.0), 0.0);
}

TEST(SpectralDatabase, CarotenoidsFollowTheirTablesThenEndAtZero) {
  // Bilirubin peak row "450.75,55023", MW 584.66: ln10 · 55023 / 584.66 = 216.699.
  EXPECT_NEAR(mu(Absorber::Bilirubin, 450.75), 216.699, 1e-3);
  EXPECT_EQ(mu(Absorber::Bilirubin, 557.0), 0.0);
  EXPECT_EQ(mu(Absorber::Bilirubin, 600.0), 0.0);
  EXPECT_EQ(mu(Absorber::BetaCarotene, 536.24), 0.0);
  EXPECT_EQ(mu(Absorber::BetaCarotene, 700.0), 0.0);
  // β-carotene row "451,..." is scaled to 139,500 M⁻¹cm⁻¹ by PhotochemCAD; MW 536.87.
  EXPECT_NEAR(mu(Absorber::BetaCarotene, 451.0) / (kLn10 * 139500.0 / 536.87), 1.0, 0.02);
}

TEST(SpectralDatabase, HemoglobinFillsAreContinuousAndTheTailReachesTheFloor) {
  // MetHb at 390 nm: van Assendelft 84.5 L/mmol/cm per haem × 4000, MW 64,458 ⇒ 12.0741.
  EXPECT_NEAR(mu(Absorber::Methemoglobin, 390.0), 12.0741, 1e-4);
  const Absorber hemoglobins[] = {Absorber::Oxyhemoglobin, Absorber::Deoxyhemoglobin,
                                  Absorber::Carboxyhemoglobin, Absorber::Methemoglobin,
                                  Absorber::Sulfhemoglobin};
  for (Absorber a : hemoglobins) {
    for (double junction : {390.0, 450.0, 800.0, 1000.0}) {
      const double below = mu(a, junction - 1e-7), above = mu(a, junction + 1e-7);
      EXPECT_LT(std::abs(above - below), 1e-5 * std::max(below, 1e-3))
          << absorberName(a) << " at " << junction;
    }
    // The floor F, computed offline from the Bosschaart rows 1150–1780 nm by the procedure in
    // extensions.toml: median[(μa_blood − 0.8 μa_water)/150] = 0.007959 cm⁻¹ per mg/mL.
    EXPECT_NEAR(mu(a, 2500.0), 0.007959, 2e-6) << absorberName(a);
  }
  // Oxy: from ζ(1000) = ln10·1024/64500 = 0.036556 towards F with a 130 nm decay length.
  const double f = mu(Absorber::Oxyhemoglobin, 2500.0);
  EXPECT_NEAR(mu(Absorber::Oxyhemoglobin, 1130.0), f + (0.036556 - f) * std::exp(-1.0), 1e-6);
}

TEST(SpectralDatabase, LipidJoinsItsTablesAndHoldsTheUvValue) {
  EXPECT_NEAR(mu(Absorber::Lipid, 250.0), 0.0828, 1e-12);    // van Veen 429 nm: 8.280 m⁻¹
  EXPECT_NEAR(mu(Absorber::Lipid, 1098.0), 0.04911, 1e-12);  // van Veen 1098 nm: 4.911 m⁻¹
  EXPECT_NEAR(mu(Absorber::Lipid, 1110.0), 0.06298, 1e-12);  // lard 1110 nm
  // Anderson duplicates at 1135.668 nm: (0.125352 + 0.145731)/2 = 0.135541.
  EXPECT_NEAR(mu(Absorber::Lipid, 1135.668016194332), 0.135541, 1e-6);
  EXPECT_NEAR(mu(Absorber::Lipid, 2500.0), 18.853871089458192, 1e-9);  // corn oil 2500 nm
}

// ---- load errors: a copy of the data folder with one defect -------------------------------

class SpectralDatabaseLoadTest : public ::testing::Test {
 protected:
  fs::path dir_;
  void SetUp() override {
    dir_ = hylios::test::freshTestFolder("hylios_spectral_db_");
    fs::copy(spectraDir(), dir_, fs::copy_options::recursive);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void replaceInFile(const std::string& file, const std::string& from, const std::string& to) {
    std::ifstream in(dir_ / file);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const auto at = s.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
    std::ofstream(dir_ / file) << s;
  }

  std::string loadError() const {
    try {
      SpectralDatabase::load(dir_);
    } catch (const SpectralDataError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(SpectralDatabaseLoadTest, MissingTableNamesTheFile) {
  fs::remove(dir_ / "eumelanin_sarna_swartz.csv");
  EXPECT_NE(loadError().find("eumelanin_sarna_swartz.csv"), std::string::npos);
}

TEST_F(SpectralDatabaseLoadTest, MalformedTableNamesFileAndLine) {
  replaceInFile("hemoglobin_oxy_deoxy_prahl.csv", "\n550,43016,", "\n550,4x016,");
  const std::string message = loadError();
  EXPECT_NE(message.find("hemoglobin_oxy_deoxy_prahl.csv:152"), std::string::npos) << message;
}

TEST_F(SpectralDatabaseLoadTest, UnknownExtensionKeyNamesFileAndLine) {
  replaceInFile("extensions.toml", "decay_length_nm = 130.0",
                "decay_length_nm = 130.0\ndecay_lenght_nm = 1.0");
  const std::string message = loadError();
  EXPECT_NE(message.find("extensions.toml:"), std::string::npos) << message;
  EXPECT_NE(message.find("decay_lenght_nm"), std::string::npos) << message;
}

TEST_F(SpectralDatabaseLoadTest, BandCutTooEarlyIsRefused) {
  replaceInFile("extensions.toml", "zero_from_nm = 440.0", "zero_from_nm = 300.0");
  EXPECT_NE(loadError().find("urocanic_acid"), std::string::npos);
}

TEST_F(SpectralDatabaseLoadTest, MoleculeEndBeyondItsTableIsRefused) {
  // [keratin.tyrosine] ends with its table at 350 nm; 360 nm lies beyond the table.
  replaceInFile("extensions.toml", "zero_from_nm = 350.0", "zero_from_nm = 360.0");
  const std::string message = loadError();
  EXPECT_NE(message.find("tyrosine_photochemcad.csv"), std::string::npos) << message;
}

TEST_F(SpectralDatabaseLoadTest, UnknownMoleculeTableIsRefused) {
  replaceInFile("extensions.toml", "[keratin.phenylalanine]", "[keratin.cystine]");
  const std::string message = loadError();
  EXPECT_NE(message.find("keratin.cystine"), std::string::npos) << message;
}

}  // namespace
}  // namespace hylios::skin
