// Melanosome orientation (Eq. 8): chi-square of (cos α, β) about several ray directions for a
// Table 1 melanosome, a sphere and c/a = 20; hand values of the density and its inversion; the
// link between χ1, χ2 and the exact silhouette areas; end points.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/melanosome_orientation_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

const ProlateSpheroid kTableOneMelanosome{0.085, 0.205};  // 0.17 × 0.41 µm full axes (Table 1)
const ProlateSpheroid kSphere{0.1, 0.1};
const ProlateSpheroid kNeedle{0.05, 1.0};  // c/a = 20

TEST(MelanosomeOrientation, DensityByHand) {
  // a = 1, c = 2: χ1 ∝ c = 2, χ2 ∝ a = 1 -> density 2/3 at μ = 0, 1/3 at |μ| = 1, 1/2 at |μ| = 1/2.
  const ProlateSpheroid s{1.0, 2.0};
  EXPECT_NEAR(melanosomeAxisCosDensity(s, 0.0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(melanosomeAxisCosDensity(s, -1.0), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(melanosomeAxisCosDensity(s, 0.5), 0.5, 1e-15);
  EXPECT_EQ(melanosomeAxisCosDensity(s, 1.5), 0.0);
  for (const ProlateSpheroid& p : {kTableOneMelanosome, kSphere, kNeedle}) {
    EXPECT_NEAR(
        test::integrate([&](double mu) { return melanosomeAxisCosDensity(p, mu); }, -1.0, 1.0), 1.0,
        1e-12);
  }
  // A sphere has no preferred orientation: cos α uniform.
  EXPECT_NEAR(melanosomeAxisCosDensity(kSphere, 0.3), 0.5, 1e-15);
}

TEST(MelanosomeOrientation, WeightsAreTheExactSilhouetteAreasAtTheExtremes) {
  // Eq. 8 interpolates the silhouette linearly in |cos α| between χ1 (α = 90°) and χ2 (α = 0).
  for (const ProlateSpheroid& p : {kTableOneMelanosome, kNeedle}) {
    const double ratio = melanosomeAxisCosDensity(p, 0.0) / melanosomeAxisCosDensity(p, 1.0);
    EXPECT_NEAR(ratio, projectedArea(p, kPi / 2) / projectedArea(p, 0.0), 1e-12);
  }
}

TEST(MelanosomeOrientation, InversionByHand) {
  // a = 1, c = 2, u = 0.75 -> v = 0.5: m = 0.5·3/(2 + sqrt(4·0.5 + 1·0.5)) = 1.5/(2 + √2.5)
  // = 0.418861; check: (2m − m²/2)/1.5 = (0.837722 − 0.087722)/1.5 = 0.5.
  const ProlateSpheroid s{1.0, 2.0};
  EXPECT_NEAR(sampleMelanosomeAxisCos(s, 0.75), 1.5 / (2.0 + std::sqrt(2.5)), 1e-15);
  EXPECT_NEAR(sampleMelanosomeAxisCos(s, 0.25), -1.5 / (2.0 + std::sqrt(2.5)), 1e-15);
  EXPECT_EQ(sampleMelanosomeAxisCos(s, 0.0), -1.0);
  EXPECT_EQ(sampleMelanosomeAxisCos(s, 0.5), 0.0);
  // Sphere: μ = 2u − 1.
  EXPECT_NEAR(sampleMelanosomeAxisCos(kSphere, 0.9), 0.8, 1e-15);
}

struct OrientationCase {
  ProlateSpheroid spheroid;
  Vec3 rayDirection;
};

class MelanosomeOrientationChi2 : public ::testing::TestWithParam<OrientationCase> {};

TEST_P(MelanosomeOrientationChi2, AxisCosineAndAzimuthMatchEquationEight) {
  const OrientationCase c = GetParam();
  const Vec3 d = normalize(c.rayDirection);
  const Frame rayFrame(d);
  Rng rng(81, static_cast<std::uint64_t>(1e3 * c.spheroid.semiMajorAxis / c.spheroid.semiMinorAxis +
                                         10 * d.z));
  const std::size_t n = 400000;
  std::vector<double> mus(n), betas(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 axis = sampleMelanosomeAxis(c.spheroid, d, rng.uniform(), rng.uniform());
    ASSERT_NEAR(length(axis), 1.0, 1e-13);
    // Measured independently of the sampler's internals: cos α = axis·d, β about d in Frame(d).
    const Vec3 local = rayFrame.toLocal(axis);
    mus[i] = dot(axis, d);
    betas[i] = std::atan2(local.y, local.x) + (local.y < 0 ? 2 * kPi : 0.0);
  }
  const auto density = [&](double mu, double) {
    return melanosomeAxisCosDensity(c.spheroid, mu) / (2 * kPi);
  };
  EXPECT_TRUE(
      test::chi2Accepts(test::chi2Test2D(mus, betas, density, test::uniformEdges(-1.0, 1.0, 20),
                                         test::uniformEdges(0.0, 2 * kPi, 12))));
}

INSTANTIATE_TEST_SUITE_P(SpheroidsAndRays, MelanosomeOrientationChi2,
                         ::testing::Values(OrientationCase{kTableOneMelanosome, {0, 0, 1}},
                                           OrientationCase{kTableOneMelanosome, {0.48, -0.6, 0.64}},
                                           OrientationCase{kNeedle, {0, 0, -1}},
                                           OrientationCase{kNeedle, {1, 2, -0.5}},
                                           OrientationCase{kSphere, {0.3, 0.3, 0.9}}));

TEST(MelanosomeOrientation, MeanAbsoluteCosine) {
  // E|μ| = 2∫_0^1 m(c(1 − m) + a m) dm/(a + c) = (c + 2a)/(3(a + c)); Var|μ| <= 1/4 -> se <=
  // 0.5/√n.
  const ProlateSpheroid s = kNeedle;
  Rng rng(3);
  const int n = 400000;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += std::fabs(sampleMelanosomeAxisCos(s, rng.uniform()));
  const double a = s.semiMinorAxis, c = s.semiMajorAxis;
  EXPECT_NEAR(sum / n, (c + 2 * a) / (3 * (a + c)), 4 * 0.5 / std::sqrt(double(n)));
}

TEST(MelanosomeOrientation, EndPointsAreFiniteUnitVectors) {
  for (const ProlateSpheroid& p : {kTableOneMelanosome, kSphere, kNeedle}) {
    for (const double u1 : {0.0, 0.5, kOneMinusEpsilon}) {
      for (const double u2 : {0.0, kOneMinusEpsilon}) {
        const Vec3 axis = sampleMelanosomeAxis(p, {0, 0, -1}, u1, u2);
        EXPECT_TRUE(std::isfinite(axis.x) && std::isfinite(axis.y) && std::isfinite(axis.z));
        EXPECT_NEAR(length(axis), 1.0, 1e-15);
      }
      const double mu = sampleMelanosomeAxisCos(p, u1);
      EXPECT_GE(mu, -1.0);
      EXPECT_LE(mu, 1.0);
    }
  }
  EXPECT_THROW(sampleMelanosomeAxisCos(ProlateSpheroid{0.2, 0.1}, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleMelanosomeAxisCos(kSphere, 1.0), std::invalid_argument);
  EXPECT_THROW(sampleMelanosomeAxis(kSphere, {0, 0, 2}, 0.5, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
