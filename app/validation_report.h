// `hylios validate`: every comparison the project has data for, computed and written as a
// Markdown report with plots (issue 14). The comparisons:
//
// | id     | what                                                                 | data                           |
// |--------|----------------------------------------------------------------------|--------------------------------|
// | fig7   | S1 vs NCSU object 117 and S2 vs object 113, 45°, 400–700 nm (Fig. 7) | tests/data/validation (Vrhel 1994) |
// | fig9   | S3 at 8° vs the lightest quarter of the NIST set, S4 vs its darkest quarter, 250–2500 nm; S1, S2 and S3 with the site's stratum corneum vs the lightest quarter | tests/data/validation (Cooksey 2017) |
// | fig8   | S2 epidermis, 302 nm, normal incidence, transmitted profile (Fig. 8) | none in the project: the paper's claim (forward scattering) is checked |
// | fig10  | S1 visible BRDF in the plane of incidence at 0° and 60° (Fig. 10)    | none in the project: shape checks |
// | fig11  | S1 at 45°, 365 nm vs 1100 nm, surface/subsurface/total (Fig. 11)     | none in the project: the paper's claim (IR more diffuse) is checked |
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "skin/core/statistics.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios {

/// The stratum corneum of the NIST set's site, the inside of the forearm (Cooksey, Tsai & Allen,
/// Proc. SPIE 9461, 94611M, 2015), as measured there in vivo by confocal Raman: 22.6 µm (Egawa,
/// Hirao & Takahashi, Acta Derm. Venereol. 87, 4, 2007) and 17.6–21.3 µm (Skin Res. Technol. 24,
/// 504, 2018, PMID 29464802). Table 1 gives S3 4 µm, S1 and S2 10 µm.
constexpr double kNistSiteStratumCorneumCm = 0.0020;

/// One modelled curve against a measured one.
struct CurveComparison {
  std::string specimen, measuredLabel, measuredColumn;
  double incidenceDeg = 45;
  std::vector<double> wavelengthNm;
  std::vector<skin::Estimate> model;
  std::vector<double> measured;
  double rms = 0;          ///< of model − measured
  double maxAbsError = 0;  ///< max |model − measured|
  double worstWavelengthNm = 0;
  double meanError = 0;  ///< mean of model − measured (sign: model brighter > 0)
  double noiseRms = 0;   ///< sqrt(mean σ²): the RMS's own Monte Carlo uncertainty bound
};

/// The spectral walk's reflectance curve (exact melanosomes, no per-layer absorption tally) of
/// `specimen` at `incidenceDeg`, `rays` per wavelength: the model side of every comparison.
std::vector<skin::Estimate> modelReflectanceCurve(const skin::Specimen& specimen,
                                                  const std::vector<double>& wavelengths,
                                                  double incidenceDeg, std::uint64_t rays,
                                                  std::uint64_t seed,
                                                  const skin::SpectralDatabase& spectra);

/// S1/obj117 or S2/obj113 style comparison over `wavelengths` at `incidenceDeg` with the spectral
/// walk (exact melanosomes) and `rays` per wavelength; `ncsuFile` is the NCSU CSV.
CurveComparison compareWithMeasured(const std::string& specimen,
                                    const std::filesystem::path& ncsuFile,
                                    const std::string& column,
                                    const std::vector<double>& wavelengths, double incidenceDeg,
                                    std::uint64_t rays, std::uint64_t seed,
                                    const skin::SpectralDatabase& spectra);

struct ValidationOptions {
  std::filesystem::path outDir;
  std::uint64_t rays = 100000;  ///< per wavelength for the NCSU curves and the angular figures
  std::uint64_t seed = 1;
  bool plots = true;
};

/// Runs every comparison and writes outDir/validation.md and its PNGs under outDir/validation/
/// (fig7_ncsu.png, fig9_nist.png, fig9_nist_uv.png, fig8_forward_profile.png, fig10_brdf.png,
/// fig11_uv_ir.png).
/// `--out docs` gives the committed docs/validation.md. Returns the Markdown text.
std::string runValidation(const ValidationOptions& options);

}  // namespace hylios
