// Where hylios finds its data: $HYLIOS_DATA_DIR if set, else the source tree it was built from.
#pragma once
#include <filesystem>

namespace hylios {

/// Root holding assets/ and scenes/. Throws std::runtime_error naming the folder if it is missing.
std::filesystem::path dataRoot();
inline std::filesystem::path spectraDir() { return dataRoot() / "assets" / "spectra"; }
inline std::filesystem::path specimenDir() { return dataRoot() / "scenes" / "specimens"; }

}  // namespace hylios
