// hylios validate: every comparison the project has data for (paper Figs. 7–11), written
// as DIR/validation.md with PNG plots (app/validation_report.h). docs/validation.md is its output.
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/validation_report.h"
#include "skin/core/thread_limit.h"

namespace hylios {
namespace {

struct ValidateArguments {
  std::string out = "validation";
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  int threads = 0;
};

}  // namespace

void registerValidateCommand(CLI::App& app) {
  auto args = std::make_shared<ValidateArguments>();
  CLI::App* command = app.add_subcommand("validate",
                                         "Run every comparison with measured skin (Figs. 7-11); "
                                         "writes DIR/validation.md and PNG plots");
  command->add_option("--out", args->out, "Folder for validation.md and its plots")
      ->capture_default_str();
  addRaysOption(*command, args->rays,
                "Rays per wavelength (the visible BRDF uses a fifth per wavelength)", 100,
                std::uint64_t{1} << 36);
  addSeedOption(*command, args->seed,
                "Random seed in [0, 2^63-1] (same seed, same report at any thread count)");
  addThreadsOption(*command, args->threads);
  command->callback([args] {
    const ThreadLimit limit(args->threads);
    ValidationOptions options;
    options.outDir = args->out;
    options.rays = args->rays;
    options.seed = args->seed;
    runValidation(options);
    std::cout << "wrote " << (options.outDir / "validation.md").string() << "\n";
  });
}

}  // namespace hylios
