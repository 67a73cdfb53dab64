// app/figure_layout.h: the panel order and captions of a contact sheet come from what varies
// between the scenes, never from file names (issue 17). Only parsing, no rendering.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/figure_layout.h"
#include "renderer/scene/scene_file.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(HYLIOS_SOURCE_DIR) / "scenes";

std::vector<SceneDesc> load(const std::vector<std::string>& names) {
  std::vector<SceneDesc> scenes;
  for (const auto& n : names) scenes.push_back(loadSceneFile(kScenes / n));
  return scenes;
}

std::vector<std::string> stemsInOrder(const std::vector<SceneDesc>& scenes,
                                      const FigureLayout& layout) {
  std::vector<std::string> stems;
  for (const std::size_t i : layout.order) stems.push_back(scenes[i].file.stem().string());
  return stems;
}

/// The layout of the paper figure's scene files, given in `files` order, against what it should be.
struct PaperFigure {
  std::vector<std::string> files;     ///< in the order a user (or the shell) gives them
  std::vector<std::string> stems;     ///< the panels' scenes, left to right
  std::vector<std::string> captions;  ///< the panels' captions, left to right
  std::string title;
};

FigureLayout expectLayout(const PaperFigure& figure) {
  const auto scenes = load(figure.files);
  const FigureLayout layout = layoutFigure(scenes);
  EXPECT_EQ(stemsInOrder(scenes, layout), figure.stems);
  EXPECT_EQ(layout.captions, figure.captions);
  EXPECT_EQ(layout.title, figure.title);
  return layout;
}

TEST(FigureLayout, Figure13OrdersByMelaninNotByFileName) {
  // The shell's order of figure13_*.toml: 1.5, 30, 7.
  const FigureLayout layout = expectLayout(
      {{"figure13_melanin1.5.toml", "figure13_melanin30.toml", "figure13_melanin7.toml"},
       {"figure13_melanin1.5", "figure13_melanin7", "figure13_melanin30"},
       {"epidermal melanin 1.5 %", "epidermal melanin 7 %", "epidermal melanin 30 %"},
       "365 nm · specimen S1"});
  EXPECT_FALSE(layout.bandInCaptions);
}

TEST(FigureLayout, Figure14OrdersByDehydrationAndSharesTheMelanin) {
  expectLayout({{"figure14_water40.toml", "figure14_water0.toml", "figure14_water20.toml"},
                {"figure14_water0", "figure14_water20", "figure14_water40"},
                {"no water reduction", "water −20 %", "water −40 %"},
                "1650 nm · specimen S1 · epidermal melanin 1.5 %"});
}

TEST(FigureLayout, Figure1OrdersByWavelength) {
  const FigureLayout layout =
      expectLayout({{"figure01_ir1100.toml", "figure01_visible.toml", "figure01_uv365.toml"},
                    {"figure01_uv365", "figure01_visible", "figure01_ir1100"},
                    {"365 nm", "visible 380–780 nm", "1100 nm"},
                    "specimen S1 · freckles 1 /cm²"});
  EXPECT_TRUE(layout.bandInCaptions);
}

/// A one-sphere scene with a skin material; `material` is extra text for its [[material]].
SceneDesc sphereScene(const std::string& band, const std::string& material,
                      const std::string& name) {
  const std::string text =
      "[camera]\nposition = [0, 0, 4]\nlook_at = [0, 0, 0]\n"
      "[film]\nresolution = [8, 8]\nspp = 1\n[[film.band]]\n" +
      band + "\n[[material]]\nname = \"skin\"\ntype = \"skin\"\nspecimen = \"S1\"\n" + material +
      "\n[[shape]]\ntype = \"sphere\"\nmaterial = \"skin\"\nradius = 1\n"
      "[[light]]\ntype = \"environment\"\nemission = { type = \"constant\" }\n";
  SceneDesc scene = parseSceneText(text, name + ".toml", kScenes);
  scene.file = name + ".toml";
  return scene;
}

