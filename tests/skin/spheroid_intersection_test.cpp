// Ray / spheroid geometry (Sec. 4.2.2 hit points): entry points uniform over the silhouette
// (chi-square in the ellipse's normalised radius² and angle), entry points on the surface facing
// the ray, normals, exit distances by hand for a sphere and for c/a = 20, the mean chord V/A.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/spheroid_intersection.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

/// x²/a² + y²/a² + z²/c² in the body frame, computed from the axis without the library's frame.
double normalisedRadiusSquared(const ProlateSpheroid& s, const Vec3& axis, const Vec3& p) {
  const double along = dot(p, axis);
  const double acrossSquared = dot(p, p) - along * along;
  return acrossSquared / (s.semiMinorAxis * s.semiMinorAxis) +
         along * along / (s.semiMajorAxis * s.semiMajorAxis);
}

/// Gradient of the above, normalised: p/a² + (p·axis)(1/c² − 1/a²) axis.
Vec3 expectedNormal(const ProlateSpheroid& s, const Vec3& axis, const Vec3& p) {
  const double ia2 = 1 / (s.semiMinorAxis * s.semiMinorAxis);
  const double ic2 = 1 / (s.semiMajorAxis * s.semiMajorAxis);
  return normalize(p * ia2 + axis * (dot(p, axis) * (ic2 - ia2)));
}

struct SilhouetteCase {
  ProlateSpheroid spheroid;
  Vec3 axis;
  Vec3 direction;
};

class SilhouetteChi2 : public ::testing::TestWithParam<SilhouetteCase> {};

TEST_P(SilhouetteChi2, EntryPointsAreUniformOverTheSilhouetteAndOnTheSurface) {
  const SilhouetteCase c = GetParam();
  const Vec3 axis = normalize(c.axis), d = normalize(c.direction);
  const double a = c.spheroid.semiMinorAxis, cc = c.spheroid.semiMajorAxis;
  // The silhouette ellipse, built here from geometry alone: semi-axis a along e1 ⟂ (axis, d),
  // semi-axis b = sqrt(a²cos²α + c²sin²α) along e2 = d × e1.
  const double cosAlpha = dot(axis, d);
  const double b = std::sqrt(a * a * cosAlpha * cosAlpha + cc * cc * (1 - cosAlpha * cosAlpha));
  const Vec3 across = cross(axis, d);
  const Vec3 e1 = length(across) > 1e-9 ? normalize(across) : Frame(d).t;
  const Vec3 e2 = cross(d, e1);
  Rng rng(55, static_cast<std::uint64_t>(100 * cc / a + 1000 * std::fabs(cosAlpha)));
  const std::size_t n = 300000;
  std::vector<double> radiusSquared(n), angle(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SpheroidSurfacePoint hit =
        sampleSilhouetteEntry(c.spheroid, axis, d, rng.uniform(), rng.uniform());
    ASSERT_NEAR(normalisedRadiusSquared(c.spheroid, axis, hit.position), 1.0, 1e-12);
    ASSERT_LT(dot(hit.outwardNormal, d), 0.0) << "the entry point must face the ray";
    const Vec3 n0 = expectedNormal(c.spheroid, axis, hit.position);
    ASSERT_NEAR(dot(hit.outwardNormal, n0), 1.0, 1e-12);
    const double x = dot(hit.position, e1) / a, y = dot(hit.position, e2) / b;
    radiusSquared[i] = x * x + y * y;
    angle[i] = std::atan2(y, x) + (y < 0 ? 2 * kPi : 0.0);
  }
  const auto uniform = [](double, double) { return 1.0 / (2 * kPi); };
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test2D(radiusSquared, angle, uniform,
                                                 test::uniformEdges(0.0, 1.0, 15),
                                                 test::uniformEdges(0.0, 2 * kPi, 16))));
  // The library's area agrees with π a b and with spheroid.h's projectedArea.
  EXPECT_NEAR(spheroidSilhouetteArea(c.spheroid, axis, d), kPi * a * b, 1e-12 * kPi * a * b);
  EXPECT_NEAR(spheroidSilhouetteArea(c.spheroid, axis, d),
              projectedArea(c.spheroid, std::acos(std::fmin(1.0, std::fabs(cosAlpha)))),
              1e-9 * kPi * a * b);
}

INSTANTIATE_TEST_SUITE_P(
    ShapesAndViews, SilhouetteChi2,
    ::testing::Values(SilhouetteCase{{1.0, 1.0}, {0, 0, 1}, {0.2, 0.3, 0.9}},  // sphere
                      SilhouetteCase{{0.085, 0.205}, {0, 0, 1}, {0, 0, 1}},    // along axis
                      SilhouetteCase{{0.085, 0.205}, {1, 1, 0}, {0, 0, -1}},   // α = 90°
                      SilhouetteCase{{0.085, 0.205}, {0.3, -0.5, 0.8}, {0.6, 0, 0.8}},
                      SilhouetteCase{{0.05, 1.0}, {0, 1, 0}, {0.6, 0.8, 0}},  // c/a = 20
                      SilhouetteCase{{0.05, 1.0}, {0, 0, 1}, {0, 0, -1}}));

