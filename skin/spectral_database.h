// The absorbers' spectra over 250–2500 nm, loaded from assets/spectra/ (see its SOURCES.md).
// The unit derivation for every absorber is listed in docs/absorber_units.md.
//
// Each absorber has tabulated data plus, where a table stops short of 250–2500 nm, a declared and
// cited extension (a power law, a band model, ...). A wavelength that neither covers is refused
// with SpectralDataError naming the substance and its covered range; nothing is clamped silently.
#pragma once
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "skin/absorber.h"

namespace hylios::skin {

/// The model's spectral domain, 250–2500 nm (the paper's title and Sec. 5): the wavelengths every
/// absorber and water's index cover (docs/interpretations.md, "Model domain"). Inputs are checked
/// against it where they are read (the command line, scene files), so the error names the input.
inline constexpr double kModelMinWavelengthNm = 250.0;
inline constexpr double kModelMaxWavelengthNm = 2500.0;

class SpectralDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The wavelengths an absorber (or water's refractive index) is defined at.
struct SpectralCoverage {
  double minNm = 0;
  double maxNm = 0;
};

class SpectralDatabase {
 public:
  /// Loads every table under `spectraDir` (e.g. <data>/assets/spectra). Throws SpectralDataError
  /// naming file and line on a malformed or missing table.
  static SpectralDatabase load(const std::filesystem::path& spectraDir);

  /// Natural-log specific absorption coefficient of `absorber` at `wavelengthNm`, in cm⁻¹ per unit
  /// of concentrationUnit(absorber) (decadic tables are converted with ln 10, paper Eq. 2).
  /// Throws SpectralDataError outside coverage(absorber).
  double specificAbsorption(Absorber absorber, double wavelengthNm) const;

  static ConcentrationUnit concentrationUnit(Absorber absorber);
  SpectralCoverage coverage(Absorber absorber) const;

  /// Real refractive index of water (for the layers' dispersion, paper Fig. 6).
  double waterRefractiveIndex(double wavelengthNm) const;

  SpectralDatabase(SpectralDatabase&&) noexcept;
  SpectralDatabase& operator=(SpectralDatabase&&) noexcept;
  ~SpectralDatabase();

 private:
  struct Impl;
  explicit SpectralDatabase(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace hylios::skin