TEST(FigureLayout, AMissingOverrideReadsAsTheSpecimensAndComesFirst) {
  const std::string band = "name = \"uv\"\nwavelength_nm = 365";
  const std::vector<SceneDesc> scenes = {
      sphereScene(band, "overrides = { melanosome_percent = 3 }", "c"), sphereScene(band, "", "a"),
      sphereScene(band, "overrides = { melanosome_percent = 2 }", "b")};
  const FigureLayout layout = layoutFigure(scenes);
  EXPECT_EQ(layout.order, (std::vector<std::size_t>{1, 2, 0}));
  EXPECT_EQ(layout.captions,
            (std::vector<std::string>{"epidermal melanin as S1", "epidermal melanin 2 %",
                                      "epidermal melanin 3 %"}));
}

TEST(FigureLayout, WaterFromTheOverrideAndTheMaterialCombined) {
  const std::string band = "name = \"ir\"\nwavelength_nm = 1650";
  const std::vector<SceneDesc> scenes = {
      sphereScene(band,
                  "overrides = { water_reduction_percent = 20 }\nwater_reduction_percent = 50",
                  "both"),
      sphereScene(band, "water_reduction_percent = 10", "material")};
  const FigureLayout layout = layoutFigure(scenes);
  // 1 − (1 − 0.2)(1 − 0.5) = 60 %.
  EXPECT_EQ(layout.captions, (std::vector<std::string>{"water −10 %", "water −60 %"}));
  EXPECT_EQ(layout.order, (std::vector<std::size_t>{1, 0}));
}

TEST(FigureLayout, IdenticalScenesFallBackToTheirStemsAndKeepTheirOrder) {
  const std::string band = "name = \"uv\"\nwavelength_nm = 365";
  const std::vector<SceneDesc> scenes = {sphereScene(band, "", "second"),
                                         sphereScene(band, "", "first")};
  const FigureLayout layout = layoutFigure(scenes);
  EXPECT_EQ(layout.order, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(layout.captions, (std::vector<std::string>{"second", "first"}));
  // One scene alone: its caption is empty (the figure job shows its band).
  EXPECT_EQ(layoutFigure({scenes[0]}).captions, std::vector<std::string>{""});
  EXPECT_THROW(layoutFigure({}), std::invalid_argument);
}

TEST(FigureLayout, SeveralBandsPerSceneNameTheBandPerPanel) {
  const std::string bands =
      "name = \"uv\"\nwavelength_nm = 365\n[[film.band]]\nname = \"ir\"\n"
      "wavelength_nm = 1100";
  const std::vector<SceneDesc> scenes = {
      sphereScene(bands, "overrides = { blood_percent = 4 }", "x"),
      sphereScene(bands, "overrides = { blood_percent = 1 }", "y")};
  const FigureLayout layout = layoutFigure(scenes);
  EXPECT_TRUE(layout.bandInCaptions);
  EXPECT_EQ(layout.order, (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(layout.captions, (std::vector<std::string>{"dermal blood 1 %", "dermal blood 4 %"}));
  EXPECT_EQ(layout.title, "specimen S1");
}

TEST(FigureLayout, OverrideTexts) {
  EXPECT_EQ(overrideText("melanosome_percent", 7), "epidermal melanin 7 %");
  EXPECT_EQ(overrideText("water_reduction_percent", 20), "water −20 %");
  EXPECT_EQ(overrideText("water_reduction_percent", 0), "no water reduction");
  EXPECT_EQ(overrideText("stratum_basale.thickness_cm", 0.002),
            "stratum basale thickness 0.002 cm");
  EXPECT_EQ(overrideText("surface_fold_aspect_ratio", 0.25), "surface fold aspect ratio 0.25");
  EXPECT_EQ(overrideText("something_new", 1.5), "something_new = 1.5");
}

}  // namespace
}  // namespace hylios
