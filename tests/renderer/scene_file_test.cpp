// Scene files: a full scene parses to the values it says; every bad input is refused with a
// message naming file:line:col; every shipped scene (scenes/**.toml but specimens) parses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "renderer/scene/scene_file.h"

namespace hylios {
namespace {

const std::filesystem::path kSourceDir = HYLIOS_SOURCE_DIR;

/// A valid scene exercising every table; relative paths resolve against the source folder.
const std::string kFullScene = R"(# a comment
unit_cm = 5.0

[camera]
position = [0, 1, 10]
look_at = [0, 1, 0]
up = [0, 1, 0]
fov_deg = 30
aperture_radius = 0.1
focus_distance = 9.5

[film]
resolution = [320, 200]
spp = 32
exposure = 1.5

[[film.band]]
name = "uv365"
wavelength_nm = 365
preview_range = [0.0, 0.2]

[[film.band]]
name = "visible"
range_nm = [380, 780]
step_nm = 10

[[material]]
name = "skin"
type = "skin"
specimen = "S1"
overrides = { melanosome_percent = 7, "stratum_basale.thickness_cm" = 0.002, papillary_dermis.blood_percent = 1.0 }
freckles = { density_per_cm2 = 2.5, radius_cm = 0.2, melanin_gain = 4, seed = 9 }
melanin_map = { file = "assets/meshes/head/Map-COL.jpg", min_multiplier = 2.0, max_multiplier = 0.5 }
water_reduction_percent = 20

[[material]]
name = "paint"
type = "diffuse"
reflectance = { type = "tabulated", wavelengths_nm = [300, 800], values = [0.2, 0.8] }

[[material]]
name = "glass"
type = "dielectric"
refractive_index = 1.45
roughness = 0.1

[[shape]]
name = "head"
type = "mesh"
file = "assets/meshes/head/LeePerrySmith.obj"
material = "skin"
smooth_normals = false
transform = { translate = [1, 2, 3], rotate_deg = [90, 0, 0], scale = 2 }

[[shape]]
name = "ball"
type = "sphere"
material = "glass"
centre = [1, 0, -1]
radius = 0.5

[[shape]]
name = "lamp"
type = "plane"
material = "paint"
point = [0, 5, 0]
normal = [0, -2, 0]
size = 3

[[light]]
type = "area"
shape = "lamp"
emission = { type = "blackbody", temperature_k = 3000, scale = 4 }

[[light]]
type = "spot"
position = [0, 4, 4]
direction = [0, -1, -1]
outer_angle_deg = 30
inner_angle_deg = 20
emission = { type = "led", centre_nm = 365, fwhm_nm = 10 }

[[light]]
type = "point"
position = [2, 2, 2]
[light.emission]
type = "d65"
scale = 0.5

[[light]]
type = "environment"
emission = { type = "constant", scale = 0.1 }

[integrator]
max_depth = 12
seed = 42
skin_mode = "walk"
exit_control_variate = false
table_rays_per_bin = 40000
)";

SceneDesc parse(const std::string& text) { return parseSceneText(text, "scene.toml", kSourceDir); }

/// "<source>:line:col" of the first occurrence of `needle` in `text` at or after `from`.
std::string positionOf(const std::string& text, const std::string& needle, std::size_t from = 0,
                       const std::string& source = "bad.toml") {
  const auto at = text.find(needle, from);
  EXPECT_NE(at, std::string::npos) << needle;
  if (at == std::string::npos) return "";
  int line = 1;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < at; ++i)
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  return source + ":" + std::to_string(line) + ":" + std::to_string(at - lineStart + 1);
}

