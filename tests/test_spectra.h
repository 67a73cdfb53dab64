// The project's spectral database for tests, loaded once from the source tree.
#pragma once
#include <string>

#include "skin/spectral_database.h"

namespace hylios::test {

inline const skin::SpectralDatabase& spectra() {
  static const skin::SpectralDatabase database =
      skin::SpectralDatabase::load(std::string(HYLIOS_SOURCE_DIR) + "/assets/spectra");
  return database;
}

}  // namespace hylios::test
