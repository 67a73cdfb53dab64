// hylios figure: several scene files → DIR/<scene stem>.exr with previews each, and
// DIR/contact_sheet.png with every preview, ordered by what varies between the scenes and
// captioned with it (app/figure_job.h, app/figure_layout.h).
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/figure_job.h"
#include "app/render_options.h"

namespace hylios {
namespace {

struct FigureArguments {
  std::vector<std::string> scenes;
  std::string out;
  RenderCommandOptions options;
};

}  // namespace

void registerFigureCommand(CLI::App& app) {
  auto args = std::make_shared<FigureArguments>();
  CLI::App* command = app.add_subcommand(
      "figure",
      "Render several scenes into a folder with a contact sheet: panels ordered by what varies "
      "between the scenes (band, specimen overrides, water, freckles), captioned with its value");
  command->add_option("scenes", args->scenes, "Scene files (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", args->out, "Output folder")->required();
  addRenderCommandOptions(*command, args->options);
  command->callback([args] {
    renderFigure(args->scenes, args->out, renderSettingsFromOptions(args->options), &std::cout);
  });
}

}  // namespace hylios
