// The declared extensions of the absorber tables (assets/spectra/extensions.toml): the model's
// wavelength domain, the melanin power-law fit ranges, the hemoglobin tail above 1000 nm, the
// lipid and carotenoid settings, and the band models of keratin, DNA and urocanic acid.
// Every key is required and unknown keys are errors (file:line:column).
#pragma once
#include <filesystem>
#include <string>

#include "skin/absorption_band.h"

namespace hylios::skin {

struct SpectralExtensions {
  double domainMinNm = 0;
  double domainMaxNm = 0;

  double eumelaninFitMinNm = 0;
  double pheomelaninFitMinNm = 0;

  double prahlHemoglobinMolarMass = 0;     ///< g/mol per tetramer
  double zijlstraHemoglobinMolarMass = 0;  ///< g/mol per tetramer
  double hemoglobinFloorMinNm = 0;
  double hemoglobinFloorMaxNm = 0;
  double bloodWaterVolumeFraction = 0;
  double bloodHemoglobinMgPerMl = 0;
  double hemoglobinDecayLengthNm = 0;

  double cornOilFirstValidNm = 0;

  double bilirubinMolarMass = 0;  ///< g/mol
  double bilirubinZeroFromNm = 0;
  double betaCaroteneMolarMass = 0;  ///< g/mol
  double betaCaroteneZeroFromNm = 0;

  AbsorptionBand keratin;       ///< per volume fraction of solid keratin
  AbsorptionBand dna;           ///< per mg/mL
  AbsorptionBand urocanicAcid;  ///< per mol/L

  /// Throws SpectralDataError (file:line:column where known) on a parse error, a missing, unknown
  /// or non-numeric key, or inconsistent values.
  static SpectralExtensions load(const std::filesystem::path& tomlFile);
  /// Parses TOML text exactly as load does; `sourceName` stands for the file in messages.
  static SpectralExtensions parse(const std::string& tomlText,
                                  const std::filesystem::path& sourceName);
};

}  // namespace hylios::skin
