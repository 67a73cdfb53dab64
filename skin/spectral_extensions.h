// The declared extensions of the absorber tables (assets/spectra/extensions.toml): the model's
// wavelength domain, the melanin power-law fit ranges, the hemoglobin tail above 1000 nm, the
// lipid and carotenoid settings, the compositions that build keratin (aromatic amino acids) and DNA
// (nucleobases) from their PhotochemCAD tables, and the band model of urocanic acid.
// Every key is required and unknown keys are errors (file:line:column).
#pragma once
#include <filesystem>
#include <string>

#include "skin/absorption_band.h"

namespace hylios::skin {

/// One PhotochemCAD molecule table of a composite absorber: its share, its molar mass and the
/// wavelength from which it is declared zero (its first non-positive row, or the table's end).
struct MoleculeShare {
  double share = 0;      ///< keratin: g per 100 g of protein; DNA: mole fraction of the base
  double molarMass = 0;  ///< g/mol (keratin's amino acids; unused for DNA's bases)
  double zeroFromNm = 0;
};

/// Keratin as its aromatic amino acids (Block 1951 composition of human skin keratin).
struct KeratinComposition {
  double densityMgPerMl = 0;  ///< solid keratin, mg/mL (converts a volume fraction to mg/mL)
  MoleculeShare tyrosine, tryptophan, phenylalanine;
};

/// DNA as the sum of its four bases weighted by base composition, scaled to a cited value.
struct DnaComposition {
  double gcFraction = 0;      ///< G + C share of the bases
  double referenceNm = 0;     ///< wavelength of the cited extinction
  double referenceValue = 0;  ///< decadic cm⁻¹ per mg/mL of double-stranded DNA there
  MoleculeShare adenine, guanine, cytosine, thymine;  ///< shares set from gcFraction
};

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

  KeratinComposition keratin;   ///< per volume fraction of solid keratin
  DnaComposition dna;           ///< per mg/mL
  AbsorptionBand urocanicAcid;  ///< per mol/L (band model: no table found)

  /// Throws SpectralDataError (file:line:column where known) on a parse error, a missing, unknown
  /// or non-numeric key, or inconsistent values.
  static SpectralExtensions load(const std::filesystem::path& tomlFile);
  /// Parses TOML text exactly as load does; `sourceName` stands for the file in messages.
  static SpectralExtensions parse(const std::string& tomlText,
                                  const std::filesystem::path& sourceName);
};

}  // namespace hylios::skin
