// The project's spectral database for tests, loaded once from the source tree, and the folder of
// its specimen files (tests of hylios_skin cannot use renderer/scene/data_paths.h).
#pragma once
#include <filesystem>
#include <string>

#include "skin/spectral_database.h"

namespace hylios::test {

inline const skin::SpectralDatabase& spectra() {
  static const skin::SpectralDatabase database =
      skin::SpectralDatabase::load(std::string(HYLIOS_SOURCE_DIR) + "/assets/spectra");
  return database;
}

inline std::filesystem::path specimenDir() {
  return std::filesystem::path(HYLIOS_SOURCE_DIR) / "scenes" / "specimens";
}

}  // namespace hylios::test
