// `hylios radial-profile` run in-process: one row per annulus with its exact area, the annuli add
// up to (at most) the subsurface reflectance of the same walk, and bad arguments are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/commands.h"
#include "skin/core/constants.h"
#include "tests/support/command_reference.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

const test::CommandRunner runProfile(registerRadialProfileCommand, "radial-profile");

TEST(RadialProfileCommand, AnnuliAddUpToTheSubsurfaceReflectance) {
  const test::ScratchOutputs outputs("radial-profile-test");
  runProfile("--specimen S1 --wavelength 550 --rays 3000 --seed 2 --max-radius-cm 2 --bins 20" +
             outputs.options());
  const auto rows = test::readCsv(outputs.csv);
  ASSERT_EQ(rows.size(), 1u + 20);
  const auto& header = rows[0];
  ASSERT_EQ(header, (std::vector<std::string>{
                        "inner_radius_cm", "outer_radius_cm", "annulus_area_cm2", "fraction",
                        "fraction_stderr", "reflectance_per_cm2", "reflectance_per_cm2_stderr"}));
  double subsurface = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), header.size());
    const double inner = std::stod(rows[r][0]), outer = std::stod(rows[r][1]);
    EXPECT_NEAR(inner, 0.1 * static_cast<double>(r - 1), 1e-9);
    EXPECT_NEAR(std::stod(rows[r][2]), kPi * (outer * outer - inner * inner), 1e-5 * outer * outer);
    subsurface +=
        std::stod(rows[r][test::columnOf(header, "reflectance_per_cm2")]) * std::stod(rows[r][2]);
  }
  skin::WalkRunOptions run;
  run.rays = 3000;
  run.seed = 2;
  const skin::SkinTally tally = test::spectralTally(test::specimenOptics("S1", 550), run);
  // Exits beyond 2 cm from the entry point are rare but possible: the annuli hold at most R_d.
  EXPECT_LE(subsurface, tally.subsurfaceReflectance().mean + 1e-5);
  EXPECT_GT(subsurface, tally.subsurfaceReflectance().mean - 0.01);
  EXPECT_GT(std::filesystem::file_size(outputs.png), 1000u);
}

TEST(RadialProfileCommand, BadArgumentsAreClearErrors) {
  test::ScratchFolder scratch("radial-profile-bad-test");
  const auto csv = scratch.path / "bad.csv";
  EXPECT_THROW(runProfile("--bins 0 --out " + csv.string()), CLI::ValidationError);
  EXPECT_THROW(runProfile("--max-radius-cm -1 --out " + csv.string()), CLI::ValidationError);
  EXPECT_THROW(runProfile("--angle 95 --out " + csv.string()), CLI::ValidationError);
  EXPECT_THROW(runProfile("--rays 10"), CLI::RequiredError);
  test::expectThrowMentioning([&] { runProfile("--specimen S9 --rays 10 --out " + csv.string()); },
                              "S9");
  EXPECT_FALSE(std::filesystem::exists(csv));
}

}  // namespace
}  // namespace hylios
