// `hylios coefficients`: the CSV covers every wavelength and layer with finite numbers for S1–S4,
// its total column is the sum of its absorber columns, --set reaches the specimen, and the plot is
// written.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "app/commands.h"
#include "skin/absorber.h"
#include "skin/layer.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

using test::readCsv;
using test::ScratchFolder;

void runCommand(const std::string& arguments) {
  CLI::App app;
  registerCoefficientsCommand(app);
  app.parse("coefficients " + arguments, false);
}

constexpr std::size_t kColumns = 6 + skin::kAbsorberCount;

TEST(CoefficientsCommand, HeaderNamesEveryColumn) {
  ScratchFolder scratch("coefficients-test");
  runCommand("--specimen S1 --wavelengths 500 --out " + (scratch.path / "c.csv").string());
  const auto rows = readCsv(scratch.path / "c.csv");
  ASSERT_EQ(rows.size(), 1 + skin::kLayerCount);
  ASSERT_EQ(rows[0].size(), kColumns);
  EXPECT_EQ(rows[0][0], "wavelength_nm");
  EXPECT_EQ(rows[0][2], "mu_a_per_cm");
  EXPECT_EQ(rows[0][5], "refractive_index");
  EXPECT_EQ(rows[0][6], "mu_a_keratin_per_cm");
  EXPECT_EQ(rows[0][kColumns - 1], "mu_a_lipid_per_cm");
}

TEST(CoefficientsCommand, NoGapNoNanOver250To2500nmForEverySpecimen) {
  ScratchFolder scratch("coefficients-test");
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    const auto csv = scratch.path / (std::string(name) + ".csv");
    runCommand(std::string("--specimen ") + name + " --wavelengths 250:2500:5 --out " +
               csv.string());
    const auto rows = readCsv(csv);
    const std::size_t wavelengths = (2500 - 250) / 5 + 1;
    ASSERT_EQ(rows.size(), 1 + wavelengths * skin::kLayerCount) << name;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const auto& row = rows[r];
      ASSERT_EQ(row.size(), kColumns) << name << " row " << r;
      const std::size_t w = (r - 1) / skin::kLayerCount;
      const skin::Layer layer = skin::kAllLayers[(r - 1) % skin::kLayerCount];
      ASSERT_EQ(std::stod(row[0]), 250.0 + 5.0 * static_cast<double>(w)) << name << " row " << r;
      ASSERT_EQ(row[1], skin::layerName(layer));
      double absorberSum = 0;
      for (std::size_t c = 2; c < kColumns; ++c) {
        const double value = std::stod(row[c]);
        ASSERT_TRUE(std::isfinite(value) && value >= 0) << name << " row " << r << " col " << c;
        if (c >= 6) absorberSum += value;
      }
      // Each column is rounded to 6 significant digits; 14 terms: 1e-5 relative is ample.
      const double total = std::stod(row[2]);
      ASSERT_GT(total, 0.0) << name << " row " << r;
      ASSERT_NEAR(total, absorberSum, 1e-5 * total) << name << " row " << r;
    }
  }
}

TEST(CoefficientsCommand, SetOverridesReachTheSpecimen) {
  ScratchFolder scratch("coefficients-test");
  const auto plain = scratch.path / "plain.csv";
  const auto more = scratch.path / "more.csv";
  runCommand("--specimen S2 --wavelengths 500 --out " + plain.string());
  runCommand(
      "--specimen S2 --wavelengths 500 --set melanosome_percent=3 --set blood_percent=1 "
      "--out " +
      more.string());
  const auto a = readCsv(plain);
  const auto b = readCsv(more);
  const std::size_t granulosum = 1 + skin::index(skin::Layer::StratumGranulosum);
  const std::size_t papillary = 1 + skin::index(skin::Layer::PapillaryDermis);
  EXPECT_EQ(std::stod(a[granulosum][4]), 0.0);  // S2 has no melanosomes in the granulosum
  EXPECT_GT(std::stod(b[granulosum][4]), 0.0);
  EXPECT_GT(std::stod(b[papillary][2]), std::stod(a[papillary][2]));
}

TEST(CoefficientsCommand, BadInputsSayWhatIsWrong) {
  ScratchFolder scratch("coefficients-test");
  const std::string out = " --out " + (scratch.path / "x.csv").string();
  const auto message = [&](const std::string& args) {
    try {
      runCommand(args + out);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("--specimen S9").find("unknown specimen 'S9'"), std::string::npos);
  // The --set parser and messages of every command (app/specimen_options.h).
  EXPECT_NE(message("--specimen S1 --set melanosome_percent").find("expected KEY=VALUE"),
            std::string::npos);
  EXPECT_NE(message("--specimen S1 --set melanosome_percent=abc").find("is not a finite number"),
            std::string::npos);
  EXPECT_EQ(message("--specimen S1 --set melanosome_percent=150"),
            "--set melanosome_percent=150: melanosome_percent = 150 must be in [0, 100]");
  EXPECT_FALSE(message("--specimen S1 --wavelengths 250:2500:0").empty());
  EXPECT_FALSE(std::filesystem::exists(scratch.path / "x.csv"));
}

TEST(CoefficientsCommand, WritesAPngPlot) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  ScratchFolder scratch("coefficients-test");
  const auto png = scratch.path / "c.png";
  runCommand("--specimen S4 --wavelengths 250:2500:10 --out " + (scratch.path / "c.csv").string() +
             " --plot " + png.string());
  std::ifstream in(png, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

}  // namespace
}  // namespace hylios