/// kFullScene with the first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = kFullScene;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string errorOf(const std::string& text, const std::filesystem::path& baseDir = kSourceDir) {
  try {
    parseSceneText(text, "bad.toml", baseDir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

/// Replaces `from` by `to` and expects "<position of `at`>: <message>", where `at` is looked for
/// from the start of the edited line (or, failing that, from the top).
void expectError(const std::string& from, const std::string& to, const std::string& at,
                 const std::string& message) {
  const std::string text = edited(from, to);
  const std::size_t editLine = text.rfind('\n', kFullScene.find(from)) + 1;
  const bool after = text.find(at, editLine) != std::string::npos;
  EXPECT_EQ(errorOf(text), positionOf(text, at, after ? editLine : 0) + ": " + message)
      << "edit: " << to;
}

TEST(SceneFile, FullSceneHasTheValuesItSays) {
  const SceneDesc s = parse(kFullScene);
  EXPECT_EQ(s.unitCm, 5.0);
  EXPECT_EQ(s.camera.position, glm::dvec3(0, 1, 10));
  EXPECT_EQ(s.camera.lookAt, glm::dvec3(0, 1, 0));
  EXPECT_EQ(s.camera.verticalFovDeg, 30);
  EXPECT_EQ(s.camera.apertureRadius, 0.1);
  EXPECT_EQ(s.camera.focusDistance, 9.5);
  EXPECT_EQ(s.camera.where.str(), "scene.toml:4:1");

  EXPECT_EQ(s.film.width, 320);
  EXPECT_EQ(s.film.height, 200);
  EXPECT_EQ(s.film.samplesPerPixel, 32);
  EXPECT_EQ(s.film.exposure, 1.5);
  ASSERT_EQ(s.film.bands.size(), 2u);
  EXPECT_EQ(s.film.bands[0].name, "uv365");
  EXPECT_FALSE(s.film.bands[0].isRange());
  EXPECT_EQ(s.film.bands[0].minNm, 365);
  EXPECT_EQ(s.film.bands[0].previewMax, 0.2);
  EXPECT_TRUE(s.film.bands[1].isRange());
  EXPECT_EQ(s.film.bands[1].channelWavelengths().size(), 41u);

  ASSERT_EQ(s.materials.size(), 3u);
  const SkinMaterialDesc& skin = s.materials[0].skin;
  EXPECT_EQ(s.materials[0].kind, MaterialDesc::Kind::Skin);
  EXPECT_EQ(skin.specimen, "S1");
  ASSERT_EQ(skin.overrides.size(), 3u);
  EXPECT_EQ(skin.overrides[0].key, "melanosome_percent");
  EXPECT_EQ(skin.overrides[0].value, 7);
  EXPECT_EQ(skin.overrides[0].origin,
            positionOf(kFullScene, "melanosome_percent = 7", 0, "scene.toml"));
  EXPECT_EQ(skin.overrides[1].key, "stratum_basale.thickness_cm");
  EXPECT_EQ(skin.overrides[2].key, "papillary_dermis.blood_percent");
  EXPECT_EQ(skin.freckles.densityPerCm2, 2.5);
  EXPECT_EQ(skin.freckles.radiusCm, 0.2);
  EXPECT_EQ(skin.freckles.melaninGain, 4);
  EXPECT_EQ(skin.freckles.seed, 9u);
  EXPECT_EQ(skin.melaninMap, kSourceDir / "assets/meshes/head/Map-COL.jpg");
  EXPECT_EQ(skin.melaninMapMin, 2.0);
  EXPECT_EQ(skin.melaninMapMax, 0.5);
  EXPECT_DOUBLE_EQ(skin.waterReduction, 0.2);
  EXPECT_EQ(s.materials[1].reflectance.kind, EmissionDesc::Kind::Tabulated);
  EXPECT_EQ(s.materials[1].reflectance.tableValue, (std::vector<double>{0.2, 0.8}));
  EXPECT_EQ(s.materials[2].refractiveIndex, 1.45);
  EXPECT_EQ(s.materials[2].roughness, 0.1);

  ASSERT_EQ(s.shapes.size(), 3u);
  EXPECT_EQ(s.shapes[0].meshPath, kSourceDir / "assets/meshes/head/LeePerrySmith.obj");
  EXPECT_FALSE(s.shapes[0].smoothNormals);
  // scale 2, then 90° about x, then translate: (0, 1, 0) → (0, 2, 0) → (0, 0, 2) → (1, 2, 5).
  const glm::dvec4 moved = s.shapes[0].transform * glm::dvec4(0, 1, 0, 1);
  EXPECT_NEAR(moved.x, 1, 1e-12);
  EXPECT_NEAR(moved.y, 2, 1e-12);
  EXPECT_NEAR(moved.z, 5, 1e-12);
  EXPECT_EQ(s.shapes[1].centre, glm::dvec3(1, 0, -1));
  EXPECT_EQ(s.shapes[1].radius, 0.5);
  EXPECT_EQ(s.shapes[2].planeNormal, glm::dvec3(0, -1, 0));
  EXPECT_EQ(s.shapes[2].planeSize, 3);

  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].kind, LightDesc::Kind::Area);
  EXPECT_EQ(s.lights[0].shape, "lamp");
  EXPECT_EQ(s.lights[0].emission.temperatureK, 3000);
  EXPECT_EQ(s.lights[0].emission.scale, 4);
  EXPECT_EQ(s.lights[1].kind, LightDesc::Kind::Spot);
  EXPECT_NEAR(s.lights[1].direction.y, -std::sqrt(0.5), 1e-12);
  EXPECT_EQ(s.lights[1].spotOuterDeg, 30);
  EXPECT_EQ(s.lights[1].spotInnerDeg, 20);
  EXPECT_EQ(s.lights[1].emission.centreNm, 365);
  EXPECT_EQ(s.lights[1].emission.fwhmNm, 10);
  EXPECT_EQ(s.lights[2].emission.kind, EmissionDesc::Kind::D65);
  EXPECT_EQ(s.lights[2].emission.scale, 0.5);
  EXPECT_EQ(s.lights[3].kind, LightDesc::Kind::Environment);

  EXPECT_EQ(s.integrator.maxDepth, 12);
  EXPECT_EQ(s.integrator.seed, 42u);
  EXPECT_FALSE(s.integrator.exitControlVariate);
  EXPECT_EQ(s.integrator.tableRaysPerBin, 40000u);
  EXPECT_TRUE(IntegratorDesc{}.exitControlVariate);  // the default
}

