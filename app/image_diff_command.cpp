// hylios image-diff: how far a test image is from a reference image, per channel and overall
// (relative RMSE and relative bias, renderer/image/image_comparison.h) — for convergence studies
// and image regression checks.
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/option_checks.h"
#include "renderer/image/image_comparison.h"
#include "skin/core/atomic_file.h"

namespace hylios {
namespace {

struct ImageDiffArguments {
  std::string test;
  std::string reference;
  int blockSize = 1;
  std::string csv;
  bool noise = false;
};

/// --noise: the two images are two renders of one scene with different seeds.
void printNoise(const ImageDiffArguments& args) {
  const ExrImage a = readExrImage(args.test), b = readExrImage(args.reference);
  const std::vector<bool>& mask = !a.coverage.empty() ? a.coverage : b.coverage;
  std::cout << "noise of '" << args.test << "' and '" << args.reference
            << "' (two seeds: median over the pixels that see an object of |a - b|/sqrt(2)/mean"
            << (mask.empty() ? "; no coverage channel A: every pixel" : "") << ")\n"
            << formatNoise(measureNoise(noiseImageOf(a), noiseImageOf(b), mask));
}

void runImageDiff(const ImageDiffArguments& args) {
  checkOutputs({{"--csv", args.csv, true}}, {{"test", args.test}, {"reference", args.reference}});
  if (args.noise) return printNoise(args);
  const ImageComparison comparison = compareImageFiles(args.test, args.reference, args.blockSize);
  std::cout << "test '" << args.test << "' against reference '" << args.reference << "'\n"
            << formatComparisonTable(comparison);
  if (!args.csv.empty()) writeTextAtomically(args.csv, formatComparisonCsv(comparison));
}

}  // namespace

void registerImageDiffCommand(CLI::App& app) {
  auto args = std::make_shared<ImageDiffArguments>();
  CLI::App* command = app.add_subcommand("image-diff",
                                         "Compare an image with a reference of the same size and "
                                         "channels: per channel and overall (spectral "
                                         "channels pooled) relative RMSE = sqrt(mean((a-b)^2)) / "
                                         "mean(|b|) and mean relative difference = "
                                         "mean(a-b) / mean(|b|), b the reference");
  command->add_option("test", args->test, "Image to assess (OpenEXR)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("reference", args->reference, "Reference image (OpenEXR)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--block", args->blockSize,
                   "Compare means over NxN pixel blocks (default 1: pixels)")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--csv", args->csv,
                      "CSV file to write (one row per channel, then 'overall')");
  command->add_flag(
      "--noise", args->noise,
      "Instead: the per-pixel noise of two renders that differ only in the seed, per band, R, G, B "
      "and chromaticity (median over the pixels that see an object, channel A)");
  command->callback([args] { runImageDiff(*args); });
}

}  // namespace hylios
