// `hylios fit` run in-process: it writes a specimen file that the spectrum command reads, lowers
// the RMS to the measured curve, and refuses bad inputs (unknown quantity, no common wavelength,
// NaN in the measured file) with clear errors, writing nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/commands.h"
#include "skin/specimen.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;
const std::string kNcsu =
    std::string(HYLIOS_SOURCE_DIR) + "/tests/data/validation/ncsu_vrhel1994_skin.csv";

std::string runFit(const std::string& arguments) {
  try {
    test::runCommandLine(registerFitCommand, "fit " + arguments);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(FitCommand, WritesASpecimenThatSpectrumReads) {
  test::ScratchFolder scratch("fit-command");
  const fs::path out = scratch.path / "fitted.toml";
  const std::string error = runFit("--measured " + kNcsu +
                                   ":obj113 --specimen S2 --angle 45 --wavelengths 400:700:30 "
                                   "--free colloidal,blood --rays 2000 --max-iterations 4 --out " +
                                   out.string());
  ASSERT_EQ(error, "");
  const skin::Specimen fitted = skin::loadSpecimen(out.string(), "");
  EXPECT_EQ(fitted.name, "S2");
  std::ifstream in(out);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first.rfind("# Specimen fitted by `hylios fit`", 0), 0u);
  // The spectrum command reads it.
  const fs::path csv = scratch.path / "fitted.csv";
  test::runCommandLine(registerSpectrumCommand, "spectrum --specimen " + out.string() +
                                                    " --wavelengths 550 --rays 500 --out " +
                                                    csv.string());
  EXPECT_EQ(test::readCsv(csv).size(), 2u);
}

TEST(FitCommand, BadInputsAreClearErrorsAndWriteNothing) {
  test::ScratchFolder scratch("fit-command-bad");
  const fs::path out = scratch.path / "fitted.toml";
  const std::string common = " --specimen S2 --rays 200 --out " + out.string();
  EXPECT_NE(runFit("--measured " + kNcsu + ":obj113 --free blood,melanin" + common)
                .find("unknown fit quantity 'melanin'"),
            std::string::npos);
  EXPECT_NE(runFit("--measured " + kNcsu + ":obj113 --wavelengths 800:900:10 --free blood" + common)
                .find("covers none of --wavelengths 800:900:10"),
            std::string::npos);
  const fs::path nan = scratch.path / "nan.csv";
  std::ofstream(nan) << "wavelength_nm,skin\n400,0.2\n450,nan\n500,0.3\n";
  const std::string nanError = runFit("--measured " + nan.string() + ":skin --free blood" + common);
  EXPECT_NE(nanError.find("nan.csv:3"), std::string::npos) << nanError;
  EXPECT_NE(nanError.find("not a finite number"), std::string::npos) << nanError;
  EXPECT_NE(runFit("--measured " + kNcsu + ":obj113 --free blood --specimen S2 --out " +
                   (scratch.path / "no" / "f.toml").string())
                .find("does not exist"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace hylios
