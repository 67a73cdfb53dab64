// Fitting specimen quantities to a curve (skin/specimen_fit.h): a curve synthesised by the model
// from known values (with an independent seed, so it carries Monte Carlo noise like a measurement)
// is recovered within the stated uncertainties; fitted values stay inside their bounds; bad
// requests are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "skin/specimen_fit.h"
#include "tests/support/test_spectra.h"

namespace hylios::skin {
namespace {

std::vector<double> grid(double from, double to, double step) {
  std::vector<double> w;
  for (double x = from; x <= to + 1e-9; x += step) w.push_back(x);
  return w;
}

FitTarget synthesise(const Specimen& truth, const std::vector<double>& wavelengths,
                     std::uint64_t rays, std::uint64_t seed) {
  FitOptions options;
  options.rays = rays;
  options.seed = seed;
  FitTarget target{wavelengths, {}};
  for (const Estimate& e : modelReflectance(truth, test::spectra(), wavelengths, options))
    target.reflectance.push_back(e.mean);
  return target;
}

// S2 with known values of the three quantities the fits below free (kTruthValues, in the order
// of kTruthQuantities).
const std::vector<std::string> kTruthQuantities{"colloidal", "blood", "oxygenation"};
constexpr double kTruthValues[] = {2.0, 1.2, 70.0};
Specimen knownTruth(const Specimen& s2) {
  Specimen truth = s2;
  for (std::size_t k = 0; k < kTruthQuantities.size(); ++k)
    setFitQuantity(s2, truth, kTruthQuantities[k], kTruthValues[k]);
  return truth;
}

TEST(SpecimenFit, RecoversKnownValuesWithinStatedUncertainties) {
  const Specimen s2 = loadSpecimen("S2", test::specimenDir());
  const Specimen truth = knownTruth(s2);
  const std::vector<double> wavelengths = grid(400, 700, 15);
  const FitTarget target = synthesise(truth, wavelengths, 40000, 777);
  FitOptions options;
  options.free = kTruthQuantities;
  options.rays = 10000;
  options.seed = 3;
  const FitResult fit = fitSpecimen(s2, test::spectra(), target, options);
  std::cout << "RMS " << fit.startRms << " -> " << fit.rms << ", " << fit.evaluations
            << " evaluations, " << fit.stopReason << "\n";
  for (std::size_t k = 0; k < fit.quantities.size(); ++k) {
    const FittedQuantity& q = fit.quantities[k];
    std::cout << q.quantity.name << ": " << q.start << " -> " << q.value << " ± " << q.uncertainty
              << " (truth " << kTruthValues[k] << ")\n";
    EXPECT_FALSE(q.atBound) << q.quantity.name;
    EXPECT_GT(q.uncertainty, 0) << q.quantity.name;
    EXPECT_LT(q.uncertainty, 0.25 * kTruthValues[k]) << q.quantity.name;
    // 3σ: three quantities, each within 3σ with probability 0.997 if σ is right.
    EXPECT_NEAR(q.value, kTruthValues[k], 3 * q.uncertainty) << q.quantity.name;
  }
  EXPECT_LT(fit.rms, 0.5 * fit.startRms);
  EXPECT_LT(fit.rms, 0.005);  // the synthetic curve's own noise is ≈ 0.002
  EXPECT_NEAR(fitQuantityValue(fit.specimen, "blood"), fit.quantities[1].value, 1e-12);
}

TEST(SpecimenFit, StatedUncertaintiesCoverTheErrorsOverSeeds) {
  // Ten synthetic curves (independent seeds; 80 000 rays, so that their own noise, correlated
  // across a bundle like the model's, stays small against the fit's 10 000) fitted with ten
  // seeds: if σ is right, z = (fitted − truth)/σ has rms 1 over the 30 values (measured over 40
  // seeds: 1.13, 0.95, 1.04 per quantity; σ from the residuals alone gave 2.5–3.0). The bound
  // 1.8 is far in the tail for calibrated σ (30 values, χ² with 15–30 effective degrees of
  // freedom: p < 1e-4) and far below the residual-only σ's errors.
  const Specimen s2 = loadSpecimen("S2", test::specimenDir());
  const Specimen truth = knownTruth(s2);
  const std::vector<double> wavelengths = grid(400, 700, 30);
  double squares = 0;
  int scored = 0;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const FitTarget target = synthesise(truth, wavelengths, 80000, 5000 + 13 * seed);
    FitOptions options;
    options.free = kTruthQuantities;
    options.rays = 10000;
    options.seed = 60 + 7 * seed;
    const FitResult fit = fitSpecimen(s2, test::spectra(), target, options);
    for (std::size_t k = 0; k < fit.quantities.size(); ++k) {
      const FittedQuantity& q = fit.quantities[k];
      if (q.atBound) continue;
      ASSERT_TRUE(std::isfinite(q.uncertainty) && q.uncertainty > 0) << q.quantity.name;
      const double z = (q.value - kTruthValues[k]) / q.uncertainty;
      squares += z * z;
      ++scored;
    }
  }
  ASSERT_GE(scored, 27);
  const double rmsZ = std::sqrt(squares / scored);
  std::cout << "rms z over " << scored << " fitted values: " << rmsZ << "\n";
  EXPECT_LT(rmsZ, 1.8);
  EXPECT_GT(rmsZ, 0.4);  // nor grossly inflated
}

TEST(SpecimenFit, ValuesStayInsideTheirBounds) {
  const Specimen s2 = loadSpecimen("S2", test::specimenDir());
  Specimen truth = s2;
  setFitQuantity(s2, truth, "blood", 0.02);  // below the 0.2 % bound
  const FitTarget target = synthesise(truth, grid(400, 700, 20), 10000, 9);
  FitOptions options;
  options.free = {"blood", "oxygenation"};
  options.rays = 4000;
  const FitResult fit = fitSpecimen(s2, test::spectra(), target, options);
  for (const auto& q : fit.quantities) {
    EXPECT_GE(q.value, q.quantity.lower) << q.quantity.name;
    EXPECT_LE(q.value, q.quantity.upper) << q.quantity.name;
  }
  EXPECT_TRUE(fit.quantities[0].atBound);
  EXPECT_DOUBLE_EQ(fit.quantities[0].value, fitQuantity("blood").lower);
  // Dermis layers keep S2's equal contents.
  EXPECT_DOUBLE_EQ(fit.specimen.bloodFraction[index(Layer::PapillaryDermis)],
                   fit.specimen.bloodFraction[index(Layer::ReticularDermis)]);
}

TEST(SpecimenFit, ProfilesOverLayersAreKept) {
  const Specimen s2 = loadSpecimen("S2", test::specimenDir());  // melanosomes in the basale only
  Specimen s = s2;
  setFitQuantity(s2, s, "melanosome", 5.0);
  EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(Layer::StratumBasale)], 0.05);
  EXPECT_DOUBLE_EQ(s.melanosomeFraction[index(Layer::StratumSpinosum)], 0.0);
  setFitQuantity(s2, s, "epidermis_thickness", 0.006);
  EXPECT_NEAR(s.thicknessCm[index(Layer::StratumGranulosum)], 0.002, 1e-15);
  EXPECT_NEAR(fitQuantityValue(s, "epidermis_thickness"), 0.006, 1e-15);
  for (const auto& q : fitQuantities()) {
    EXPECT_LT(q.lower, q.upper) << q.name;
    EXPECT_FALSE(q.basis.empty()) << q.name;
  }
}

TEST(SpecimenFit, BadRequestsAreClearErrors) {
  const Specimen s2 = loadSpecimen("S2", test::specimenDir());
  const FitTarget target{{400, 500, 600}, {0.2, 0.3, 0.4}};
  auto message = [&](const FitTarget& t, std::vector<std::string> free) {
    FitOptions options;
    options.free = std::move(free);
    options.rays = 200;
    try {
      fitSpecimen(s2, test::spectra(), t, options);
    } catch (const FitError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(target, {"melanin"}).find("unknown fit quantity 'melanin' (known: melanosome"),
            std::string::npos);
  EXPECT_NE(message(target, {}).find("no quantity to fit"), std::string::npos);
  EXPECT_NE(message(target, {"blood", "blood"}).find("given twice"), std::string::npos);
  EXPECT_NE(message(FitTarget{}, {"blood"}).find("no wavelength in common"), std::string::npos);
  FitTarget nan = target;
  nan.reflectance[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(nan, {"blood"}).find("value at 500 nm is not finite"), std::string::npos);
  EXPECT_NE(
      message(FitTarget{{500}, {0.3}}, {"blood", "colloidal"}).find("at least as many wavelengths"),
      std::string::npos);
}

}  // namespace
}  // namespace hylios::skin
