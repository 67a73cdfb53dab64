// The measured skin population (app/skin_population.h): the NIST set loads whole, its ranking by
// lightness and the envelope of a group give the values read off the data file by hand, and a
// value that is no reflectance factor is an error naming the subject and wavelength.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/skin_population.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

const std::filesystem::path kNist = std::filesystem::path(HYLIOS_SOURCE_DIR) / "tests" / "data" /
                                    "validation" / "nist_cooksey2017_skin.csv";

TEST(SkinPopulation, NistSetLoadsWhole) {
  const SkinPopulation nist = loadSkinPopulation(kNist);
  ASSERT_EQ(nist.subjects.size(), 100u);
  EXPECT_EQ(nist.subjects.front().label, "subject001");
  EXPECT_EQ(nist.subjects.front().wavelengthNm.size(), 751u);  // 250–2500 nm every 3 nm
  EXPECT_DOUBLE_EQ(nist.subjects.front().wavelengthNm.back(), 2500.0);
  EXPECT_DOUBLE_EQ(nist.subjects.front().at(250), 0.0573);  // first row, subject 1's average
  EXPECT_NEAR(nist.subjects.front().at(251.5), 0.5 * (0.0573 + 0.0561), 1e-12);
}

TEST(SkinPopulation, RankingAndEnvelopeMatchTheDataFile) {
  const SkinPopulation nist = loadSkinPopulation(kNist);
  const std::vector<std::size_t> order = nist.byLightness();
  // Mean over the 67 rows of 500–700 nm: subject 42 is the lightest, subject 44 the darkest.
  EXPECT_EQ(nist.subjects[order.front()].label, "subject042");
  EXPECT_EQ(nist.subjects[order.back()].label, "subject044");
  EXPECT_NEAR(nist.lightness(order.front()), 0.546079, 1e-6);
  EXPECT_NEAR(nist.lightness(order.back()), 0.193103, 1e-6);
  const std::vector<std::size_t> light = nist.quantileGroup(0.25, true);
  ASSERT_EQ(light.size(), 25u);
  EXPECT_EQ(light.front(), order.front());
  EXPECT_EQ(nist.quantileGroup(0.25, false).front(), order.back());
  const PopulationEnvelope e = nist.envelope(light, {250});
  EXPECT_EQ(e.members, 25u);
  EXPECT_DOUBLE_EQ(e.lowest[0], 0.0496);  // sorted 250 nm values of the 25: 1st, 13th, 25th
  EXPECT_DOUBLE_EQ(e.median[0], 0.0567);
  EXPECT_DOUBLE_EQ(e.highest[0], 0.0689);
  EXPECT_THROW(nist.quantileGroup(0, true), std::invalid_argument);
  EXPECT_THROW(nist.envelope({}, {250}), std::invalid_argument);
  EXPECT_THROW(nist.envelope(light, {240}), std::out_of_range);
}

TEST(SkinPopulation, EvenGroupsTakeTheMeanOfTheMiddleTwo) {
  test::ScratchFolder scratch("population");
  const auto file = scratch.path / "four.csv";
  std::ofstream(file) << "wavelength_nm,a,b,c,d\n500,0.1,0.4,0.2,0.3\n700,0.1,0.4,0.2,0.3\n";
  const SkinPopulation p = loadSkinPopulation(file);
  EXPECT_EQ(p.byLightness(), (std::vector<std::size_t>{1, 3, 2, 0}));
  const PopulationEnvelope e = p.envelope({0, 1, 2, 3}, {600});
  EXPECT_NEAR(e.median[0], 0.25, 1e-15);
  EXPECT_EQ(p.quantileGroup(0.5, false), (std::vector<std::size_t>{0, 2}));
}

TEST(SkinPopulation, AValueThatIsNoReflectanceFactorIsAnError) {
  test::ScratchFolder scratch("population");
  const auto file = scratch.path / "bad.csv";
  std::ofstream(file) << "wavelength_nm,a,b\n500,0.1,0.4\n700,0.1,-0.2\n";
  try {
    loadSkinPopulation(file);
    FAIL() << "negative reflectance accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.csv: b at 700"), std::string::npos) << what;
    EXPECT_NE(what.find("not a reflectance factor"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace hylios