TEST(SceneFile, RotationsApplyAboutXThenYThenZ) {
  // (0, 1, 0) → 90° about x → (0, 0, 1) → 90° about y → (1, 0, 0); the other order gives (0, 0, 1).
  const SceneDesc s =
      parse(edited("rotate_deg = [90, 0, 0], scale = 2", "rotate_deg = [90, 90, 0]"));
  const glm::dvec4 moved = s.shapes[0].transform * glm::dvec4(0, 1, 0, 0);
  EXPECT_NEAR(moved.x, 1, 1e-12);
  EXPECT_NEAR(moved.y, 0, 1e-12);
  EXPECT_NEAR(moved.z, 0, 1e-12);
}

TEST(SceneFile, NonUniformScale) {
  const SceneDesc s = parse(edited("rotate_deg = [90, 0, 0], scale = 2", "scale = [1, 2, 3]"));
  const glm::dvec4 moved = s.shapes[0].transform * glm::dvec4(1, 1, 1, 0);
  EXPECT_EQ(moved, glm::dvec4(1, 2, 3, 0));
}

TEST(SceneFile, UnknownKey) {
  expectError("fov_deg = 30", "fov_degs = 30", "fov_degs",
              "unknown key 'fov_degs' in [camera] (known keys: position, look_at, up, fov_deg, "
              "aperture_radius, focus_distance)");
}

TEST(SceneFile, KeyUnusedByItsVariant) {
  expectError("centre = [1, 0, -1]", "file = \"x.obj\"", "file = \"x.obj\"",
              "key 'file' is not used by a \"sphere\" shape");
  expectError("step_nm = 10", "step_nm = 10\npreview_range = [0, 1]", "preview_range = [0, 1]",
              "key 'preview_range' is not used by a range band ('preview_range' is for "
              "single-wavelength bands)");
  expectError("type = \"constant\", scale = 0.1", "type = \"constant\", centre_nm = 500",
              "centre_nm", "key 'centre_nm' is not used by a \"constant\" spectrum");
}

TEST(SceneFile, EnvironmentCameraVisibility) {
  // Seen by the camera unless camera_visible = false; the key belongs to environment lights only.
  EXPECT_TRUE(parse(kFullScene).lights.back().cameraVisible);
  const std::string hidden = "type = \"constant\", scale = 0.1 }\ncamera_visible = false";
  EXPECT_FALSE(
      parse(edited("type = \"constant\", scale = 0.1 }", hidden)).lights.back().cameraVisible);
  expectError("outer_angle_deg = 30", "outer_angle_deg = 30\ncamera_visible = false",
              "camera_visible", "key 'camera_visible' is not used by a \"spot\" light");
  const std::string number = edited("type = \"constant\", scale = 0.1 }",
                                    "type = \"constant\", scale = 0.1 }\ncamera_visible = 0");
  EXPECT_EQ(errorOf(number), positionOf(number, "0", number.find("camera_visible")) +
                                 ": 'camera_visible' must be a boolean, got an integer");
}

