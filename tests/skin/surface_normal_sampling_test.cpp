// Surface-normal polar angle (Sec. 4.3): chi-square for s = 0.1, 0.25, 0.45, 1, 2 (and 1e-6 on
// its own scale); the closed-form normalisation and CDF against quadrature of the paper's formula;
// hand values; the nearly specular limit s -> 0; end points and monotonicity.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/random.h"
#include "skin/sampling/surface_normal_sampling.h"
#include "tests/support/chi2.h"

namespace hylios::skin {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

/// The paper's unnormalised P_s(θs).
double paperFormula(double s, double theta) {
  const double c = std::cos(theta), sn = std::sin(theta);
  const double q = s * s * c * c + sn * sn;
  return s * s * s * s * sn / (q * q);
}

/// ∫ over [lo, hi] of f, split at 100·s so the peak near θ ~ s is resolved for small s.
template <class F>
double integrateWithPeak(F&& f, double s, double lo, double hi) {
  const double split = std::fmin(100.0 * s, 0.5 * (lo + hi));
  if (lo >= split || hi <= split) return test::integrate(f, lo, hi, 1e-15, 64);
  return test::integrate(f, lo, split, 1e-15, 64) + test::integrate(f, split, hi, 1e-15, 64);
}

TEST(SurfaceNormalSampling, DensityMatchesPaperFormulaNormalisedByQuadrature) {
  for (const double s : {1e-6, 0.1, 0.25, 0.45, 1.0, 2.0, 100.0}) {
    // Scaled by 1/s² so that the integral is O(1) (about 1/2 for small s) and the quadrature's
    // absolute tolerance is a relative one.
    const auto raw = [s](double t) { return paperFormula(s, t) / (s * s); };
    const double z = integrateWithPeak(raw, s, 0.0, kHalfPi);
    for (const double theta : {0.3 * s, s, 3 * s, 0.2, 0.9, 1.5}) {
      if (theta >= kHalfPi) continue;
      EXPECT_NEAR(surfaceNormalPolarDensity(s, theta) * z / raw(theta), 1.0, 1e-8)
          << "s = " << s << ", θ = " << theta;
    }
  }
}

TEST(SurfaceNormalSampling, ClosedFormCdfMatchesQuadrature) {
  for (const double s : {1e-6, 0.1, 0.45, 1.0, 2.0, 100.0}) {
    const auto density = [s](double t) { return surfaceNormalPolarDensity(s, t); };
    for (const double theta : {0.5 * s, 2 * s, 0.3, 1.2, 1.56}) {
      if (theta >= kHalfPi) continue;
      EXPECT_NEAR(surfaceNormalPolarCdf(s, theta), integrateWithPeak(density, s, 0.0, theta), 1e-10)
          << "s = " << s << ", θ = " << theta;
    }
  }
}

TEST(SurfaceNormalSampling, HandValues) {
  // s = 1: the density is sinθ, F = 1 − cosθ, θ = acos(1 − u).
  for (const double u : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(sampleSurfaceNormalPolar(1.0, u), std::acos(1.0 - u), 1e-14);
  }
  // s = 1: normaliser (s⁴/2)(1/s² + Φ(0)) = 1, so the density is exactly sinθ.
  EXPECT_NEAR(surfaceNormalPolarDensity(1.0, 0.7), std::sin(0.7), 1e-15);
  // s -> 0: tanθ = s·sqrt(u/(1 − u)) up to O(s² ln s): u = 0.5 gives θ = s, u = 0.8 gives 2s.
  EXPECT_NEAR(sampleSurfaceNormalPolar(1e-6, 0.5) / 1e-6, 1.0, 1e-9);
  EXPECT_NEAR(sampleSurfaceNormalPolar(1e-6, 0.8) / 2e-6, 1.0, 1e-9);
  EXPECT_NEAR(sampleSurfaceNormalPolar(1e-30, 0.8) / 2e-30, 1.0, 1e-15);
  // The closed-form branch and the s -> 0 limit branch meet at s = 1e-20.
  EXPECT_NEAR(
      sampleSurfaceNormalPolar(1.000001e-20, 0.3) / sampleSurfaceNormalPolar(0.999999e-20, 0.3),
      1.000001 / 0.999999, 1e-12);
  // The u <= 1/2 (head) and u > 1/2 (tail) branches meet at u = 1/2.
  for (const double s : {0.1, 2.0}) {
    EXPECT_NEAR(sampleSurfaceNormalPolar(s, 0.5),
                sampleSurfaceNormalPolar(s, std::nextafter(0.5, 1.0)), 1e-14);
  }
}

TEST(SurfaceNormalSampling, SmallAspectRatioIsNearlySpecular) {
  // Median θs for s = 1e-6 is ~1e-6 rad; 99.99 % of normals lie within 100 s (tail ~ s²/θ²).
  Rng rng(4);
  int beyond = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) beyond += sampleSurfaceNormalPolar(1e-6, rng.uniform()) > 1e-4;
  // P(θ > 100 s) ≈ 1/(1 + 100²) ≈ 1e-4 -> 10 expected; Poisson 4σ: 10 + 4·sqrt(10) ≈ 23.
  EXPECT_LE(beyond, 23);
}

