// Tests of the measured UV tables (issue 14): each PhotochemCAD molecule table (one test each)
// loads with its unit column, its range and its row at a named wavelength; keratin (aromatic amino
// acids weighted by Block 1951's composition) and DNA (bases weighted by base composition, scaled
// to A260 = 20 per mg/mL) give the hand-computed sums; each ends at its declared zero; the layers'
// dispersion reads Hale & Querry's n. Hand values are computed from the rows quoted in comments.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>

#include "skin/spectral_database.h"
#include "skin/spectral_table.h"
#include "tests/support/test_spectra.h"

namespace hylios::skin {
namespace {

namespace fs = std::filesystem;
const double kLn10 = std::log(10.0);

/// The tables the database is loaded from (tests/support/test_spectra.h: the source tree's).
fs::path spectraDir() { return fs::path(HYLIOS_SOURCE_DIR) / "assets" / "spectra"; }

double mu(Absorber a, double nm) { return test::spectra().specificAbsorption(a, nm); }

/// Decadic molar extinction [cm⁻¹ M⁻¹] of a PhotochemCAD table at one of its rows.
double molarExtinction(const std::string& file, double nm) {
  const SpectralTable t = SpectralTable::loadCsv(spectraDir() / file);
  EXPECT_EQ(t.columnNames().size(), 1u) << file;
  return t.interpolate(t.columnIndex("molar_extinction_cm-1_M-1"), nm);
}

struct TableRow {
  const char* file;
  double nm;
  double value;  ///< the row's molar extinction, cm⁻¹ M⁻¹ (decadic)
  double firstNm, lastNm;
};

// One row of each table, copied from the file, and the table's range.
const TableRow kRows[] = {
    {"tyrosine_photochemcad.csv", 275.0, 1400.1, 240.0, 350.0},
    {"tryptophan_photochemcad.csv", 280.0, 5502.2, 235.0, 350.0},
    {"phenylalanine_photochemcad.csv", 260.0, 143.84, 225.0, 300.0},
    {"adenine_photochemcad.csv", 260.0, 12946.0, 220.0, 350.0},
    {"guanine_photochemcad.csv", 246.0, 10625.0, 230.0, 350.0},
    {"cytosine_photochemcad.csv", 270.0, 5830.6, 235.0, 350.0},
    {"thymine_photochemcad.csv", 260.0, 7549.7, 220.0, 350.0},
};

void PrintTo(const TableRow& row, std::ostream* out) { *out << row.file; }

// One test per table: it loads, has the one unit column, its range, and the quoted row.
class MoleculeTable : public ::testing::TestWithParam<TableRow> {};

TEST_P(MoleculeTable, LoadsWithItsUnitRangeAndRow) {
  const TableRow& row = GetParam();
  const SpectralTable t = SpectralTable::loadCsv(spectraDir() / row.file);
  EXPECT_EQ(t.minWavelengthNm(), row.firstNm);
  EXPECT_EQ(t.maxWavelengthNm(), row.lastNm);
  EXPECT_EQ(molarExtinction(row.file, row.nm), row.value);
}

INSTANTIATE_TEST_SUITE_P(UvAbsorberTables, MoleculeTable, ::testing::ValuesIn(kRows),
                         [](const ::testing::TestParamInfo<TableRow>& p) {
                           const std::string file = p.param.file;
                           return file.substr(0, file.find('_'));
                         });

TEST(UvAbsorberTables, PhotochemcadScalingsAreThoseOfItsRecords) {
  // The PhotochemCAD scalings (records F03, F05, F06, F07): ε = 1405 at 274.8 nm (tyrosine),
  // 5579 at 279 nm (tryptophan), 13,000 at 260.5 nm (adenine), 10,700 at 246 nm (guanine).
  EXPECT_NEAR(molarExtinction("tyrosine_photochemcad.csv", 274.75) / 1405.0, 1.0, 0.01);
  EXPECT_NEAR(molarExtinction("tryptophan_photochemcad.csv", 279.0) / 5579.0, 1.0, 0.02);
  EXPECT_NEAR(molarExtinction("adenine_photochemcad.csv", 260.5) / 13000.0, 1.0, 0.01);
  EXPECT_NEAR(molarExtinction("guanine_photochemcad.csv", 246.0) / 10700.0, 1.0, 0.01);
}

TEST(UvAbsorberTables, KeratinIsTheWeightedSumOfItsAromaticAminoAcids) {
  // Rows at 280 nm: tyrosine 1206.7, tryptophan 5502.2, phenylalanine 1.7347 cm⁻¹ M⁻¹. Per unit
  // volume fraction of keratin at 1300 mg/mL with 5.0, 0.5, 2.9 g per 100 g (MW 181.19, 204.23,
  // 165.19): ln10 · 1300 · (0.05·1206.7/181.19 + 0.005·5502.2/204.23 + 0.029·1.7347/165.19)
  // = 1400.903 cm⁻¹.
  EXPECT_NEAR(mu(Absorber::Keratin, 280.0), 1400.903, 1e-3);
  // 300 nm: tyrosine 18.699, tryptophan 507.44; phenylalanine is zero from 300 nm: 52.633 cm⁻¹.
  EXPECT_NEAR(mu(Absorber::Keratin, 300.0), 52.633, 1e-3);
  // Tryptophan is zero from 313.5 nm, so from there on tyrosine alone (row 320 nm: 11.081).
  EXPECT_NEAR(mu(Absorber::Keratin, 320.0), kLn10 * 1300.0 * 0.05 * 11.081 / 181.19, 1e-9);
  // Zero from 350 nm (tyrosine's last row), up to the end of the domain.
  EXPECT_EQ(mu(Absorber::Keratin, 350.0), 0.0);
  EXPECT_EQ(mu(Absorber::Keratin, 2500.0), 0.0);
  EXPECT_GT(mu(Absorber::Keratin, 349.0), 0.0);
}

TEST(UvAbsorberTables, DnaIsTheBaseCompositionSumScaledToA260) {
  // A260 = 1 for 50 µg/mL over 1 cm: 20 cm⁻¹ per mg/mL, decadic.
  EXPECT_NEAR(mu(Absorber::Dna, 260.0), kLn10 * 20.0, 1e-9);
  // GC 41 %: ε_mix = 0.295·A + 0.205·G + 0.205·C + 0.295·T. Rows at 260 nm: 12946, 10698,
  // 5576.6, 7549.7 ⇒ 9382.52; at 280 nm: 1608.9, 11374, 3126.3, 3948.8 ⇒ 4612.08.
  // ζ(280) = ln10 · 20 · 4612.08 / 9382.52 = 22.6372; A260/A280 = 2.034 (pure DNA: 1.8–2.0).
  EXPECT_NEAR(mu(Absorber::Dna, 280.0), 22.6372, 1e-4);
  // Thymine is zero from 310.5 nm, adenine from 328.5 nm, guanine and cytosine from 350 nm.
  EXPECT_EQ(mu(Absorber::Dna, 350.0), 0.0);
  EXPECT_EQ(mu(Absorber::Dna, 420.0), 0.0);
  EXPECT_GT(mu(Absorber::Dna, 349.0), 0.0);
}

TEST(UvAbsorberTables, LayerDispersionReadsHaleAndQuerry) {
  // Hale & Querry rows 250 nm: n = 1.362; 1200 and 1400 nm: 1.324 and 1.321 ⇒ 1.3225 at 1300 nm.
  EXPECT_DOUBLE_EQ(test::spectra().waterRefractiveIndex(250.0), 1.362);
  EXPECT_NEAR(test::spectra().waterRefractiveIndex(1300.0), 1.3225, 1e-12);
  // Water's absorption still comes from Segelstein's k (spectral_database_test, 1450 nm).
}

}  // namespace
}  // namespace hylios::skin
