#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/measured_spectrum.h"

namespace {
const std::string kNcsu =
    std::string(HYLIOS_SOURCE_DIR) + "/tests/data/validation/ncsu_vrhel1994_skin.csv";

void expectError(const std::string& spec, const std::string& fragment) {
  try {
    hylios::loadMeasuredSpectrum(spec);
    FAIL() << "no error for " << spec;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(MeasuredSpectrum, LoadsNcsuObjectByPrefix) {
  const auto s = hylios::loadMeasuredSpectrum(kNcsu + ":obj113");
  EXPECT_EQ(s.label, "obj113 skin -- caucasian");
  EXPECT_DOUBLE_EQ(s.wavelengthNm.front(), 390.0);
  EXPECT_DOUBLE_EQ(s.wavelengthNm.back(), 730.0);
  EXPECT_DOUBLE_EQ(s.at(390.0), 0.1116);                     // first data row of obj113
  EXPECT_NEAR(s.at(391.0), 0.5 * (0.1116 + 0.1125), 1e-12);  // halfway to the 392 nm row
}

TEST(MeasuredSpectrum, RmsDifferenceOverCoveredWavelengths) {
  const auto s = hylios::loadMeasuredSpectrum(kNcsu + ":obj113");
  std::size_t compared = 0;
  const double rms =
      hylios::rmsDifference({380, 390, 392}, {0.0, 0.1116 + 0.01, 0.1125 - 0.02}, s, &compared);
  EXPECT_EQ(compared, 2u);  // 380 nm is outside the measurement
  EXPECT_NEAR(rms, std::sqrt((0.01 * 0.01 + 0.02 * 0.02) / 2), 1e-12);
}

TEST(MeasuredSpectrum, ErrorsSayWhereAndWhat) {
  expectError(kNcsu, "expected FILE:COLUMN");
  expectError(kNcsu + ":obj999", "no column named 'obj999'");
  expectError(kNcsu + ":obj1", "several columns start with 'obj1'");
  expectError("/nonexistent.csv:x", "cannot open");
  const auto bad = std::filesystem::temp_directory_path() / "hylios_measured_bad.csv";
  std::ofstream(bad) << "wavelength_nm,r\n400,0.1\n410,abc\n";
  expectError(bad.string() + ":r", ":3: 'abc' is not a finite number");
}

TEST(MeasuredSpectrum, ParsesFromAStreamWithTheGivenName) {
  std::istringstream csv("wavelength_nm,\"r, quoted\",q\r\n400,0.1,5\r\n410,0.3,6\r\n");
  const auto s = hylios::parseMeasuredSpectrum(csv, "2", "inline.csv");
  EXPECT_EQ(s.label, "r, quoted");
  EXPECT_NEAR(s.at(405.0), 0.2, 1e-15);
  std::istringstream bad("wavelength_nm,r\n400,0.1\n400,0.2\n");
  try {
    hylios::parseMeasuredSpectrum(bad, "r", "inline.csv");
    FAIL() << "repeated wavelength accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("inline.csv:3: wavelengths must ascend"),
              std::string::npos)
        << e.what();
  }
}

TEST(MeasuredSpectrum, LoadsEveryColumnOnOneGrid) {
  std::istringstream csv("wavelength_nm,a,b\n400,0.1,0.5\n410,0.3,0.7\n");
  const auto all = hylios::parseMeasuredSpectra(csv, "inline.csv");
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].label, "a");
  EXPECT_EQ(all[1].label, "b");
  EXPECT_EQ(all[1].wavelengthNm, (std::vector<double>{400, 410}));
  EXPECT_NEAR(all[1].at(405.0), 0.6, 1e-15);
  std::istringstream ragged("wavelength_nm,a,b\n400,0.1,0.5\n410,0.3\n");
  try {
    hylios::parseMeasuredSpectra(ragged, "inline.csv");
    FAIL() << "a short row accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("inline.csv:3: 2 fields, header has 3"), std::string::npos)
        << e.what();
  }
  std::istringstream onlyWavelengths("wavelength_nm\n400\n410\n");
  EXPECT_THROW(hylios::parseMeasuredSpectra(onlyWavelengths, "inline.csv"), std::runtime_error);
}
