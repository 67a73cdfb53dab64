// The HyLIoS walk against measured skin and against its own bookkeeping (paper Figs. 7, 9).
//
// Monte Carlo errors: a reflectance from N rays has σ = sqrt(R(1−R)/N) (reported by the tally);
// comparisons of two wavelengths use independent streams, σ_diff = sqrt(σ1² + σ2²).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "app/measured_spectrum.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "tests/support/test_spectra.h"

using namespace hylios::skin;

namespace {

const std::string kRoot = HYLIOS_SOURCE_DIR;

using hylios::test::spectra;

Estimate reflectance(const std::string& specimenName, double wavelengthNm, double angleDeg,
                     std::uint64_t rays) {
  const Specimen specimen = loadSpecimen(specimenName, kRoot + "/scenes/specimens");
  WalkRunOptions options;
  options.incidenceDeg = angleDeg;
  options.rays = rays;
  options.seed = 2024;
  return simulateSkin(computeSkinOptics(specimen, spectra(), wavelengthNm), options).reflectance();
}

/// RMS difference of the modelled curve (400–700 nm, 10 nm, 45°) to an NCSU object, with the
/// largest Monte Carlo standard error of the modelled points.
double ncsuRms(const std::string& specimen, const std::string& object, double* worstSigma) {
  const auto measured = hylios::loadMeasuredSpectrum(
      kRoot + "/tests/data/validation/ncsu_vrhel1994_skin.csv:" + object);
  std::vector<double> wavelengths, model;
  *worstSigma = 0;
  for (double w = 400; w <= 700; w += 10) {
    const Estimate r = reflectance(specimen, w, 45, 20000);
    wavelengths.push_back(w);
    model.push_back(r.mean);
    *worstSigma = std::fmax(*worstSigma, r.standardError);
  }
  return hylios::rmsDifference(wavelengths, model, measured);
}

}  // namespace

// Paper Fig. 7: "computed using the pigmentation datasets S1 and S2" for NCSU curves 117 (left)
// and 113 (right), with Table 1's values. Issue 14's goal: RMS difference ≤ 0.03 each. The bound
// is the goal itself. Its margin against the walk's noise: the RMS of a 31-point curve moves by
// about σ_point/√31 between seeds (σ_point ≤ 0.0036 at 2·10⁴ rays), and `hylios spectrum
// --estimator per-wavelength --rays 20000` with seeds 1–4 gave S2 0.0283–0.0290 (spread 0.0004)
// against 0.0289 ± 0.001 from the spectral walk at 10⁵ rays (docs/validation.md); S1 is at 0.015.
// So S2 sits about 3 seed spreads below the bound, S1 far below it. Before the complexes met at
// most ⌊m⌋ = 4 melanosomes (docs/interpretations.md) the figures were 0.030 and 0.044.
TEST(SkinValidation, S1MatchesNcsuObject117) {
  double sigma = 0;
  const double rms = ncsuRms("S1", "obj117", &sigma);
  std::cout << "S1 vs NCSU obj117: RMS " << rms << " (max point σ " << sigma << ")\n";
  EXPECT_LT(rms, 0.03);
  EXPECT_GT(rms, 0.005);  // the model is not the measurement: a far smaller RMS means a mix-up
}

TEST(SkinValidation, S2MatchesNcsuObject113) {
  double sigma = 0;
  const double rms = ncsuRms("S2", "obj113", &sigma);
  std::cout << "S2 vs NCSU obj113: RMS " << rms << " (max point σ " << sigma << ")\n";
  EXPECT_LT(rms, 0.03);
  EXPECT_GT(rms, 0.005);
}

// Paper Fig. 9 (top): S3 at 8° shows the water valleys at 1450 and 1940 nm and the
// hemoglobin features at 420 (Soret), 542 and 577 nm. Each asserted difference is > 4 σ_diff.
TEST(SkinValidation, S3ShowsWaterAndHemoglobinFeatures) {
  auto r = [](double w, std::uint64_t rays) { return reflectance("S3", w, 8, rays); };
  auto expectBelow = [](const Estimate& low, const Estimate& high, const char* what) {
    const double sigma = std::hypot(low.standardError, high.standardError);
    EXPECT_GT(high.mean - low.mean, 4 * sigma) << what << ": " << low.mean << " vs " << high.mean;
  };
  const Estimate r1300 = r(1300, 20000), r1450 = r(1450, 20000), r1650 = r(1650, 20000);
  const Estimate r1940 = r(1940, 50000), r2200 = r(2200, 50000);
  expectBelow(r1450, r1300, "1450 nm water valley below 1300 nm");
  expectBelow(r1450, r1650, "1450 nm water valley below 1650 nm");
  expectBelow(r1940, r1650, "1940 nm water valley below 1650 nm");
  expectBelow(r1940, r2200, "1940 nm water valley below 2200 nm");
  const Estimate r420 = r(420, 50000), r440 = r(440, 50000);
  expectBelow(r420, r440, "Soret band at 420 nm");
  // The 577 nm band sits on the steep rise towards 600 nm: its dip below 560 nm is only ≈ 0.005,
  // so those two wavelengths get 10⁶ rays each (σ_diff ≈ 0.00065).
  const Estimate r542 = r(542, 200000), r560 = r(560, 1000000), r577 = r(577, 1000000),
                 r600 = r(600, 50000);
  expectBelow(r542, r560, "HbO2 band at 542 nm");
  expectBelow(r577, r560, "HbO2 band at 577 nm");
  expectBelow(r577, r600, "HbO2 band at 577 nm (red side)");
}

// Every ray ends in exactly one outcome, so R + A + T = 1 per ray; a ray stopped by the event
// limit would break it, so none may occur.
TEST(SkinValidation, EnergyBalanceForAllSpecimens) {
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    const Specimen specimen = loadSpecimen(name, kRoot + "/scenes/specimens");
    for (double w : {250.0, 365.0, 550.0, 1100.0, 1450.0, 1940.0, 2500.0}) {
      WalkRunOptions options;
      options.incidenceDeg = 45;
      options.rays = 4000;
      const SkinTally t = simulateSkin(computeSkinOptics(specimen, spectra(), w), options);
      EXPECT_EQ(t.eventLimited().mean, 0.0) << name << " " << w;
      EXPECT_NEAR(t.reflectance().mean + t.absorptance().mean + t.transmittance().mean, 1.0, 1e-12)
          << name << " " << w;
      EXPECT_TRUE(std::isfinite(t.reflectance().standardError));
    }
  }
}
