// The project's spectral database for tests, loaded once from the source tree, the folder of its
// specimen files (tests of hylios_skin cannot use renderer/scene/data_paths.h), and specimen S1's
// optics.
#pragma once
#include <filesystem>
#include <string>

#include "skin/skin_optics.h"
#include "skin/specimen.h"
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

/// Specimen S1's optics at one wavelength (the specimen loaded once).
inline skin::SkinOptics s1Optics(double wavelengthNm) {
  static const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  return skin::computeSkinOptics(specimen, spectra(), wavelengthNm);
}

}  // namespace hylios::test
