// A measured population of skin reflectance curves and the groups of it that the validation
// compares specimens with: the NIST reference set of 100 subjects, 250–2500 nm (Cooksey, Allen &
// Tsai 2017; tests/data/validation/nist_cooksey2017_skin.csv, provenance in its SOURCES.md).
//
// Groups are ranked by lightness, the mean reflectance over 500–700 nm (where melanin sets the
// curve and water does not): the lightest quarter stands for lightly pigmented skin, the darkest
// quarter for the most pigmented skin the set holds (docs/interpretations.md, "Measured skin
// population").
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "app/measured_spectrum.h"

namespace hylios {

/// The spread of a group's curves per wavelength.
struct PopulationEnvelope {
  std::vector<double> wavelengthNm;
  std::vector<double> lowest, median, highest;  ///< over the group's members at each wavelength
  std::size_t members = 0;
};

struct SkinPopulation {
  std::vector<MeasuredSpectrum> subjects;  ///< on one wavelength grid

  /// Mean reflectance of subject `index` over 500–700 nm (every measured wavelength there).
  double lightness(std::size_t index) const;
  /// Subject indices, lightest first (ties by index).
  std::vector<std::size_t> byLightness() const;
  /// The lightest (lightest = true) or darkest `fraction` of the subjects, at least one.
  std::vector<std::size_t> quantileGroup(double fraction, bool lightest) const;
  /// The group's lowest, median and highest reflectance at each of `wavelengths` (linear
  /// interpolation between measured ones); throws std::out_of_range outside the data.
  PopulationEnvelope envelope(const std::vector<std::size_t>& members,
                              const std::vector<double>& wavelengths) const;
};

/// Loads a CSV of curves (first column nm, one column per subject; loadMeasuredSpectra's format).
/// Throws std::runtime_error naming the file for a value outside [0, 1.5] (a reflectance factor).
SkinPopulation loadSkinPopulation(const std::filesystem::path& file);

}  // namespace hylios