TEST(SceneFile, TopLevelTableMisplaced) {
  expectError("[integrator]", "[integrators]", "integrators",
              "unknown key 'integrators' in the top level (known keys: unit_cm, camera, film, "
              "light, material, shape, integrator)");
}

TEST(SceneFile, MissingMeshFile) {
  const std::string text = edited("assets/meshes/head/LeePerrySmith.obj", "missing/head.obj");
  const std::string message = errorOf(text);
  EXPECT_EQ(message.rfind(positionOf(text, "\"missing/head.obj\"") +
                              ": 'file': file 'missing/head.obj' does not exist (looked for '",
                          0),
            0u)
      << message;
}

TEST(SceneFile, MissingTexture) {
  const std::string text = edited("Map-COL.jpg", "Map-NOPE.jpg");
  EXPECT_EQ(errorOf(text).rfind(positionOf(text, "\"assets/meshes/head/Map-NOPE.jpg\""), 0), 0u)
      << errorOf(text);
}

TEST(SceneFile, WrongType) {
  expectError("spp = 32", "spp = \"32\"", "\"32\"", "'spp' must be an integer, got a string");
  expectError("spp = 32", "spp = 32.5", "32.5",
              "'spp' must be an integer, got a floating-point number");
  expectError("fov_deg = 30", "fov_deg = true", "true",
              "'fov_deg' must be a number, got a boolean");
  expectError("position = [0, 1, 10]", "position = [0, 1]", "[0, 1]",
              "'position' must be an array of 3 numbers, got 2 element(s)");
  expectError("skin_mode = \"walk\"", "skin_mode = 3", "3",
              "'skin_mode' must be a string, got an integer");
  expectError("exit_control_variate = false", "exit_control_variate = 1", "1",
              "'exit_control_variate' must be a boolean, got an integer");
}

TEST(SceneFile, ArrayOfTablesWrittenAsTable) {
  const std::string text =
      "[camera]\nposition = [0, 0, 1]\nlook_at = [0, 0, 0]\n"
      "[film]\nresolution = [1, 1]\nspp = 1\n[[film.band]]\nname = \"a\"\nwavelength_nm = 500\n"
      "[light]\ntype = \"environment\"\nemission = { type = \"constant\" }\n";
  EXPECT_EQ(errorOf(text), positionOf(text, "[light]") +
                               ": 'light' must be an array of tables, written [[light]]");
}

TEST(SceneFile, WavelengthOutsideTheModel) {
  expectError("wavelength_nm = 365", "wavelength_nm = 200", "200",
              "'wavelength_nm' = 200 must be in [250, 2500]");
  expectError("range_nm = [380, 780]", "range_nm = [380, 2600]", "2600",
              "'range_nm'[1] = 2600 must be in [250, 2500]");
}

TEST(SceneFile, NegativeRadiusAndScale) {
  expectError("radius = 0.5", "radius = -1", "-1", "'radius' = -1 must be in (0, 10000000]");
  expectError("scale = 2 }", "scale = 0 }", "0 }", "'scale' = 0 must be in (0, 10000000]");
}

TEST(SceneFile, SamplesAndResolution) {
  expectError("spp = 32", "spp = 0", "0", "'spp' = 0 must be in [1, 1000000]");
  expectError("table_rays_per_bin = 40000", "table_rays_per_bin = 10", "10",
              "'table_rays_per_bin' = 10 must be in [1000, 10000000]");
  expectError("resolution = [320, 200]", "resolution = [320, 0]", "[320, 0]",
              "'resolution' = [320, 0]: each must be in [1, 16384]");
  expectError("resolution = [320, 200]", "resolution = [16384, 16384]", "[16384, 16384]",
              "'resolution' = [16384, 16384] is 268435456 pixels; at most 67108864 (64 Mpixel)");
}

TEST(SceneFile, NonFiniteNumbers) {
  expectError("fov_deg = 30", "fov_deg = nan", "nan", "'fov_deg' = nan is not finite");
  expectError("look_at = [0, 1, 0]", "look_at = [0, inf, 0]", "inf",
              "'look_at'[1] = inf is not finite");
  expectError("fov_deg = 30", "fov_deg = 180", "180", "'fov_deg' = 180 must be in (0, 180)");
}

