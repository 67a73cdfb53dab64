// hylios render: one scene file → a spectral OpenEXR plus PNG previews
// (renderer/image/film_output.h). SIGINT/SIGTERM stop the render after its current sample pass: the
// samples so far are written (EXR + previews, "hylios:spp" < "hylios:sppTarget") with a checkpoint
// <out>.hylios-state (renderer/image/render_checkpoint.h), and the command exits with 128 + signal;
// --resume continues the checkpoint to the image an uninterrupted render gives, and removes it.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <stdexcept>
#include <vector>

#include "app/commands.h"
#include "app/interrupt_signal.h"
#include "app/mpi_render.h"
#include "app/mpi_session.h"
#include "app/option_checks.h"
#include "app/render_options.h"
#include "renderer/image/film_output.h"
#include "renderer/image/render_checkpoint.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/render_memory.h"

namespace hylios {
namespace {

struct RenderArguments {
  std::string scene;
  std::string out;
  RenderCommandOptions options;
  std::uint64_t seed = 0;
  bool seedGiven = false;
  bool resume = false;
};

/// The given options of `command` that can change the image, canonical ("--name=value" in name
/// order), for checkpoints: every option except the scene path (its contents are hashed), --out,
/// --resume, --threads (the image does not depend on it), --explain, and --spp, --resolution and
/// --seed (compared by their effect, RenderIdentity).
std::string imageAffectingOptions(const CLI::App& command) {
  static const std::set<std::string> ignored = {"--help",    "--out", "--resume",     "--threads",
                                                "--explain", "--spp", "--resolution", "--seed"};
  std::vector<std::string> given;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || !option->nonpositional()) continue;
    const std::string name = option->get_lnames().empty() ? "-" + option->get_snames().front()
                                                          : "--" + option->get_lnames().front();
    if (ignored.count(name) > 0) continue;
    std::string text = name + "=";
    for (std::size_t i = 0; i < option->results().size(); ++i)
      text += (i ? "," : "") + option->results()[i];
    given.push_back(text);
  }
  std::sort(given.begin(), given.end());
  std::string joined;
  for (const std::string& text : given) joined += (joined.empty() ? "" : " ") + text;
  return joined;
}

/// The files a scene reads: itself, its meshes, melanin maps and specimen files.
std::vector<NamedPath> sceneInputs(const SceneDesc& scene) {
  std::vector<NamedPath> inputs = {{"scene", scene.file.string()}};
  for (const ShapeDesc& shape : scene.shapes)
    if (!shape.meshPath.empty()) inputs.push_back({"mesh", shape.meshPath.string()});
  for (const MaterialDesc& material : scene.materials) {
    if (material.kind != MaterialDesc::Kind::Skin) continue;
    if (!material.skin.melaninMap.empty())
      inputs.push_back({"melanin map", material.skin.melaninMap.string()});
    inputs.push_back(inputFile("specimen", material.skin.specimen));
  }
  return inputs;
}

