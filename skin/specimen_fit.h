// Fitting specimen quantities to a measured reflectance curve (issue 14): bounded
// Levenberg–Marquardt on the spectral walk's curve with common random numbers.
//
// Every evaluation of the model curve runs simulateSkinSpectral (skin/spectral_simulation.h) with
// the same seed and ray count, so two evaluations differ only through the parameters: the paths
// reuse their random numbers and the objective is smooth in the absorber contents (they enter the
// spectral walk's weights only), nearly smooth in the scattering quantities (melanosome content,
// thicknesses). The Jacobian is taken by one-sided finite differences of that curve.
//
// The free quantities and their physiological bounds (with citations in docs/interpretations.md,
// "Fitting a specimen"):
//
// | name                        | what it sets                                               | unit |
// |-----------------------------|------------------------------------------------------------|------|
// | melanosome                  | melanosome content of the most pigmented epidermal layer;   | %    |
// |                             | the other layers keep their ratio to it                     |      |
// | colloidal                   | colloidal melanin content (same profile rule)              | %    |
// | blood                       | dermal blood content (same profile rule, both dermis layers)| %    |
// | oxygenation                 | oxygenated fraction of the blood                            | %    |
// | water_reduction             | water reduction of every layer (Fig. 14's dehydration)      | %    |
// | stratum_corneum_thickness   | stratum corneum thickness                                   | cm   |
// | epidermis_thickness         | granulosum + spinosum + basale, ratios kept                 | cm   |
// | papillary_dermis_thickness  | papillary dermis thickness                                  | cm   |
// | reticular_dermis_thickness  | reticular dermis thickness                                  | cm   |
//
// Uncertainties (FittedQuantity::uncertainty) add two variances: the residuals' s²(JᵀJ)⁻¹ (the
// measured curve's noise, taken as independent per wavelength), and the frozen noise of the
// model's own curve (the fit's seed), which is correlated across the wavelengths of a bundle, so
// the parameters absorb it and the residuals do not show it: its covariance is estimated at the
// optimum from kFitNoiseBatches curves on other seeds, each with rays/kFitNoiseBatches rays (one
// more curve's worth of rays), and projected by (JᵀJ)⁻¹Jᵀ. Measured before that second term, on
// synthetic S2 curves over 40 seeds: the errors were 2.5–3× the stated σ; with it, rms z ≈ 1
// (docs/interpretations.md, "Fitting a specimen", row "Uncertainties"). For the scattering
// quantities (melanosome content, thicknesses) the finite differences also see path flips.
//
// No command line here (app/fit_command.cpp is the command).
#pragma once
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "skin/core/statistics.h"
#include "skin/skin_walk.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios::skin {

/// A bad fit request (unknown quantity, bounds, empty curve, non-finite data); what() says which.
class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One quantity a fit may free, with its physiological bounds.
struct FitQuantity {
  std::string name;  ///< as given to --free
  std::string unit;  ///< "%" or "cm"
  double lower = 0;  ///< in `unit`
  double upper = 0;
  std::string basis;  ///< one line: where the bounds come from (details in docs/interpretations.md)
};

/// Every quantity fitSpecimen accepts, in table order.
const std::vector<FitQuantity>& fitQuantities();
/// The quantity called `name`; throws FitError listing the known names.
const FitQuantity& fitQuantity(const std::string& name);
/// The value of a quantity in `specimen` (in its unit).
double fitQuantityValue(const Specimen& specimen, const std::string& name);
/// `start` with quantity `name` set to `value` (profiles over layers taken from `start`, so the
/// ratio between layers survives a value of 0 on the way).
void setFitQuantity(const Specimen& start, Specimen& specimen, const std::string& name,
                    double value);

/// Batches of the model-noise term of the uncertainties, and their seeds' offset from the fit's.
inline constexpr std::uint64_t kFitNoiseBatches = 16;
inline constexpr std::uint64_t kFitNoiseSeedOffset = 0x5eed0000;

/// A measured curve on the fit's wavelengths (already interpolated; same length).
struct FitTarget {
  std::vector<double> wavelengthNm;
  std::vector<double> reflectance;
};

struct FitOptions {
  std::vector<std::string> free;  ///< names of fitQuantities(), each at most once
  double incidenceDeg = 45;
  std::uint64_t rays = 20000;  ///< per wavelength and evaluation
  std::uint64_t seed = 1;      ///< the same for every evaluation (common random numbers)
  WalkOptions walk = defaultFitWalk();
  int maxIterations = 25;
  /// Stop when an accepted step lowers the sum of squares by less than this fraction.
  double relativeTolerance = 1e-3;
  /// Finite-difference step as a fraction of each quantity's bound range.
  double differenceStep = 0.02;
  /// Called after every curve evaluation with the count so far and the current best RMS.
  std::function<void(std::size_t evaluations, double bestRms)> progress;

  static WalkOptions defaultFitWalk() {
    WalkOptions w;
    w.tabulatedMelanosomes = true;
    w.layerAbsorption = false;
    return w;
  }
};

struct FittedQuantity {
  FitQuantity quantity;
  double start = 0;
  double value = 0;
  double uncertainty = 0;  ///< 1 σ: the residuals' and the model's own noise, at the optimum
  bool atBound = false;    ///< within 0.1 % of the range of a bound (σ then from the free ones)
};

struct FitResult {
  Specimen specimen;  ///< the start specimen with the fitted values
  std::vector<FittedQuantity> quantities;
  std::vector<Estimate> model;  ///< model curve at the optimum, per target wavelength
  double startRms = 0;
  double rms = 0;
  std::size_t evaluations = 0;  ///< curve evaluations (each `rays` × wavelengths)
  int iterations = 0;
  std::string stopReason;
};

/// The model's reflectance curve for `specimen` (simulateSkinSpectral with `options`' incidence,
/// rays, seed and walk). Throws SpectralDataError for wavelengths outside the data.
std::vector<Estimate> modelReflectance(const Specimen& specimen, const SpectralDatabase& spectra,
                                       const std::vector<double>& wavelengthNm,
                                       const FitOptions& options);

/// Fits options.free of `start` to `target` by bounded Levenberg–Marquardt. The start values are
/// clamped into the bounds. Throws FitError for an unknown or repeated quantity, no free
/// quantity, an empty target, fewer wavelengths than free quantities, or non-finite target values.
FitResult fitSpecimen(const Specimen& start, const SpectralDatabase& spectra,
                      const FitTarget& target, const FitOptions& options);

}  // namespace hylios::skin
