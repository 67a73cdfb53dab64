// `hylios brdf` run in-process: one CSV row per direction bin with the documented columns, the
// bins add up to the hemispherical reflectance of the same walk, output is identical at any
// thread count, and bad arguments are clear errors that write nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/commands.h"
#include "skin/core/constants.h"
#include "tests/support/command_reference.h"
#include "tests/support/file_bytes.h"
#include "tests/support/scratch_csv.h"

namespace hylios {
namespace {

const test::CommandRunner runBrdf(registerBrdfCommand, "brdf");

TEST(BrdfCommand, OneRowPerBinAddingUpToTheReflectance) {
  const test::ScratchOutputs outputs("brdf-test");
  runBrdf(
      "--specimen S1 --angle 45 --wavelengths 550 --rays 3000 --seed 5 --polar-bins 6 "
      "--azimuth-bins 4" +
      outputs.options());
  const auto rows = test::readCsv(outputs.csv);
  ASSERT_EQ(rows.size(), 1u + 6 * 4);
  const auto& header = rows[0];
  std::vector<std::string> columns = {"polar_lower_deg", "polar_upper_deg", "azimuth_lower_deg",
                                      "azimuth_upper_deg", "solid_angle_sr"};
  for (const char* quantity : {"per_sr", "brdf"})
    for (const char* part : {"surface", "subsurface", "total"})
      for (const char* suffix : {"", "_stderr"})
        columns.push_back(std::string(part) + "_" + quantity + suffix);
  ASSERT_EQ(header, columns);  // 17 documented columns, in order
  const std::size_t omega = test::columnOf(header, "solid_angle_sr"),
                    total = test::columnOf(header, "total_per_sr"),
                    surface = test::columnOf(header, "surface_per_sr");
  double reflectance = 0, surfaceReflectance = 0, solidAngle = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), header.size()) << "row " << r;
    reflectance += std::stod(rows[r][total]) * std::stod(rows[r][omega]);
    surfaceReflectance += std::stod(rows[r][surface]) * std::stod(rows[r][omega]);
    solidAngle += std::stod(rows[r][omega]);
  }
  EXPECT_NEAR(solidAngle, 2 * kPi, 1e-4);  // printed with 6 significant digits
  // The same walk through the library: the default spectral estimator (same seed, same stream).
  skin::WalkRunOptions run;
  run.incidenceDeg = 45;
  run.rays = 3000;
  run.seed = 5;
  const skin::SkinTally tally = test::spectralTally(test::specimenOptics("S1", 550), run);
  EXPECT_NEAR(reflectance, tally.reflectance().mean, 1e-5);
  EXPECT_NEAR(surfaceReflectance, tally.surfaceReflectance().mean, 1e-5);
  EXPECT_GT(std::filesystem::file_size(outputs.png), 1000u);
}

TEST(BrdfCommand, SameOutputAtAnyThreadCountAndVisibleHasEveryBin) {
  test::ScratchFolder scratch("brdf-threads-test");
  const auto one = scratch.path / "one.csv", two = scratch.path / "two.csv";
  const std::string common =
      "--wavelengths 400,700 --rays 2000 --polar-bins 3 --azimuth-bins 2 --out ";
  runBrdf(common + one.string() + " --threads 1");
  runBrdf(common + two.string() + " --threads 2");
  EXPECT_EQ(test::readBytes(one), test::readBytes(two));
  const auto visible = scratch.path / "visible.csv";
  runBrdf("--visible --rays 100 --polar-bins 2 --azimuth-bins 3 --out " + visible.string());
  EXPECT_EQ(test::readCsv(visible).size(), 1u + 2 * 3);
}

TEST(BrdfCommand, BadArgumentsAreClearErrors) {
  test::ScratchFolder scratch("brdf-bad-test");
  const auto csv = scratch.path / "bad.csv";
  test::expectThrowMentioning<std::invalid_argument>(
      [&] { runBrdf("--rays 10 --out " + csv.string()); }, "--visible");
  EXPECT_THROW(runBrdf("--visible --wavelengths 500 --out " + csv.string()), CLI::ExcludesError);
  EXPECT_THROW(runBrdf("--wavelengths 500 --polar-bins 0 --out " + csv.string()),
               CLI::ValidationError);
  EXPECT_THROW(runBrdf("--wavelengths 500 --angle 90 --out " + csv.string()), CLI::ValidationError);
  EXPECT_THROW(runBrdf("--wavelengths 500"), CLI::RequiredError);
  test::expectThrowMentioning([&] { runBrdf("--wavelengths 100 --rays 10 --out " + csv.string()); },
                              "100");
  EXPECT_FALSE(std::filesystem::exists(csv));
}

}  // namespace
}  // namespace hylios