void runRender(const RenderArguments& args, const CLI::App& command) {
  RenderSettings settings = renderSettingsFromOptions(args.options);
  if (args.seedGiven) settings.seed = args.seed;
  // Outputs first: a bad --out fails now, not after the render (issue 13, rows 6 and 7). Under
  // MPI rank 0 checks and every rank stops with its verdict (app/mpi_session.h).
  shareRootVerdict([&] { checkOutputs({{"--out", args.out}}, {{"scene", args.scene}}); });
  const SceneDesc scene = applyRenderSettings(loadSceneFile(args.scene), settings);
  const RenderIdentity identity = renderIdentity(scene, imageAffectingOptions(command));
  const std::filesystem::path checkpoint = checkpointPathFor(args.out);
  shareRootVerdict([&] {
    checkOutputs({{"--out", args.out}}, sceneInputs(scene));
    if (MpiSession::distributed() && args.resume)
      throw std::invalid_argument(
          "--resume continues a render of one process; run it without mpirun/srun");
    std::error_code noCheckpoint;
    if (!args.resume && std::filesystem::exists(checkpoint, noCheckpoint))
      throw std::runtime_error(
          "'" + checkpoint.string() + "' holds an interrupted render of '" + args.out +
          "'; continue it with the same command and --resume, or delete that file to start "
          "afresh (nothing was changed)");
  });
  if (args.resume)
    settings.resumeFrom =
        std::make_shared<const RenderCheckpoint>(readMatchingCheckpoint(checkpoint, identity));
  checkRenderMemory(scene);
  if (MpiSession::distributed()) {  // tiles divided among the ranks; SIGINT/SIGTERM end the job
    settings.division = renderDivisionAcrossRanks();
    const RenderResult result = renderScene(scene, settings, &std::cout);
    if (!MpiSession::isRoot()) return;
    for (const auto& path :
         writeFilmOutputs(*result.film, args.out, renderAttributes(scene, result)))
      std::cout << "wrote " << path.string() << "\n";
    return;
  }
  const InterruptSignalScope signals;
  settings.stopRequested = [&signals] { return signals.requested(); };
  const RenderResult result = renderScene(scene, settings, &std::cout);
  const std::vector<std::pair<std::string, std::string>> attributes =
      renderAttributes(scene, result);
  if (!result.stopped) {
    for (const auto& path : writeFilmOutputs(*result.film, args.out, attributes))
      std::cout << "wrote " << path.string() << "\n";
    std::error_code ignored;
    if (std::filesystem::remove(checkpoint, ignored))
      std::cout << "removed the checkpoint " << checkpoint.string() << "\n";
    return;
  }
  const int signal = signals.signalNumber();
  const int done = result.film->samplesPerPixelDone();
  if (done == result.samplesPerPixelAtStart) {
    std::cerr << "hylios: render interrupted by " << InterruptSignalScope::signalName(signal)
              << " before a sample pass completed; nothing written\n";
  } else {
    for (const auto& path : writeFilmOutputs(*result.film, args.out, attributes))
      std::cout << "wrote " << path.string() << "\n";
    // A device or FIFO --out (/dev/null) keeps nothing to resume from: no checkpoint beside it.
    std::error_code noStatus;
    const std::filesystem::file_status outStatus = std::filesystem::status(args.out, noStatus);
    if (std::filesystem::exists(outStatus) && !std::filesystem::is_regular_file(outStatus)) {
      std::cerr << "hylios: render interrupted by " << InterruptSignalScope::signalName(signal)
                << " at " << done << "/" << scene.film.samplesPerPixel
                << " spp; no checkpoint, since " << args.out << " is not a regular file\n";
    } else {
      writeRenderCheckpoint(checkpoint, identity, *result.film);
      std::cout << "wrote " << checkpoint.string() << "\n";
      std::cerr << "hylios: render interrupted by " << InterruptSignalScope::signalName(signal)
                << " at " << done << "/" << scene.film.samplesPerPixel << " spp; " << args.out
                << " holds the samples so far. Continue "
                << "with the same command and --resume.\n";
    }
  }
  std::cout << std::flush;
  throw CLI::RuntimeError(InterruptSignalScope::exitStatusFor(signal));
}

}  // namespace

void registerRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArguments>();
  CLI::App* command =
      app.add_subcommand("render", "Render a scene file to a spectral OpenEXR and PNG previews");
  command->add_option("scene", args->scene, "Scene file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", args->out, "OpenEXR file to write (previews go beside it)")
      ->required();
  addRenderCommandOptions(*command, args->options);
  auto* seed =
      command->add_option("--seed", args->seed, "Random seed in [0, 2^63-1] (default: the scene's)")
          ->check(seedRange());
  command->add_flag(
      "--resume", args->resume,
      "Continue the interrupted render whose checkpoint <out>.hylios-state lies beside --out "
      "(same scene and options)");
  command->callback([args, seed, command] {
    args->seedGiven = seed->count() > 0;
    runRender(*args, *command);
  });
}

}  // namespace hylios
