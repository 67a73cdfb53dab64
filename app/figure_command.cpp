// hylios figure: several scene files → DIR/<scene stem>.exr with previews each, and
// DIR/contact_sheet.png with every preview (one row per scene, labelled "<stem>: <band>").
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include "app/commands.h"
#include "app/option_checks.h"
#include "app/render_options.h"
#include "renderer/image/film_output.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/render_memory.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

struct FigureArguments {
  std::vector<std::string> scenes;
  std::string out;
  RenderCommandOptions options;
};

/// The output folder must be a folder we can write in (made if missing); checked before any work.
void checkOutputFolder(const std::string& out) {
  if (out.empty()) throw std::invalid_argument("--out '': empty path; give an output folder");
  std::error_code error;
  if (fs::exists(out, error) && !fs::is_directory(out, error))
    throw std::invalid_argument("--out '" + out + "': exists and is not a folder");
  fs::create_directories(out, error);
  if (error)
    throw std::invalid_argument("--out '" + out +
                                "': cannot create the folder: " + error.message());
  checkWritableOutput({"--out", (fs::path(out) / "contact_sheet.png").string()});
}

void runFigure(const FigureArguments& args) {
  const RenderSettings settings = renderSettingsFromOptions(args.options);
  // Two scenes with one stem would write one DIR/<stem>.exr (the second over the first).
  std::map<std::string, std::string> stems;
  for (const auto& file : args.scenes) {
    const std::string stem = fs::path(file).stem().string();
    if (const auto [it, inserted] = stems.emplace(stem, file); !inserted)
      throw std::invalid_argument(
          "scenes '" + it->second + "' and '" + file + "' would both be written to '" +
          (fs::path(args.out) / (stem + ".exr")).string() + "'; rename one of them");
  }
  // Parse every scene first, so a typo in the last one fails before hours of rendering.
  std::vector<SceneDesc> scenes;
  for (const auto& file : args.scenes)
    scenes.push_back(applyRenderSettings(loadSceneFile(file), settings));
  checkOutputFolder(args.out);
  std::vector<NamedPath> inputs, outputs;
  for (const auto& file : args.scenes) inputs.push_back({"scene", file});
  for (const auto& [stem, file] : stems)
    outputs.push_back({"--out", (fs::path(args.out) / (stem + ".exr")).string()});
  checkOutputs(outputs, inputs);
  for (const SceneDesc& scene : scenes) checkRenderMemory(scene);
  std::vector<fs::path> panels;
  std::vector<std::string> labels;
  int columns = 1;
  for (const SceneDesc& scene : scenes) {
    const RenderResult result = renderScene(scene, settings, &std::cout);
    const std::string stem = scene.file.stem().string();
    const auto written = writeFilmOutputs(*result.film, fs::path(args.out) / (stem + ".exr"),
                                          renderAttributes(scene, result));
    int previews = 0;
    for (const auto& path : written) {
      std::cout << "wrote " << path.string() << "\n";
      if (path.extension() != ".png") continue;
      panels.push_back(path);
      const std::string band =
          path.stem().string().substr(std::min(path.stem().string().size(), stem.size() + 1));
      labels.push_back(stem + ": " + band);
      ++previews;
    }
    columns = std::max(columns, previews);
  }
  const fs::path sheet = fs::path(args.out) / "contact_sheet.png";
  // One row per scene with its previews side by side; scenes with a single preview each (the
  // paper's figures) make one row of panels, like the paper's.
  writeContactSheet(panels, labels, sheet,
                    columns == 1 ? static_cast<int>(panels.size()) : columns);
  std::cout << "wrote " << sheet.string() << "\n";
}

}  // namespace

void registerFigureCommand(CLI::App& app) {
  auto args = std::make_shared<FigureArguments>();
  CLI::App* command =
      app.add_subcommand("figure", "Render several scenes into a folder with a contact sheet");
  command->add_option("scenes", args->scenes, "Scene files (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", args->out, "Output folder")->required();
  addRenderCommandOptions(*command, args->options);
  command->callback([args] { runFigure(*args); });
}

}  // namespace hylios
