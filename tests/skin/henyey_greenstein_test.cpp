// Henyey–Greenstein sampling: chi-square for g = 0, 0.5, 0.9, −0.7, 0.999, hand values, the mean
// cosine, stability near g = 0 and |g| = 1, end points.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/random.h"
#include "skin/sampling/henyey_greenstein.h"
#include "tests/support/chi2.h"

namespace hylios::skin {
namespace {

/// The textbook inversion, used only where it is well conditioned (moderate g).
double textbookHenyeyGreensteinCos(double g, double u) {
  const double s = (1 - g * g) / (1 - g + 2 * g * u);
  return (1 + g * g - s * s) / (2 * g);
}

TEST(HenyeyGreenstein, InversionByHand) {
  // u = 1/2: s = 1 − g², μ = g(3 − g²)/2 -> g = 0.5: 0.6875.
  EXPECT_NEAR(sampleHenyeyGreensteinCos(0.5, 0.5), 0.6875, 1e-15);
  EXPECT_DOUBLE_EQ(sampleHenyeyGreensteinCos(0.0, 0.25), -0.5);
  for (const double g : {-0.7, -0.2, 0.3, 0.5, 0.9}) {
    for (const double u : {0.01, 0.3, 0.5, 0.77, 0.99}) {
      EXPECT_NEAR(sampleHenyeyGreensteinCos(g, u), textbookHenyeyGreensteinCos(g, u), 1e-13)
          << "g = " << g << ", u = " << u;
    }
  }
}

TEST(HenyeyGreenstein, StableNearIsotropyAndNearOne) {
  // g = 1e-12, u = 1/2: μ = g(3 − g²)/2 = 1.5e-12. The textbook form computes (1 + g² − s²)/(2g)
  // with s² ≈ 1 − 4g, losing ~1e-16/(2g) = 5e-5 absolutely; the factorised form keeps the
  // rounding of 1 − (1 − μ), a few 1e-16.
  EXPECT_NEAR(sampleHenyeyGreensteinCos(1e-12, 0.5), 1.5e-12, 1e-15);
  // g = 1 − 1e-9: u = 0 gives −1; u = 1e-9 gives D = (1 − g) + 2gu ≈ 3e-9 and
  // 1 − μ = 2(1 − g)²(1 − u)(1 + gu)/D² ≈ 2e-18/9e-18 = 2/9 (to ~1e-8).
  const double gNearOne = 1.0 - 1e-9;
  EXPECT_DOUBLE_EQ(sampleHenyeyGreensteinCos(gNearOne, 0.0), -1.0);
  EXPECT_NEAR(sampleHenyeyGreensteinCos(gNearOne, 1e-9), 7.0 / 9.0, 1e-8);
  EXPECT_LE(sampleHenyeyGreensteinCos(gNearOne, 0.5), 1.0);
}

TEST(HenyeyGreenstein, DensityIsNormalised) {
  for (const double g : {0.0, 0.5, 0.9, -0.7, 0.999}) {
    EXPECT_NEAR(test::integrate([g](double mu) { return henyeyGreensteinDensity(g, mu); }, -1.0,
                                1.0, 1e-13, 64),
                1.0, 1e-9)
        << "g = " << g;
  }
}

class HenyeyGreensteinChi2 : public ::testing::TestWithParam<double> {};

TEST_P(HenyeyGreensteinChi2, CosineMatchesDensity) {
  const double g = GetParam();
  Rng rng(17, static_cast<std::uint64_t>(1000 * (g + 1)));
  const int n = 1000000;
  const std::vector<double> mus =
      test::drawSamples(n, [&] { return sampleHenyeyGreensteinCos(g, rng.uniform()); });
  const auto density = [g](double mu) { return henyeyGreensteinDensity(g, mu); };
  const auto edges = test::equalProbabilityEdges(density, -1.0, 1.0, 50);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(mus, density, edges))) << "g = " << g;
  // Mean cosine g: Var[μ] <= 1, so se <= 1/sqrt(n) = 1e-3; 4σ.
  EXPECT_NEAR(test::mean(mus), g, 4e-3) << "g = " << g;
}

INSTANTIATE_TEST_SUITE_P(AsymmetryValues, HenyeyGreensteinChi2,
                         ::testing::Values(0.0, 0.5, 0.9, -0.7, 0.999));

TEST(HenyeyGreenstein, EndPointsAreFiniteAndInRange) {
  for (const double g : {0.0, 1e-15, 0.5, -0.999999, 0.999999}) {
    for (const double u : {0.0, kOneMinusEpsilon}) {
      const double mu = sampleHenyeyGreensteinCos(g, u);
      EXPECT_TRUE(std::isfinite(mu)) << "g = " << g << ", u = " << u;
      EXPECT_GE(mu, -1.0);
      EXPECT_LE(mu, 1.0);
    }
  }
  EXPECT_THROW(sampleHenyeyGreensteinCos(1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleHenyeyGreensteinCos(-1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(henyeyGreensteinDensity(std::nan(""), 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
