// Rayleigh polar-angle sampling (Sec. 4.2.1, Algorithm 1): chi-square against its density,
// hand-computed inversions, the density's normalisation, and the u = 0 / 1 − ε end points.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/rayleigh_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

TEST(RayleighSampling, InversionByHand) {
  // F(μ) = (μ³ + 3μ + 4)/8: F(0) = 1/2, F(0.5) = (0.125 + 1.5 + 4)/8 = 0.703125,
  // F(−0.5) = (−0.125 − 1.5 + 4)/8 = 0.296875.
  EXPECT_NEAR(sampleRayleighCos(0.5), 0.0, 1e-16);
  EXPECT_NEAR(sampleRayleighCos(0.703125), 0.5, 1e-15);
  EXPECT_NEAR(sampleRayleighCos(0.296875), -0.5, 1e-15);
  EXPECT_DOUBLE_EQ(sampleRayleighCos(0.0), -1.0);
  EXPECT_NEAR(sampleRayleighPolar(0.5), kPi / 2, 1e-15);
  // Near u = 1/2 the result keeps its relative accuracy: u = 1/2 + 2⁻⁴⁰ (exact) gives
  // μ³ + 3μ = 2w, w = 2⁻³⁸, so μ = 2w/3 up to a relative O(w²) ≈ 1e-23.
  EXPECT_NEAR(sampleRayleighCos(0.5 + std::ldexp(1.0, -40)) / (std::ldexp(1.0, -37) / 3.0), 1.0,
              1e-14);
}

TEST(RayleighSampling, DensityIsNormalisedAndMatchesAlgorithmOne) {
  EXPECT_NEAR(test::integrate(rayleighPolarDensity, 0.0, kPi), 1.0, 1e-12);
  EXPECT_NEAR(test::integrate(rayleighCosDensity, -1.0, 1.0), 1.0, 1e-12);
  // Algorithm 1's acceptance target (1 + cos²θ) sinθ, normalised by ∫ = 8/3, is the density.
  for (const double theta : {0.1, 0.7, 1.5, 2.9}) {
    const double target = (1.0 + std::cos(theta) * std::cos(theta)) * std::sin(theta);
    EXPECT_NEAR(rayleighPolarDensity(theta), target * 3.0 / 8.0, 1e-15);
  }
}

TEST(RayleighSampling, ChiSquareOfPolarAngle) {
  Rng rng(2024);
  std::vector<double> thetas(1000000);
  for (double& t : thetas) t = sampleRayleighPolar(rng.uniform());
  const auto edges = test::equalProbabilityEdges(rayleighPolarDensity, 0.0, kPi, 60);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, rayleighPolarDensity, edges)));
}

TEST(RayleighSampling, MomentsMatch) {
  // E[μ²] = (3/8)∫(μ² + μ⁴) = (3/8)(2/3 + 2/5) = 2/5; Var[μ²] = E[μ⁴] − 4/25 with
  // E[μ⁴] = (3/8)(2/5 + 2/7) = 9/35, so σ(μ²) = sqrt(9/35 − 4/25) = 0.3116; n = 1e6 -> se 3.1e-4.
  Rng rng(5);
  const int n = 1000000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double mu = sampleRayleighCos(rng.uniform());
    sum += mu * mu;
  }
  EXPECT_NEAR(sum / n, 0.4, 4 * 3.116e-4);
}

TEST(RayleighSampling, EndPointsAreFiniteAndInRange) {
  for (const double u : {0.0, kOneMinusEpsilon}) {
    const double mu = sampleRayleighCos(u);
    const double theta = sampleRayleighPolar(u);
    EXPECT_TRUE(std::isfinite(mu) && std::isfinite(theta)) << "u = " << u;
    EXPECT_GE(mu, -1.0);
    EXPECT_LE(mu, 1.0);
    EXPECT_GE(theta, 0.0);
    EXPECT_LE(theta, kPi);
  }
  EXPECT_NEAR(sampleRayleighCos(kOneMinusEpsilon), 1.0, 1e-15);
}

TEST(RayleighSampling, RejectsOutOfRangeUniforms) {
  EXPECT_THROW(sampleRayleighCos(1.0), std::invalid_argument);
  EXPECT_THROW(sampleRayleighCos(-1e-300), std::invalid_argument);
  EXPECT_THROW(sampleRayleighPolar(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
