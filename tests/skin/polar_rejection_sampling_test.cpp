// The walk's rejection samplers against the densities of the inversion samplers (chi-square), for
// the paper's parameters and beyond, also with the first trial from stratified numbers; unit (cos,
// sin) pairs; the azimuth from one number; the θo = 0 and bad-argument cases.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/sampling/cosine_sampling.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "skin/sampling/polar_rejection_sampling.h"
#include "skin/sampling/surface_normal_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

constexpr double kHalfPi = 0.5 * kPi;
constexpr int kSamples = 200000;

class ExponentialPolarRejectionChi2 : public ::testing::TestWithParam<double> {};

TEST_P(ExponentialPolarRejectionChi2, MatchesAlgorithmTwoDensity) {
  const double theta0 = GetParam();
  Rng rng(11, static_cast<std::uint64_t>(1e6 * theta0));
  std::vector<double> thetas(kSamples);
  for (double& t : thetas) {
    const PolarCosSin p = sampleExponentialPolarCosSin(theta0, rng);
    ASSERT_NEAR(p.cosTheta * p.cosTheta + p.sinTheta * p.sinTheta, 1.0, 1e-12);
    ASSERT_GE(p.sinTheta, 0.0);
    t = std::atan2(p.sinTheta, p.cosTheta);
  }
  const auto density = [theta0](double t) { return exponentialPolarDensity(theta0, t); };
  // Small θo: the mass beyond 40θo is < 1e-15, so bin [0, 40θo] (the rest is the outside bin).
  const double end = std::fmin(kPi, 40.0 * theta0);
  const auto edges = test::equalProbabilityEdges(density, 0.0, end, 40);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, density, edges))) << "θo = " << theta0;
}

// 5° (the paper's visible-range value), 1°, 1e-4, the rejection limit 0.5 and the inversion
// fallback above it.
INSTANTIATE_TEST_SUITE_P(MeanAngles, ExponentialPolarRejectionChi2,
                         ::testing::Values(5.0 * kPi / 180.0, kPi / 180.0, 1e-4, 0.3, 0.5, 0.8));

TEST(ExponentialPolarRejection, ZeroMeanAngleLeavesTheDirectionAndBadAnglesThrow) {
  Rng rng(1);
  const PolarCosSin p = sampleExponentialPolarCosSin(0.0, rng);
  EXPECT_EQ(p.cosTheta, 1.0);
  EXPECT_EQ(p.sinTheta, 0.0);
  EXPECT_THROW(sampleExponentialPolarCosSin(-0.1, rng), std::invalid_argument);
  EXPECT_THROW(sampleExponentialPolarCosSin(std::nan(""), rng), std::invalid_argument);
}

/// The polar angles `thetas` drawn for aspect ratio s against Sec. 4.3's density (chi-square).
void expectSurfaceNormalDensity(double s, const std::vector<double>& thetas) {
  const auto density = [s](double t) { return surfaceNormalPolarDensity(s, t); };
  // For tiny s bin [0, 100 s]; the rest (mass ≈ 1e-4) is the outside bin.
  const double end = s < 0.01 ? 100.0 * s : kHalfPi;
  const auto edges = test::equalProbabilityEdges(density, 0.0, end, 50);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, density, edges))) << "s = " << s;
}

class SurfaceNormalRejectionChi2 : public ::testing::TestWithParam<double> {};

TEST_P(SurfaceNormalRejectionChi2, MatchesSectionFourThreeDensity) {
  const double s = GetParam();
  const SurfaceNormalPolarSampler sampler(s);
  Rng rng(12, static_cast<std::uint64_t>(1000 * std::fabs(std::log(s))));
  std::vector<double> thetas(kSamples);
  for (double& t : thetas) {
    const PolarCosSin p = sampler.sample(rng);
    ASSERT_NEAR(p.cosTheta * p.cosTheta + p.sinTheta * p.sinTheta, 1.0, 1e-12);
    ASSERT_GE(p.cosTheta, 0.0);
    ASSERT_GE(p.sinTheta, 0.0);
    t = std::atan2(p.sinTheta, p.cosTheta);
  }
  expectSurfaceNormalDensity(s, thetas);
}

