// Issue 13, "hostile use", the renderer's rows: scene values at extreme magnitudes are refused at
// parse time with file:line:col (no Embree abort), a far huge shape does not change the light
// near the origin, two bands at one wavelength are refused, errors say what is really wrong, and
// a stop request during the first sample pass is honoured inside the pass.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/scene/scene_file.h"
#include "renderer/tracing/integrator.h"
#include "renderer/tracing/render_memory.h"
#include "skin/core/constants.h"
#include "tests/support/test_scenes.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = HYLIOS_SOURCE_DIR;

std::string testScene() {
  std::ifstream in(kSource / "scenes/test/skin_sphere_550.toml");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The test scene with the first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = testScene();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The message of the SceneError `text` gives ("" when it parses).
std::string sceneError(const std::string& text) {
  try {
    parseSceneText(text, "bad.toml", kSource / "scenes/test");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneLimits, Row1HugeMagnitudesAreRefusedWithTheirPosition) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"position = [0.0, 0.0, 4.0]", "position = [0.0, 0.0, 1e20]"},
      {"fov_deg = 40.0", "fov_deg = 40.0\naperture_radius = 1e20"},
      {"unit_cm = 1.0 ", "unit_cm = 1e-24 "},
      {"radius = 1.0", "radius = 1e12"},
  };
  for (const auto& [from, to] : cases) {
    const std::string error = sceneError(edited(from, to));
    EXPECT_EQ(error.rfind("bad.toml:", 0), 0u) << to << ": " << error;
    EXPECT_NE(error.find("must be in"), std::string::npos) << to << ": " << error;
  }
  const std::string plane = sceneError(edited("[[light]]", R"([[shape]]
type = "plane"
material = "skin"
size = 1e25

[[light]])"));
  EXPECT_NE(plane.find("'size' = 1e+25 must be in"), std::string::npos) << plane;
}

TEST(SceneLimits, Row1RaysOutsideTheTracersRangeAreAnErrorNotAnAbort) {
  // A description made in code, past the parser's limits: the tracer refuses the ray.
  SceneDesc scene = parseSceneText(testScene(), "ok.toml", kSource / "scenes/test");
  scene.camera.position = {0, 0, 1e20};
  const Integrator integrator(scene, {550});
  skin::Rng rng(1);
  RenderStats stats;
  EXPECT_THROW(integrator.radiance({{0, 0, 1e20}, {0, 0, -1}}, 0, rng, stats), std::runtime_error);
}

TEST(SceneLimits, Row2AFarHugeSphereLeavesTheDirectLightNearTheOrigin) {
  // A point light over a diffuse plane (radiance exact, no noise), with and without a black
  // sphere of radius 1e6 two million units below.
  SceneDesc scene;
  scene.camera.position = {0, 0, 6};
  scene.film.width = scene.film.height = 8;
  scene.film.samplesPerPixel = 1;
  scene.film.bands = {test::singleWavelengthBand(550)};
  MaterialDesc paint;
  paint.kind = MaterialDesc::Kind::Diffuse;
  paint.name = "paint";
  paint.reflectance.kind = EmissionDesc::Kind::Constant;
  paint.reflectance.scale = 0.6;
  MaterialDesc black = paint;
  black.name = "black";
  black.reflectance.scale = 0;
  scene.materials = {paint, black};
  ShapeDesc plane;
  plane.kind = ShapeDesc::Kind::Plane;
  plane.material = "paint";
  plane.planeNormal = {0, 0, 1};
  plane.planeSize = 100;
  scene.shapes = {plane};
  LightDesc point;
  point.kind = LightDesc::Kind::Point;
  point.position = {1, 0, 2};
  point.emission.kind = EmissionDesc::Kind::Constant;
  point.emission.scale = 3;
  scene.lights = {point};
  scene.integrator.maxDepth = 1;
  const double expected = 0.6 / kPi * 3 * (2 / std::sqrt(5.0)) / 5;
  for (const bool farSphere : {false, true}) {
    SceneDesc withSphere = scene;
    if (farSphere) {
      ShapeDesc sphere;
      sphere.kind = ShapeDesc::Kind::Sphere;
      sphere.material = "black";
      sphere.radius = 1e6;
      sphere.centre = {0, 0, -2e6};
      withSphere.shapes.push_back(sphere);
    }
    const Integrator integrator(withSphere, {550});
    skin::Rng rng(1);
    RenderStats stats;
    EXPECT_NEAR(integrator.radiance({{0, 0, 5}, {0, 0, -1}}, 0, rng, stats), expected,
                1e-6 * expected)
        << (farSphere ? "with" : "without") << " the far sphere";
  }
}