TEST(SceneFile, UnknownNamesAndDuplicates) {
  expectError("material = \"glass\"", "material = \"glas\"", "\"glas\"",
              "unknown material 'glas' (materials: 'glass', 'paint', 'skin')");
  expectError("shape = \"lamp\"", "shape = \"lam\"", "\"lam\"",
              "unknown shape 'lam' (named shapes: 'ball', 'head', 'lamp')");
  expectError("name = \"glass\"", "name = \"paint\"", "\"paint\"\ntype = \"dielectric\"",
              "duplicate material name 'paint' (first defined at " +
                  positionOf(kFullScene, "\"paint\"") + ")");
  expectError(
      "name = \"visible\"", "name = \"uv365\"", "\"uv365\"\nrange",
      "duplicate band name 'uv365' (first defined at " + positionOf(kFullScene, "\"uv365\"") + ")");
}

TEST(SceneFile, BadOverrides) {
  expectError(
      "melanosome_percent = 7", "melanin_percent = 7",
      "melanin_percent", "unknown specimen override 'melanin_percent' (known: " + [] {
        std::string list;
        for (const auto& k : skin::overrideKeys()) list += (list.empty() ? "" : ", ") + k;
        return list;
      }() + ")");
  expectError("melanosome_percent = 7", "melanosome_percent = 150", "melanosome_percent",
              "melanosome_percent = 150 must be in [0, 100]");
  expectError("\"stratum_basale.thickness_cm\" = 0.002", "\"stratum_basale.thickness_cm\" = -0.002",
              "\"stratum_basale.thickness_cm\"",
              "stratum_basale.thickness_cm = -0.002 must be >= 0");
}

TEST(SceneFile, NegativeThicknessInASpecimenFile) {
  const std::filesystem::path dir =
      std::filesystem::path(HYLIOS_BINARY_DIR) / "scene_file_test_specimen";
  std::filesystem::create_directories(dir);
  std::ifstream in(kSourceDir / "scenes/specimens/S1.toml");
  std::stringstream s1;
  s1 << in.rdbuf();
  std::string specimen = s1.str();
  const std::string from = "thickness_cm = 0.0017";
  const std::size_t at = specimen.find(from);
  ASSERT_NE(at, std::string::npos);
  specimen.replace(at, from.size(), "thickness_cm = -0.0017");
  std::ofstream(dir / "thin.toml") << specimen;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += specimen[i] == '\n';
  const std::size_t lineStart = specimen.rfind('\n', at) + 1;

  const std::string path = (dir / "thin.toml").string();
  const std::string text = edited("specimen = \"S1\"", "specimen = \"" + path + "\"");
  const std::string message = errorOf(text);
  const std::string specimenPosition = (dir / "thin.toml").string() + ":" + std::to_string(line) +
                                       ":" + std::to_string(at - lineStart + 16);
  EXPECT_EQ(message, positionOf(text, "\"" + path) + ": specimen '" + (dir / "thin.toml").string() +
                         "': " + specimenPosition + ": 'thickness_cm' = -0.0017 must be >= 0");
}

TEST(SceneFile, SpectraMustCoverTheBands) {
  // The point light's D65 (300–830 nm) cannot light a 1650 nm band.
  const std::string text = edited("wavelength_nm = 365", "wavelength_nm = 1650");
  const std::string message = errorOf(text);
  const std::string start =
      positionOf(text, "[light.emission]") + ": D65 is not defined at 1650 nm";
  const std::string end = "(needed by band 'uv365')";
  EXPECT_EQ(message.rfind(start, 0), 0u) << message;
  ASSERT_GE(message.size(), end.size());
  EXPECT_EQ(message.substr(message.size() - end.size()), end) << message;
}

TEST(SceneFile, SyntaxErrorHasAPosition) {
  const std::string text = edited("spp = 32", "spp = = 32");
  EXPECT_EQ(errorOf(text).rfind(positionOf(text, "= 32"), 0), 0u) << errorOf(text);
  EXPECT_EQ(errorOf(text).rfind("bad.toml:", 0), 0u);
}

