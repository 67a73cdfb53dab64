// The render/figure options shared by both commands (app/render_options.h): --sampler reaches the
// plain RenderSettings and the scene, and a wrong name is refused with parseEnum's message.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/render_options.h"

using namespace hylios;

namespace {

/// Parses `arguments` with the shared render options; returns the settings.
RenderSettings parse(std::vector<std::string> arguments) {
  CLI::App app;
  RenderCommandOptions options;
  addRenderCommandOptions(app, options);
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
  app.parse(arguments);
  return renderSettingsFromOptions(options);
}

}  // namespace

TEST(RenderOptions, SamplerOptionSetsTheSettingAndTheScene) {
  EXPECT_FALSE(parse({}).sampler.has_value());
  const RenderSettings sobol = parse({"--sampler", "sobol"});
  ASSERT_TRUE(sobol.sampler.has_value());
  EXPECT_EQ(*sobol.sampler, SamplerKind::Sobol);
  EXPECT_EQ(applyRenderSettings(SceneDesc{}, sobol).integrator.sampler, SamplerKind::Sobol);
  EXPECT_EQ(
      applyRenderSettings(SceneDesc{}, parse({"--sampler", "independent"})).integrator.sampler,
      SamplerKind::Independent);
  EXPECT_EQ(SceneDesc{}.integrator.sampler, SamplerKind::Sobol);  // the default
  SceneDesc scene;
  scene.integrator.sampler = SamplerKind::Independent;  // the scene's choice stands without it
  EXPECT_EQ(applyRenderSettings(scene, parse({})).integrator.sampler, SamplerKind::Independent);
}

TEST(RenderOptions, UnknownSamplerIsRefusedWithTheChoices) {
  try {
    parse({"--sampler", "halton"});
    FAIL() << "accepted --sampler halton";
  } catch (const CLI::ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("\"independent\" or \"sobol\""), std::string::npos) << what;
    EXPECT_NE(what.find("halton"), std::string::npos) << what;
  }
}
