// The cases of `hylios sweep`: specimen overrides (the keys of --set, skin::overrideKeys()) from a
// grid of --vary NAME=LO:HI:STEP options or from a --cases file, checked against the specimen
// before any work. Errors name the option or file:line:col.
#pragma once
#include <string>
#include <vector>

#include "skin/specimen.h"

namespace hylios {

struct SweepCases {
  std::vector<std::string> keys;            ///< override keys, one column each
  std::vector<std::vector<double>> values;  ///< per case: one value per key
  std::vector<std::string> origins;         ///< per case: where it came from, for messages
};

/// The override key NAME stands for: a key of skin::overrideKeys(), or NAME + "_percent" when that
/// is one ("melanosome" -> "melanosome_percent"). Throws std::invalid_argument naming `origin`.
std::string sweepKey(const std::string& name, const std::string& origin);

/// LO, LO + STEP, ... up to HI inclusive (when on the grid, to 1e-9 of a step), each rounded to 12
/// significant digits. Throws std::invalid_argument for a malformed range, STEP <= 0, HI < LO or
/// more than maxValues values.
std::vector<double> parseSweepRange(const std::string& text, const std::string& origin,
                                    std::size_t maxValues);

/// The grid of --vary texts ("NAME=LO:HI:STEP"): every combination, the first --vary varying
/// slowest. At most maxCases cases.
SweepCases parseSweepGrid(const std::vector<std::string>& varyTexts, std::size_t maxCases);

/// A cases file: a CSV whose first line (after blank and '#' lines) names the keys and whose
/// other lines give one case each (numbers). `sourceName` is used in messages.
SweepCases parseSweepCasesText(const std::string& text, const std::string& sourceName,
                               std::size_t maxCases);
SweepCases loadSweepCasesFile(const std::string& path, std::size_t maxCases);

/// `base` with case `index`'s overrides applied (throws skin::SpecimenError naming the case).
skin::Specimen sweepSpecimen(const skin::Specimen& base, const SweepCases& cases,
                             std::size_t index);

}  // namespace hylios
