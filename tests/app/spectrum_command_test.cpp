// `hylios spectrum` run in-process: byte-identical CSV at 1 and 2 threads, the documented
// columns, one row per wavelength, and clear errors for bad arguments.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "tests/support/file_bytes.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const test::CommandRunner runSpectrum(registerSpectrumCommand, "spectrum");

using test::readBytes;

TEST(SpectrumCommand, SameSeedGivesByteIdenticalCsvAtAnyThreadCount) {
  const fs::path one = fs::path(HYLIOS_BINARY_DIR) / "spectrum_test_1thread.csv";
  const fs::path two = fs::path(HYLIOS_BINARY_DIR) / "spectrum_test_2threads.csv";
  const std::vector<std::string> common{
      "--specimen",   "S2",     "--angle", "45",     "--wavelengths",
      "365,550,1450", "--rays", "3000",    "--seed", "5"};
  auto with = [&](const std::string& threads, const fs::path& out) {
    auto args = common;
    args.insert(args.end(), {"--threads", threads, "--out", out.string()});
    return args;
  };
  runSpectrum(with("1", one));
  runSpectrum(with("2", two));
  const std::string csv = readBytes(one);
  EXPECT_EQ(csv, readBytes(two));
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("wavelength_nm,reflectance,reflectance_stderr,surface_reflectance,"
                         "subsurface_reflectance,transmittance,absorptance",
                         0),
            0u);
  int rows = 0;
  while (std::getline(lines, row)) ++rows;
  EXPECT_EQ(rows, 3);
}

TEST(SpectrumCommand, BadArgumentsAreClearErrorsAndWriteNothing) {
  const fs::path out = fs::path(HYLIOS_BINARY_DIR) / "spectrum_test_bad.csv";
  fs::remove(out);
  try {
    runSpectrum(
        {"--specimen", "S1", "--wavelengths", "200", "--rays", "10", "--out", out.string()});
    FAIL() << "200 nm accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(
        std::string(e.what()).find("--wavelengths '200': 200 nm is outside the model's range"),
        std::string::npos)
        << e.what();
  }
  try {
    runSpectrum({"--specimen", "S9", "--rays", "10", "--out", out.string()});
    FAIL() << "unknown specimen accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("S9"), std::string::npos) << e.what();
  }
  EXPECT_THROW(runSpectrum({"--angle", "90", "--out", out.string()}), CLI::ValidationError);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace hylios
