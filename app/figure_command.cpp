// hylios figure: several scene files → DIR/<scene stem>.exr with previews each, and
// DIR/contact_sheet.png with every preview (one row per scene, labelled "<stem>: <band>").
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "renderer/image/film_output.h"
#include "app/render_options.h"
#include "renderer/scene/scene_file.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

struct FigureArguments {
  std::vector<std::string> scenes;
  std::string out;
  RenderCommandOptions options;
};

void runFigure(const FigureArguments& args) {
  const RenderSettings settings = renderSettingsFromOptions(args.options);
  // Parse every scene first, so a typo in the last one fails before hours of rendering.
  std::vector<SceneDesc> scenes;
  for (const auto& file : args.scenes) scenes.push_back(applyRenderSettings(loadSceneFile(file), settings));
  fs::create_directories(args.out);
  std::vector<fs::path> panels;
  std::vector<std::string> labels;
  int columns = 1;
  for (const SceneDesc& scene : scenes) {
    const RenderResult result = renderScene(scene, settings, &std::cout);
    const std::string stem = scene.file.stem().string();
    const auto written = writeFilmOutputs(*result.film, fs::path(args.out) / (stem + ".exr"), renderAttributes(scene, result));
    int previews = 0;
    for (const auto& path : written) {
      std::cout << "wrote " << path.string() << "\n";
      if (path.extension() != ".png") continue;
      panels.push_back(path);
      const std::string band = path.stem().string().substr(std::min(path.stem().string().size(), stem.size() + 1));
      labels.push_back(stem + ": " + band);
      ++previews;
    }
    columns = std::max(columns, previews);
  }
  const fs::path sheet = fs::path(args.out) / "contact_sheet.png";
  // One row per scene with its previews side by side; scenes with a single preview each (the
  // paper's figures) make one row of panels, like the paper's.
  writeContactSheet(panels, labels, sheet, columns == 1 ? static_cast<int>(panels.size()) : columns);
  std::cout << "wrote " << sheet.string() << "\n";
}

}  // namespace

void registerFigureCommand(CLI::App& app) {
  auto args = std::make_shared<FigureArguments>();
  CLI::App* command = app.add_subcommand("figure", "Render several scenes into a folder with a contact sheet");
  command->add_option("scenes", args->scenes, "Scene files (TOML)")->required()->check(CLI::ExistingFile);
  command->add_option("--out", args->out, "Output folder")->required();
  addRenderCommandOptions(*command, args->options);
  command->callback([args] { runFigure(*args); });
}

}  // namespace hylios
