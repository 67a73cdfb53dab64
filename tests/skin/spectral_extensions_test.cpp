// Tests of SpectralExtensions::parse (the text form of SpectralExtensions::load, used by the
// fuzz harness): same values as loading the file, errors named after the given source.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "skin/spectral_database.h"
#include "skin/spectral_extensions.h"

namespace hylios::skin {
namespace {

const std::string kExtensions = std::string(HYLIOS_SOURCE_DIR) + "/assets/spectra/extensions.toml";

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SpectralExtensions, ParseGivesTheSameValuesAsLoad) {
  const SpectralExtensions loaded = SpectralExtensions::load(kExtensions);
  const SpectralExtensions parsed = SpectralExtensions::parse(fileText(kExtensions), "text.toml");
  EXPECT_EQ(parsed.domainMinNm, loaded.domainMinNm);
  EXPECT_EQ(parsed.domainMaxNm, loaded.domainMaxNm);
  EXPECT_EQ(parsed.hemoglobinDecayLengthNm, loaded.hemoglobinDecayLengthNm);
  EXPECT_EQ(parsed.betaCaroteneZeroFromNm, loaded.betaCaroteneZeroFromNm);
  EXPECT_EQ(parsed.keratin.tryptophan.share, loaded.keratin.tryptophan.share);
  EXPECT_EQ(parsed.dna.thymine.share, loaded.dna.thymine.share);
  EXPECT_EQ(parsed.urocanicAcid.zeroFromNm, loaded.urocanicAcid.zeroFromNm);
}

TEST(SpectralExtensions, ParseErrorsNameTheSourceAndPosition) {
  try {
    SpectralExtensions::parse("[domain]\nmin_nm = 250.0\nmax_nm = = 2500\n", "inline.toml");
    FAIL() << "syntax error accepted";
  } catch (const SpectralDataError& e) {
    EXPECT_NE(std::string(e.what()).find("inline.toml:3:"), std::string::npos) << e.what();
  }
  try {
    SpectralExtensions::parse("[domain]\nmin_nm = 250.0\n", "inline.toml");
    FAIL() << "missing key accepted";
  } catch (const SpectralDataError& e) {
    EXPECT_NE(std::string(e.what()).find("lacks the key 'max_nm'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hylios::skin