// Table 1's 0.1, 0.25, 0.45; s = 1 (cosθ uniform); s > 1 (the constant-envelope branch); tiny s.
INSTANTIATE_TEST_SUITE_P(AspectRatios, SurfaceNormalRejectionChi2,
                         ::testing::Values(0.1, 0.25, 0.45, 1.0, 2.0, 30.0, 1e-6));

// The first trial from a stratified pair (a rank-1 lattice, as a pixel sampler's numbers), later
// ones from the Rng: the same law. The chi-square takes the draws as independent; stratified
// first trials only lower its statistic.
TEST_P(SurfaceNormalRejectionChi2, FirstTrialFromStratifiedNumbersKeepsTheDensity) {
  const double s = GetParam();
  const SurfaceNormalPolarSampler sampler(s);
  Rng rng(14, static_cast<std::uint64_t>(1000 * std::fabs(std::log(s))));
  std::vector<double> thetas(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const std::array<double, 2> first = {(i + 0.5) / kSamples,
                                         std::fmod(i * 0.6180339887498949, 1.0)};
    const PolarCosSin p = sampler.sample(rng, &first);
    thetas[static_cast<std::size_t>(i)] = std::atan2(p.sinTheta, p.cosTheta);
  }
  expectSurfaceNormalDensity(s, thetas);
}

TEST(SurfaceNormalRejection, RejectsAspectRatiosOutsideTheSamplersRange) {
  EXPECT_THROW(SurfaceNormalPolarSampler(0.0), std::invalid_argument);
  EXPECT_THROW(SurfaceNormalPolarSampler(1e11), std::invalid_argument);
  EXPECT_THROW(SurfaceNormalPolarSampler(std::nan("")), std::invalid_argument);
}

TEST(AzimuthFromUniform, HandValues) {
  const Azimuth zero = azimuthFromUniform(0.0), quarter = azimuthFromUniform(0.25);
  EXPECT_EQ(zero.cosPhi, 1.0);
  EXPECT_EQ(zero.sinPhi, 0.0);
  EXPECT_NEAR(quarter.cosPhi, 0.0, 1e-15);
  EXPECT_NEAR(quarter.sinPhi, 1.0, 1e-15);
  const Azimuth a = azimuthFromUniform(0.625);  // 225°
  EXPECT_NEAR(a.cosPhi, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(a.sinPhi, -std::sqrt(0.5), 1e-15);
}

TEST(DiskSamplers, AzimuthIsUniformAndMalleyDirectionsAreCosineWeighted) {
  Rng rng(13);
  std::vector<double> azimuths(kSamples), polars(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const Azimuth a = sampleAzimuth(rng);
    ASSERT_NEAR(a.cosPhi * a.cosPhi + a.sinPhi * a.sinPhi, 1.0, 1e-14);
    azimuths[static_cast<std::size_t>(i)] = std::atan2(a.sinPhi, a.cosPhi);
    const Vec3 d = sampleCosineHemisphereByDisk(rng);
    ASSERT_NEAR(dot(d, d), 1.0, 1e-14);
    ASSERT_GT(d.z, 0.0);
    polars[static_cast<std::size_t>(i)] = std::acos(d.z);
  }
  const auto uniformAzimuth = [](double) { return 1.0 / (2.0 * kPi); };
  EXPECT_TRUE(test::chi2Accepts(
      test::chi2Test1D(azimuths, uniformAzimuth, test::uniformEdges(-kPi, kPi, 60))));
  const auto cosine = [](double t) { return cosinePolarDensity(t); };
  EXPECT_TRUE(test::chi2Accepts(
      test::chi2Test1D(polars, cosine, test::equalProbabilityEdges(cosine, 0.0, kHalfPi, 50))));
}

}  // namespace
}  // namespace hylios::skin
