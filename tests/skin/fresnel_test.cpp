// Fresnel reflectance and the reflect/refract helpers against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "skin/core/constants.h"
#include "skin/fresnel.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

TEST(FresnelTest, NormalIncidenceIsSquaredIndexContrast) {
  // ((n1 - n2) / (n1 + n2))^2: air -> glass (1.5) gives (0.5 / 2.5)^2 = 0.04.
  EXPECT_NEAR(fresnelReflectance(1.0, 1.0, 1.5), 0.04, 1e-15);
  EXPECT_NEAR(fresnelReflectance(1.0, 1.5, 1.0), 0.04, 1e-15);
  // MCML sample: air -> 1.37: (0.37 / 2.37)^2 = 0.0243729...
  EXPECT_NEAR(fresnelReflectance(1.0, 1.0, 1.37), (0.37 / 2.37) * (0.37 / 2.37), 1e-15);
}

TEST(FresnelTest, FortyFiveDegreesAirToGlassMatchesSAndPFormulas) {
  // cos i = 1/sqrt2, sin t = sin i / 1.5 so cos t = sqrt(7/9) = sqrt7/3. Then
  // r_s = (cos i - 1.5 cos t) / (cos i + 1.5 cos t) = (sqrt2 - sqrt7) / (sqrt2 + sqrt7) = -0.303337
  // and at 45 deg r_p = r_s^2 = 0.0920134, so R = (r_s^2 + r_p^2) / 2 = (0.0920134 + 0.0084665)
  // / 2.
  const double rs = (std::sqrt(2.0) - std::sqrt(7.0)) / (std::sqrt(2.0) + std::sqrt(7.0));
  const double expected = 0.5 * (rs * rs + rs * rs * rs * rs);
  EXPECT_NEAR(expected, 0.0502399, 1e-7);
  const FresnelResult f = fresnel(std::cos(kPi / 4), 1.0, 1.5);
  EXPECT_NEAR(f.reflectance, expected, 1e-14);
  EXPECT_NEAR(f.cosTransmitted, std::sqrt(7.0) / 3.0, 1e-14);
}

TEST(FresnelTest, TotalInternalReflectionBeyondCriticalAngle) {
  // 1.5 -> 1.0: critical angle asin(1/1.5) = 41.81 deg.
  const double critical = std::asin(1.0 / 1.5);
  for (double angle : {critical + 1e-9, 0.75, 1.0, 1.4, kPi / 2}) {
    const FresnelResult f = fresnel(std::cos(angle), 1.5, 1.0);
    EXPECT_EQ(f.reflectance, 1.0) << "angle " << angle;
    EXPECT_EQ(f.cosTransmitted, 0.0);
  }
  EXPECT_LT(fresnelReflectance(std::cos(critical - 1e-3), 1.5, 1.0), 1.0);
  // 30 deg inside glass: sin t = 0.75, cos t = sqrt(7)/4; R = 0.0551902 (s/p by hand, Python
  // check).
  EXPECT_NEAR(fresnelReflectance(std::cos(kPi / 6), 1.5, 1.0), 0.0551902, 1e-6);
}

TEST(FresnelTest, MatchedIndicesReflectNothing) {
  for (double c : {0.0, 1e-12, 0.3, 0.7, 1.0}) {
    EXPECT_EQ(fresnelReflectance(c, 1.37, 1.37), 0.0);
    EXPECT_EQ(fresnel(c, 1.0, 1.0).cosTransmitted, c);
  }
}

TEST(FresnelTest, GrazingAndNormalLimitsAreStable) {
  EXPECT_EQ(fresnelReflectance(0.0, 1.0, 1.5), 1.0);  // grazing from the rare side: all reflected
  EXPECT_EQ(fresnelReflectance(-0.0, 1.0, 1.5), 1.0);
  const double nearlyGrazing = fresnelReflectance(1e-12, 1.0, 1.5);
  EXPECT_LT(nearlyGrazing, 1.0);
  EXPECT_GT(nearlyGrazing, 1.0 - 1e-10);
  // A cosine a rounding error above 1 behaves as normal incidence.
  EXPECT_NEAR(fresnelReflectance(1.0 + 1e-15, 1.0, 1.5), 0.04, 1e-14);
  // The sign of the cosine does not matter.
  EXPECT_EQ(fresnelReflectance(-0.6, 1.0, 1.4), fresnelReflectance(0.6, 1.0, 1.4));
}

TEST(FresnelTest, ReciprocityAndRangeOverAllAngles) {
  // R(theta_i, n1 -> n2) = R(theta_t, n2 -> n1) (Stokes relations), and 0 <= R <= 1 everywhere.
  // Near grazing the reverse crossing sits near its critical angle, where R varies like the square
  // root of cos t: a rounding error of 1e-16 in cos t moves R by up to ~1e-11, hence 1e-9.
  // (cos i = 0 exactly maps onto the critical angle itself and is left out.)
  for (int i = 1; i <= 1000; ++i) {
    const double cosI = i / 1000.0;
    for (double n2 : {1.0001, 1.33, 1.5, 2.4}) {
      const FresnelResult forward = fresnel(cosI, 1.0, n2);
      ASSERT_TRUE(forward.reflectance >= 0.0 && forward.reflectance <= 1.0);
      const FresnelResult backward = fresnel(forward.cosTransmitted, n2, 1.0);
      EXPECT_NEAR(backward.reflectance, forward.reflectance, 1e-9) << cosI << " " << n2;
    }
  }
}

TEST(FresnelTest, ReflectDirectionMirrorsAboutTheNormal) {
  const Vec3 d = normalize(Vec3{0.3, -0.4, 0.8});
  const Vec3 r = reflectDirection(d, {0, 0, 1});
  EXPECT_DOUBLE_EQ(r.x, d.x);
  EXPECT_DOUBLE_EQ(r.y, d.y);
  EXPECT_DOUBLE_EQ(r.z, -d.z);
  const Vec3 n = normalize(Vec3{1, 1, 1});
  const Vec3 r2 = reflectDirection(d, n);
  EXPECT_NEAR(length(r2), 1.0, 1e-15);
  EXPECT_NEAR(dot(r2, n), -dot(d, n), 1e-15);
}

TEST(FresnelTest, RefractDirectionObeysSnell) {
  const Vec3 normal = normalize(Vec3{0.2, -0.1, 1.0});
  const Vec3 d = normalize(Vec3{0.5, 0.3, 0.7});  // going along +normal
  const double n1 = 1.0, n2 = 1.4;
  const double cosI = dot(d, normal);
  const FresnelResult f = fresnel(cosI, n1, n2);
  const Vec3 t = refractDirection(d, normal, n1, n2, f.cosTransmitted);
  EXPECT_NEAR(length(t), 1.0, 1e-14);
  EXPECT_NEAR(dot(t, normal), f.cosTransmitted, 1e-14);  // same side as before
  const double sinI = length(cross(d, normal)), sinT = length(cross(t, normal));
  EXPECT_NEAR(n1 * sinI, n2 * sinT, 1e-14);
  EXPECT_NEAR(dot(cross(d, normal), t), 0.0, 1e-14);  // in the plane of incidence
  // Against the normal (going out the other way) it mirrors the sign.
  const Vec3 up = refractDirection(-d, normal, n1, n2, f.cosTransmitted);
  EXPECT_NEAR(dot(up, normal), -f.cosTransmitted, 1e-14);
}

}  // namespace
}  // namespace hylios::skin