TEST(SceneFile, BandNeedsAWavelength) {
  expectError("wavelength_nm = 365\n", "", "[[film.band]]\nname = \"uv365\"",
              "a band needs 'wavelength_nm' (one wavelength) or 'range_nm' and 'step_nm'");
  expectError("step_nm = 10", "step_nm = 10\nwavelength_nm = 500", "[380, 780]",
              "a band has either 'wavelength_nm' (one wavelength) or 'range_nm' (a range), not "
              "both");
}

TEST(SceneFile, TabulatedSpectrumFromACsvFile) {
  const std::filesystem::path dir =
      std::filesystem::path(HYLIOS_BINARY_DIR) / "scene_file_test_csv";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "lamp.csv") << "wavelength_nm,warm,cool\n300,1.0,2.0\n800,3.0,4.0\n";
  const std::string path = (dir / "lamp.csv").string();
  const SceneDesc s =
      parse(edited("type = \"constant\", scale = 0.1",
                   "type = \"tabulated\", file = \"" + path + "\", column = \"cool\""));
  EXPECT_EQ(s.lights[3].emission.tableWavelengthNm, (std::vector<double>{300, 800}));
  EXPECT_EQ(s.lights[3].emission.tableValue, (std::vector<double>{2.0, 4.0}));
  expectError("type = \"constant\", scale = 0.1",
              "type = \"tabulated\", file = \"" + path + "\", column = \"hot\"", "\"hot\"",
              path + ": no column 'hot' (columns: warm, cool)");
  expectError("type = \"constant\", scale = 0.1", "type = \"tabulated\", file = \"" + path + "\"",
              "\"" + path, "'" + path + "' has 2 value columns; say which with 'column'");
}

TEST(SceneFile, ReflectanceMustStayBelowOne) {
  expectError("values = [0.2, 0.8]", "values = [0.2, 1.2]", "{ type = \"tabulated\"",
              "reflectance reaches 1.2 somewhere; it must stay within [0, 1]");
}

TEST(SceneFile, LoadSceneFileResolvesAgainstItsFolder) {
  const SceneDesc s = loadSceneFile(kSourceDir / "scenes/test/head_1650.toml");
  EXPECT_EQ(s.file, kSourceDir / "scenes/test/head_1650.toml");
  ASSERT_FALSE(s.shapes.empty());
  EXPECT_TRUE(std::filesystem::equivalent(s.shapes[0].meshPath,
                                          kSourceDir / "assets/meshes/head/LeePerrySmith.obj"));
  EXPECT_EQ(s.film.bands.at(0).minNm, 1650);
}

TEST(SceneFile, EveryShippedSceneParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kSourceDir / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    if (entry.path().parent_path().filename() == "specimens") continue;
    try {
      loadSceneFile(entry.path());
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++count;
  }
  EXPECT_GE(count, 17);
}

TEST(SceneFile, DocumentedExampleParses) {
  std::ifstream in(kSourceDir / "docs/scene-format.md");
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str();
  const std::string open = "```toml\n";
  const auto begin = text.find(open);
  ASSERT_NE(begin, std::string::npos);
  const auto end = text.find("```", begin + open.size());
  ASSERT_NE(end, std::string::npos);
  const SceneDesc s = parse(text.substr(begin + open.size(), end - begin - open.size()));
  EXPECT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.film.bands.size(), 2u);
}

TEST(SceneFile, FigureSeriesShareTheirPreviewScale) {
  const auto band = [](const std::string& name) {
    return loadSceneFile(kSourceDir / "scenes" / name).film.bands.at(0);
  };
  for (const std::string series : {"figure13_melanin", "figure14_water"}) {
    const std::vector<std::string> members = series == "figure13_melanin"
                                                 ? std::vector<std::string>{"1.5", "7", "30"}
                                                 : std::vector<std::string>{"0", "20", "40"};
    const BandDesc first = band(series + members[0] + ".toml");
    for (const auto& m : members) {
      const BandDesc b = band(series + m + ".toml");
      EXPECT_EQ(b.previewMin, first.previewMin) << series << m;
      EXPECT_EQ(b.previewMax, first.previewMax) << series << m;
    }
  }
  const SceneDesc dry = loadSceneFile(kSourceDir / "scenes/figure14_water40.toml");
  const auto& overrides = dry.materials.at(0).skin.overrides;
  ASSERT_EQ(overrides.size(), 2u);
  EXPECT_EQ(overrides[1].key, "water_reduction_percent");
  EXPECT_EQ(overrides[1].value, 40);
}

}  // namespace
}  // namespace hylios
