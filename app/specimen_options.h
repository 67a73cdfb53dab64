// The command-line options that choose a skin specimen: --specimen NAME|PATH and --set KEY=VALUE
// (repeatable overrides of the quantities scenes vary, see skin::overrideKeys()).
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "skin/specimen.h"

namespace hylios {

struct SpecimenOptions {
  std::string specimen = "S1";
  std::vector<std::string> overrides;  ///< "key=value"
};

/// Adds --specimen (default S1) and --set.
void addSpecimenOptions(CLI::App& command, SpecimenOptions& options);
/// Adds --set only (for a command with a --specimen of its own).
void addOverrideOption(CLI::App& command, SpecimenOptions& options);

/// Loads the specimen (by name from scenes/specimens/ or by path) and applies the overrides in
/// order. Throws skin::SpecimenError with the offending file position or "--set key=value".
skin::Specimen loadSpecimenWithOverrides(const SpecimenOptions& options);
/// Applies overrides "key=value" (as --set) in order. Throws skin::SpecimenError naming
/// "--set key=value".
void applyOverrides(skin::Specimen& specimen, const std::vector<std::string>& overrides);

}  // namespace hylios