TEST(SpheroidIntersection, ExitDistanceForASphereByHand) {
  const ProlateSpheroid sphere{2.0, 2.0};
  const Vec3 axis{0, 0, 1};
  // From (0.5, 0, 0) along +z: sqrt(4 − 0.25) = 1.9364916731037085, exit (0.5, 0, 1.93649),
  // normal = exit / 2.
  const SpheroidExit e = distanceToSpheroidExit(sphere, axis, {0.5, 0, 0}, {0, 0, 1});
  EXPECT_NEAR(e.distance, 1.9364916731037085, 1e-15);
  EXPECT_NEAR(e.position.z, 1.9364916731037085, 1e-15);
  EXPECT_NEAR(e.outwardNormal.x, 0.25, 1e-15);
  EXPECT_NEAR(e.outwardNormal.z, 1.9364916731037085 / 2, 1e-15);
  // From the centre, any direction: the radius.
  EXPECT_NEAR(distanceToSpheroidExit(sphere, axis, {0, 0, 0}, normalize(Vec3{1, -2, 2})).distance,
              2.0, 1e-15);
  // From (0, 0, −1) along +x: sqrt(4 − 1) = √3.
  EXPECT_NEAR(distanceToSpheroidExit(sphere, axis, {0, 0, -1}, {1, 0, 0}).distance, std::sqrt(3.0),
              1e-15);
}

TEST(SpheroidIntersection, ExitDistanceForANeedleByHand) {
  // a = 0.05, c = 1 (c/a = 20), axis along (1, 1, 0)/√2.
  const ProlateSpheroid needle{0.05, 1.0};
  const Vec3 axis = normalize(Vec3{1, 1, 0});
  EXPECT_NEAR(distanceToSpheroidExit(needle, axis, {0, 0, 0}, axis).distance, 1.0, 1e-15);
  EXPECT_NEAR(distanceToSpheroidExit(needle, axis, {0, 0, 0}, {0, 0, 1}).distance, 0.05, 1e-15);
  // From 0.6 c along the axis, straight across (z): a·sqrt(1 − 0.36) = 0.05·0.8 = 0.04.
  EXPECT_NEAR(distanceToSpheroidExit(needle, axis, axis * 0.6, {0, 0, -1}).distance, 0.04, 1e-15);
  // A surface point heading outward leaves at once; heading inward crosses the whole chord.
  const Vec3 tip = axis * 1.0;
  EXPECT_NEAR(distanceToSpheroidExit(needle, axis, tip, axis).distance, 0.0, 1e-15);
  EXPECT_NEAR(distanceToSpheroidExit(needle, axis, tip, -axis).distance, 2.0, 1e-14);
}

TEST(SpheroidIntersection, MeanChordIsVolumeOverSilhouetteArea) {
  // Cauchy: for lines uniform over the silhouette, E[chord] = V / A. c/a = 20 seen side-on:
  // V = (4/3)πa²c, A = πac, E = 4a/3. The chord's standard error is estimated from the sample.
  const ProlateSpheroid needle{0.05, 1.0};
  const Vec3 axis{0, 1, 0}, d{0.6, 0, 0.8};
  const double expected = volume(needle) / spheroidSilhouetteArea(needle, axis, d);
  Rng rng(9);
  const int n = 200000;
  double sum = 0, sumSquares = 0;
  for (int i = 0; i < n; ++i) {
    const SpheroidSurfacePoint hit =
        sampleSilhouetteEntry(needle, axis, d, rng.uniform(), rng.uniform());
    const SpheroidExit e = distanceToSpheroidExit(needle, axis, hit.position, d);
    ASSERT_NEAR(normalisedRadiusSquared(needle, axis, e.position), 1.0, 1e-9);
    ASSERT_GT(dot(e.outwardNormal, d), 0.0) << "the exit point must face away from the ray";
    sum += e.distance;
    sumSquares += e.distance * e.distance;
  }
  const double mean = sum / n;
  const double standardError = std::sqrt((sumSquares / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, expected, 4 * standardError);
  // Side-on, V/A = 4a/3 by hand.
  EXPECT_NEAR(expected, 4 * 0.05 / 3, 1e-12);
}

TEST(SpheroidIntersection, EndPointsAndBadInputs) {
  const ProlateSpheroid needle{0.05, 1.0};
  const Vec3 axis = normalize(Vec3{0, 1, 1});
  for (const double u1 : {0.0, kOneMinusEpsilon}) {
    for (const double u2 : {0.0, kOneMinusEpsilon}) {
      for (const Vec3& d : {Vec3{0, 0, 1}, axis, Vec3{1, 0, 0}}) {
        const SpheroidSurfacePoint hit = sampleSilhouetteEntry(needle, axis, d, u1, u2);
        EXPECT_TRUE(std::isfinite(hit.position.x) && std::isfinite(hit.position.y) &&
                    std::isfinite(hit.position.z));
        EXPECT_NEAR(length(hit.outwardNormal), 1.0, 1e-14);
        EXPECT_LE(dot(hit.outwardNormal, d), 0.0);
        EXPECT_NEAR(normalisedRadiusSquared(needle, axis, hit.position), 1.0, 1e-12);
      }
    }
  }
  EXPECT_THROW(distanceToSpheroidExit(needle, axis, {0.5, 0, 0}, {0, 0, 1}), std::invalid_argument);
  EXPECT_THROW(sampleSilhouetteEntry(needle, axis, {0, 0, 2}, 0.1, 0.1), std::invalid_argument);
  EXPECT_THROW(sampleSilhouetteEntry(needle, {0, 0, 0.5}, {0, 0, 1}, 0.1, 0.1),
               std::invalid_argument);
  EXPECT_THROW(sampleSilhouetteEntry(needle, axis, {0, 0, 1}, 1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(spheroidOutwardNormal(needle, axis, {0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