TEST(SceneLimits, Row8AStopRequestDuringTheFirstPassIsHonouredInsideIt) {
  SceneDesc scene = parseSceneText(testScene(), "ok.toml", kSource / "scenes/test");
  scene.film.width = scene.film.height = 64;  // 16 tiles
  scene.film.samplesPerPixel = 4;
  Film film(scene.film);
  const Integrator integrator(scene, {550});
  RenderOptions options = quietRenderOptions("stop");
  std::atomic<int> calls{0};
  options.stopRequested = [&calls] {
    return ++calls > 1;
  };  // the signal arrives once the pass has begun
  integrator.render(film, options);
  EXPECT_EQ(film.samplesPerPixelDone(), 0);  // abandoned: nothing of the pass counts (before: 1)
}

TEST(SceneLimits, Row8MemoryEstimateCoversTheFilm) {
  SceneDesc scene = parseSceneText(testScene(), "ok.toml", kSource / "scenes/test");
  scene.film.width = scene.film.height = 8192;
  BandDesc visible;
  visible.name = "visible";
  visible.minNm = 380;
  visible.maxNm = 780;
  visible.stepNm = 10;
  scene.film.bands = {visible};
  // 67 Mpixel × 41 channels: far beyond a 6 GB machine.
  EXPECT_GT(estimateRenderBytes(scene), std::uint64_t{60} << 30);
}

TEST(SceneLimits, Row9TwoChannelsAtOneWavelengthAreRefusedNamingBothBands) {
  const std::string second = R"([[film.band]]
name = "again"
)";
  for (const std::string& band :
       {second + "wavelength_nm = 550\n", second + "wavelength_nm = 550.0000001\n",
        second + "range_nm = [500, 600]\nstep_nm = 50\n"}) {
    const std::string error = sceneError(edited("[[material]]", band + "\n[[material]]"));
    EXPECT_NE(error.find("band 'again'"), std::string::npos) << band << error;
    EXPECT_NE(error.find("band 'nm550'"), std::string::npos) << band << error;
  }
  EXPECT_EQ(sceneError(edited("[[material]]", second + "wavelength_nm = 550.01\n\n[[material]]")),
            "");
}

TEST(SceneLimits, Row11ErrorsSayWhatIsReallyWrong) {
  const std::string camera =
      sceneError(edited("position = [0.0, 0.0, 4.0]", "position = [2.5, 1.8, 1e300]"));
  EXPECT_NE(camera.find("'position'[2]"), std::string::npos) << camera;
  EXPECT_EQ(camera.find("'up'"), std::string::npos) << camera;
  const std::string mesh =
      sceneError(edited("type = \"sphere\"", "type = \"mesh\"\nfile = \"../specimens\""));
  EXPECT_NE(mesh.find("is a folder"), std::string::npos) << mesh;
}

}  // namespace
}  // namespace hylios

namespace hylios {
namespace {

// The same class found beyond the rows: spectra and skin extras at extreme magnitudes were
// accepted and gave inf/NaN radiance (found only when the EXR refused the film, after the render)
// or an endless freckle field.
TEST(SceneLimits, SpectraAndSkinExtrasAtExtremeMagnitudesAreRefused) {
  const std::string env = "emission = { type = \"constant\", scale = 1.0 }";
  const std::vector<std::string> emissions = {
      "emission = { type = \"constant\", scale = 1e300 }",
      "emission = { type = \"blackbody\", temperature_k = 1e-300 }",
      "emission = { type = \"blackbody\", temperature_k = 1e300 }",
      "emission = { type = \"led\", centre_nm = 550, fwhm_nm = 1e-300 }",
      "emission = { type = \"tabulated\", wavelengths_nm = [300, 800], values = [1e300, 1] }",
  };
  for (const std::string& emission : emissions) {
    const std::string error = sceneError(edited(env, emission));
    EXPECT_NE(error.find("must be in"), std::string::npos) << emission << ": " << error;
  }
  const std::vector<std::pair<std::string, std::string>> extras = {
      {"spp = 4", "spp = 4\nexposure = 1e300"},
      {"specimen = \"S1\"", "specimen = \"S1\"\nfreckles = { density_per_cm2 = 1e300 }"},
      {"specimen = \"S1\"",
       "specimen = \"S1\"\nfreckles = { density_per_cm2 = 1, radius_cm = 1e-300 }"},
      {"specimen = \"S1\"",
       "specimen = \"S1\"\nfreckles = { density_per_cm2 = 1, melanin_gain = 1e300 }"},
  };
  for (const auto& [from, to] : extras) {
    const std::string error = sceneError(edited(from, to));
    EXPECT_NE(error.find("must be in"), std::string::npos) << to << ": " << error;
  }
}

}  // namespace
}  // namespace hylios