class SurfaceNormalChi2 : public ::testing::TestWithParam<double> {};

TEST_P(SurfaceNormalChi2, PolarAngleMatchesDensity) {
  const double s = GetParam();
  Rng rng(2025, static_cast<std::uint64_t>(1000 * std::fabs(std::log(s))));
  std::vector<double> thetas(500000);
  for (double& t : thetas) t = sampleSurfaceNormalPolar(s, rng.uniform());
  const auto density = [s](double t) { return surfaceNormalPolarDensity(s, t); };
  // For tiny s, bin [0, 100 s]; the rest (mass ≈ 1e-4) is the helper's "outside" bin.
  const double end = s < 0.01 ? 100.0 * s : kHalfPi;
  const auto edges = test::equalProbabilityEdges(density, 0.0, end, 50);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, density, edges))) << "s = " << s;
}

INSTANTIATE_TEST_SUITE_P(AspectRatios, SurfaceNormalChi2,
                         ::testing::Values(0.1, 0.25, 0.45, 1.0, 2.0, 1e-6));

TEST(SurfaceNormalSampling, EndPointsAreFiniteMonotoneAndBelowHalfPi) {
  for (const double s : {1e-100, 1e-30, 1e-20, 1e-6, 0.1, 0.999999, 1.0, 1.000001, 2.0, 1e10}) {
    for (const double u : {0.0, 1e-16, kOneMinusEpsilon}) {
      const double theta = sampleSurfaceNormalPolar(s, u);
      EXPECT_TRUE(std::isfinite(theta)) << "s = " << s << ", u = " << u;
      EXPECT_GE(theta, 0.0);
      EXPECT_GT(std::cos(theta), 0.0) << "θs must stay below π/2: s = " << s << ", u = " << u;
    }
    EXPECT_EQ(sampleSurfaceNormalPolar(s, 0.0), 0.0);
    double previous = 0;
    for (int k = 1; k < 100; ++k) {
      const double theta = sampleSurfaceNormalPolar(s, k / 100.0);
      EXPECT_GE(theta, previous) << "s = " << s;
      previous = theta;
    }
    EXPECT_TRUE(std::isfinite(surfaceNormalPolarDensity(s, 1e-3)));
  }
}

TEST(SurfaceNormalSampling, RejectsBadArguments) {
  EXPECT_THROW(sampleSurfaceNormalPolar(0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleSurfaceNormalPolar(-0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleSurfaceNormalPolar(1e11, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleSurfaceNormalPolar(std::nan(""), 0.5), std::invalid_argument);
  EXPECT_THROW(sampleSurfaceNormalPolar(0.3, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
