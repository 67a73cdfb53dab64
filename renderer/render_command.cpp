// hylios render: one scene file → a spectral OpenEXR plus PNG previews (renderer/film_output.h).
#include <iostream>
#include <memory>

#include "renderer/commands.h"
#include "renderer/film_output.h"
#include "renderer/render_job.h"
#include "renderer/scene_file.h"

namespace hylios {
namespace {

struct RenderArguments {
  std::string scene;
  std::string out;
  RenderCommandOptions options;
  std::uint64_t seed = 0;
  bool seedGiven = false;
};

void runRender(const RenderArguments& args) {
  RenderSettings settings = renderSettingsFromOptions(args.options);
  if (args.seedGiven) settings.seed = args.seed;
  const SceneDesc scene = applyRenderSettings(loadSceneFile(args.scene), settings);
  const RenderResult result = renderScene(scene, settings, &std::cout);
  for (const auto& path : writeFilmOutputs(*result.film, args.out)) std::cout << "wrote " << path.string() << "\n";
}

}  // namespace

void registerRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArguments>();
  CLI::App* command = app.add_subcommand("render", "Render a scene file to a spectral OpenEXR and PNG previews");
  command->add_option("scene", args->scene, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
  command->add_option("--out", args->out, "OpenEXR file to write (previews go beside it)")->required();
  addRenderCommandOptions(*command, args->options);
  auto* seed = command->add_option("--seed", args->seed, "Random seed (default: the scene's)");
  command->callback([args, seed] {
    args->seedGiven = seed->count() > 0;
    runRender(*args);
  });
}

}  // namespace hylios
