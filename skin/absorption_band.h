// A literature band model for an absorber that has no tabulated spectrum (urocanic acid; keratin
// and DNA are sums of measured molecule tables since issue 14): one absorption band, Gaussian in
// photon energy, with separate widths on its blue (higher-energy) and red sides, normalised to a
// cited value at a reference wavelength, and zero from a declared wavelength on (where the Gaussian
// has fallen below 1e-5 of its peak).
//
// Parameters and their citations live in assets/spectra/extensions.toml; SOURCES.md ("Extensions")
// explains how each width follows from a cited absorbance ratio.
#pragma once

namespace hylios::skin {

/// Photon energy [eV] of a vacuum wavelength [nm]: E = h·c / λ.
constexpr double photonEnergyEv(double wavelengthNm) { return 1239.841984 / wavelengthNm; }

struct AbsorptionBand {
  double peakNm = 0;          ///< band maximum
  double sigmaBlueEv = 0;     ///< Gaussian standard deviation in energy on the short-λ side
  double sigmaRedEv = 0;      ///< ... on the long-λ side
  double referenceNm = 0;     ///< wavelength at which `referenceValue` is given
  double referenceValue = 0;  ///< decadic extinction at referenceNm, in the source's unit
  double multiplier = 1;      ///< converts the source's unit to the absorber's (e.g. a density)
  double zeroFromNm = 0;      ///< absorption is declared zero at and beyond this wavelength

  /// Band shape relative to its peak (1 at peakNm); 0 from zeroFromNm on.
  double relativeShape(double wavelengthNm) const;

  /// Natural-log specific absorption: ln10 · referenceValue · multiplier · shape(λ)/shape(ref).
  double naturalLogAbsorption(double wavelengthNm) const;

  /// Throws std::invalid_argument naming `substance` unless the parameters make a valid band.
  void validate(const char* substance) const;
};

}  // namespace hylios::skin
