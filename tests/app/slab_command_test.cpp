// `hylios slab` run in-process: the CSV's columns and values equal a direct simulateLayeredSlab.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "skin/layered_slab.h"

namespace hylios {
namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

void runCommand(std::vector<std::string> args) {
  CLI::App app;
  registerSlabCommand(app);
  std::vector<const char*> argv{"hylios"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

TEST(SlabCommandTest, WritesOneRowMatchingTheLibrary) {
  const std::filesystem::path out =
      std::filesystem::path(HYLIOS_BINARY_DIR) / "slab_command_test_out.csv";
  runCommand({"slab", "--above", "1.0", "--below", "1.0", "--layer",
              "n=1.37,mua=1,mus=100,g=0.9,d=0.1", "--layer", "n=1.4,mua=2,mus=10,g=0.7,d=inf",
              "--rays", "5000", "--angle", "30", "--seed", "9", "--threads", "2", "--out",
              out.string()});
  std::ifstream in(out);
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(in, header));
  ASSERT_TRUE(std::getline(in, row));
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header,
            "specular_reflectance,diffuse_reflectance,diffuse_reflectance_stderr,transmittance,"
            "transmittance_stderr,unscattered_transmittance,absorptance,absorptance_stderr,"
            "absorptance_layer1,absorptance_layer1_stderr,absorptance_layer2,"
            "absorptance_layer2_stderr,event_limited");
  const std::vector<std::string> fields = splitCsvLine(row);
  ASSERT_EQ(fields.size(), 13u);

  skin::SlabProblem problem;
  problem.layers = {{1.37, 1, 100, 0.9, 0.1},
                    {1.4, 2, 10, 0.7, std::numeric_limits<double>::infinity()}};
  problem.incidenceAngleDeg = 30;
  skin::SlabRunOptions options;
  options.photons = 5000;
  options.seed = 9;
  options.scheme = skin::AbsorptionScheme::WeightWithRoulette;  // the command's default
  const skin::SlabResult r = skin::simulateLayeredSlab(problem, options);
  const double expected[] = {r.specularReflectance,
                             r.diffuseReflectance.mean,
                             r.diffuseReflectance.standardError,
                             r.transmittance.mean,
                             r.transmittance.standardError,
                             r.unscatteredTransmittance.mean,
                             r.absorptance.mean,
                             r.absorptance.standardError,
                             r.layerAbsorptance[0].mean,
                             r.layerAbsorptance[0].standardError,
                             r.layerAbsorptance[1].mean,
                             r.layerAbsorptance[1].standardError,
                             r.eventLimited.mean};
  for (std::size_t i = 0; i < fields.size(); ++i)  // printed with 9 significant digits
    EXPECT_NEAR(std::stod(fields[i]), expected[i], 1e-8 * std::fabs(expected[i]) + 1e-15) << i;
  EXPECT_EQ(r.transmittance.mean, 0.0);  // semi-infinite bottom
  EXPECT_EQ(r.eventLimited.mean, 0.0);
  std::filesystem::remove(out);
}

TEST(SlabCommandTest, WarnsWhenPacketsReachTheEventBound) {
  // 10^6 optical depths that only scatter: some of 2000 packets reach 2^20 events (seed 3: 3).
  const std::filesystem::path out =
      std::filesystem::path(HYLIOS_BINARY_DIR) / "slab_command_test_deep.csv";
  testing::internal::CaptureStderr();
  runCommand({"slab", "--layer", "n=1,mua=0,mus=1e6,g=0,d=1", "--rays", "2000", "--seed", "3",
              "--out", out.string()});
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("still travelling after 1048576 events"), std::string::npos) << warning;
  EXPECT_NE(warning.find("event_limited, not in Rd, Tt or A"), std::string::npos) << warning;
  std::ifstream in(out);
  std::string header, row;
  ASSERT_TRUE(std::getline(in, header));
  ASSERT_TRUE(std::getline(in, row));
  EXPECT_EQ(splitCsvLine(row).back(), "0.0015");
  std::filesystem::remove(out);
}

TEST(SlabCommandTest, BadLayerIsAnErrorAndWritesNothing) {
  const std::filesystem::path out =
      std::filesystem::path(HYLIOS_BINARY_DIR) / "slab_command_test_bad.csv";
  std::filesystem::remove(out);
  try {
    runCommand(
        {"slab", "--layer", "n=1.37,mua=1,mus=100,g=0.9,thickness=2", "--out", out.string()});
    FAIL() << "accepted a bad --layer";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'thickness'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_THROW(runCommand({"slab", "--layer", "n=1,mua=1,mus=1,g=0,d=1", "--rays", "0", "--out",
                           out.string()}),
               CLI::ValidationError);
  EXPECT_THROW(runCommand({"slab", "--out", out.string()}), CLI::RequiredError);
}

}  // namespace
}  // namespace hylios
