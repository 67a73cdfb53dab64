// FresnelPair against skin/fresnel.h's general formula: reflectance, transmitted cosine and the
// refracted direction, both ways through 1.4/1.7 (melanosome walls) and 1/1.55 (the skin surface).
#include <gtest/gtest.h>

#include <cmath>

#include "skin/fresnel.h"
#include "skin/fresnel_pair.h"

namespace hylios::skin {
namespace {

TEST(FresnelPair, MatchesTheGeneralFormulaAtEveryAngle) {
  for (const auto& [n1, n2] : {std::pair{1.4, 1.7}, std::pair{1.7, 1.4}, std::pair{1.0, 1.55},
                               std::pair{1.55, 1.0}, std::pair{1.33, 1.33}}) {
    const FresnelPair pair(n1, n2);
    for (int i = 0; i <= 2000; ++i) {
      const double cosI = i / 2000.0;
      double cosT = -1;
      const double r = pair.reflectance(cosI, cosT);
      const FresnelResult expected = fresnel(cosI, n1, n2);
      EXPECT_NEAR(r, expected.reflectance, 2e-15) << n1 << " -> " << n2 << ", cos " << cosI;
      EXPECT_NEAR(cosT, expected.cosTransmitted, 1e-15);
      EXPECT_NEAR(pair.reflectance(-cosI, cosT), expected.reflectance, 2e-15);  // sign ignored
    }
  }
  double cosT = -1;
  EXPECT_EQ(FresnelPair(1.7, 1.4).reflectance(0.1, cosT), 1.0);  // beyond the critical angle
  EXPECT_EQ(cosT, 0.0);
  // Normal incidence: ((n1 − n2)/(n1 + n2))² = (0.3/3.1)² by hand.
  EXPECT_NEAR(FresnelPair(1.4, 1.7).reflectance(1.0, cosT), 0.0093652445369406867, 1e-16);
}

TEST(FresnelPair, RefractsLikeSnell) {
  const Vec3 normal = normalize(Vec3{0.2, -0.1, 1.0});
  for (const double sign : {1.0, -1.0}) {
    const Vec3 n = normal * sign;  // either orientation
    const Vec3 d = normalize(Vec3{0.5, 0.3, 0.8});
    const FresnelPair pair(1.4, 1.7);
    double cosT = 0;
    pair.reflectance(dot(d, n), cosT);
    const Vec3 got = pair.refract(d, n, cosT);
    const Vec3 expected = refractDirection(d, n, 1.4, 1.7, cosT);
    EXPECT_NEAR(got.x, expected.x, 1e-15);
    EXPECT_NEAR(got.y, expected.y, 1e-15);
    EXPECT_NEAR(got.z, expected.z, 1e-15);
    EXPECT_NEAR(dot(got, got), 1.0, 1e-14);
  }
}

}  // namespace
}  // namespace hylios::skin
