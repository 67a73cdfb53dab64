// `hylios forward-profile` run in-process: one row per polar bin, the first bin normalised to 1,
// the rows add up to the transmittance of the same epidermis-only walk, and bad arguments are
// clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/commands.h"
#include "tests/support/command_reference.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

const test::CommandRunner runProfile(registerForwardProfileCommand, "forward-profile");

TEST(ForwardProfileCommand, RowsAddUpToTheEpidermisTransmittance) {
  const test::ScratchOutputs outputs("forward-profile-test");
  runProfile("--wavelength 400 --rays 4000 --seed 3 --polar-bins 9" + outputs.options());
  const auto rows = test::readCsv(outputs.csv);
  ASSERT_EQ(rows.size(), 1u + 9);
  const auto& header = rows[0];
  ASSERT_EQ(header,
            (std::vector<std::string>{"polar_lower_deg", "polar_upper_deg", "solid_angle_sr",
                                      "transmitted_per_sr", "transmitted_per_sr_stderr",
                                      "relative_to_normal", "relative_to_normal_stderr"}));
  EXPECT_EQ(std::stod(rows[1][test::columnOf(header, "relative_to_normal")]), 1.0);
  double transmitted = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), header.size());
    transmitted += std::stod(rows[r][test::columnOf(header, "transmitted_per_sr")]) *
                   std::stod(rows[r][test::columnOf(header, "solid_angle_sr")]);
  }
  // The same walk: S2 (the default), epidermis only, bottom index matched to the stratum basale.
  const skin::SkinOptics optics = test::specimenOptics("S2", 400);
  skin::WalkRunOptions run;
  run.rays = 4000;
  run.seed = 3;
  run.walk.deepestLayer = skin::Layer::StratumBasale;
  run.walk.belowRefractiveIndex = optics[skin::Layer::StratumBasale].refractiveIndex;
  const skin::SkinTally tally = test::spectralTally(optics, run);
  EXPECT_NEAR(transmitted, tally.transmittance().mean, 1e-5);
  EXPECT_GT(tally.transmittance().mean, 0.1);  // 400 nm: a thin epidermis lets much through
  EXPECT_GT(std::filesystem::file_size(outputs.png), 1000u);
}

TEST(ForwardProfileCommand, BadArgumentsAreClearErrors) {
  test::ScratchFolder scratch("forward-profile-bad-test");
  const auto csv = scratch.path / "bad.csv";
  test::expectThrowMentioning<std::invalid_argument>(
      [&] { runProfile("--below-index water --rays 10 --out " + csv.string()); },
      "--below-index 'water'");
  EXPECT_THROW(runProfile("--below-index 0.5 --rays 10 --out " + csv.string()),
               std::invalid_argument);
  EXPECT_THROW(runProfile("--polar-bins 0 --out " + csv.string()), CLI::ValidationError);
  EXPECT_THROW(runProfile("--rays 10"), CLI::RequiredError);
  EXPECT_ANY_THROW(runProfile("--wavelength 3000 --rays 10 --out " + csv.string()));
  EXPECT_FALSE(std::filesystem::exists(csv));
}

}  // namespace
}  // namespace hylios
