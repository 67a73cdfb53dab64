// Interface crossing: Fresnel decision with one uniform, directions, and random-number use.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "skin/fresnel.h"
#include "skin/interface_crossing.h"

namespace hylios::skin {
namespace {

// True if `a` and `b` are at the same point of their streams.
bool sameState(Rng a, Rng b) { return a.nextU64() == b.nextU64(); }

TEST(InterfaceCrossingTest, MatchedIndicesPassStraightThroughWithoutRandomNumbers) {
  Rng rng(7), reference(7);
  const Vec3 d = normalize(Vec3{0.2, 0.1, -0.9});
  const InterfaceCrossing c = crossPlaneInterfaceZ(d, 1.37, 1.37, rng);
  EXPECT_TRUE(c.transmitted);
  EXPECT_EQ(c.direction.x, d.x);
  EXPECT_EQ(c.direction.y, d.y);
  EXPECT_EQ(c.direction.z, d.z);
  EXPECT_TRUE(sameState(rng, reference));
  const InterfaceCrossing g = crossInterface(d, normalize(Vec3{0.1, 0, 1}), 1.4, 1.4, rng);
  EXPECT_TRUE(g.transmitted);
  EXPECT_TRUE(sameState(rng, reference));
}

TEST(InterfaceCrossingTest, TotalInternalReflectionMirrorsWithoutRandomNumbers) {
  Rng rng(3), reference(3);
  const Vec3 d = normalize(Vec3{0.9, 0.0, 0.3});  // 71.6 deg from the normal, critical 41.8 deg
  const InterfaceCrossing c = crossPlaneInterfaceZ(d, 1.5, 1.0, rng);
  EXPECT_FALSE(c.transmitted);
  EXPECT_EQ(c.direction.x, d.x);
  EXPECT_EQ(c.direction.z, -d.z);
  EXPECT_TRUE(sameState(rng, reference));
}

TEST(InterfaceCrossingTest, OtherwiseExactlyOneUniformIsDrawn) {
  Rng rng(11), reference(11);
  crossPlaneInterfaceZ(normalize(Vec3{0.3, 0.2, 0.9}), 1.0, 1.5, rng);
  reference.uniform();
  EXPECT_TRUE(sameState(rng, reference));
}

TEST(InterfaceCrossingTest, TransmittedFractionIsOneMinusFresnel) {
  // 45 deg in air onto 1.5: R = 0.0502399 (fresnel_test). N = 200000 trials: sigma of the
  // transmitted fraction = sqrt(R (1 - R) / N) = 4.9e-4; tolerance 4 sigma.
  const Vec3 d = normalize(Vec3{1.0, 0.0, -1.0});  // travelling upward into the medium above
  const double reflectance = fresnelReflectance(d.z, 1.0, 1.5);
  Rng rng(2024);
  const int trials = 200000;
  int transmitted = 0;
  for (int i = 0; i < trials; ++i) {
    const InterfaceCrossing c = crossPlaneInterfaceZ(d, 1.0, 1.5, rng);
    if (c.transmitted) {
      ++transmitted;
      EXPECT_LT(c.direction.z, 0.0);
    } else {
      EXPECT_GT(c.direction.z, 0.0);
    }
  }
  const double sigma = std::sqrt(reflectance * (1 - reflectance) / trials);
  EXPECT_NEAR(static_cast<double>(transmitted) / trials, 1.0 - reflectance, 4 * sigma);
}

TEST(InterfaceCrossingTest, RefractedDirectionIsUnitAndObeysSnell) {
  Rng rng(5);
  const Vec3 d = normalize(Vec3{0.4, -0.3, 0.6});
  for (int i = 0; i < 100; ++i) {
    const InterfaceCrossing c = crossPlaneInterfaceZ(d, 1.37, 1.0, rng);
    if (!c.transmitted) continue;
    EXPECT_NEAR(length(c.direction), 1.0, 1e-15);
    EXPECT_GT(c.direction.z, 0.0);
    const double sinI = std::hypot(d.x, d.y), sinT = std::hypot(c.direction.x, c.direction.y);
    EXPECT_NEAR(1.37 * sinI, 1.0 * sinT, 1e-15);
  }
}

TEST(InterfaceCrossingTest, GeneralNormalAgreesWithThePlaneZVersion) {
  const Vec3 d = normalize(Vec3{0.2, 0.5, 0.7});
  for (const Vec3& normal : {Vec3{0, 0, 1}, Vec3{0, 0, -1}}) {
    Rng a(99), b(99);
    for (int i = 0; i < 1000; ++i) {
      const InterfaceCrossing z = crossPlaneInterfaceZ(d, 1.0, 1.4, a);
      const InterfaceCrossing g = crossInterface(d, normal, 1.0, 1.4, b);
      ASSERT_EQ(z.transmitted, g.transmitted);
      EXPECT_NEAR(z.direction.x, g.direction.x, 1e-15);
      EXPECT_NEAR(z.direction.y, g.direction.y, 1e-15);
      EXPECT_NEAR(z.direction.z, g.direction.z, 1e-15);
    }
  }
}

TEST(InterfaceCrossingTest, PrecomputedIndexPairCrossesAsTheIndices) {
  // The FresnelPair overload (the spectral walk's layer interfaces): the same decision, random
  // numbers and direction to rounding, for matched, refracting and totally reflecting pairs.
  for (const auto& [n1, n2] : {std::pair{1.37, 1.37}, {1.34, 1.5}, {1.5, 1.34}, {1.5, 1.0}}) {
    const FresnelPair pair(n1, n2);
    for (int k = 0; k < 200; ++k) {
      const double z = (k % 2 == 0 ? 1.0 : -1.0) * (0.005 + 0.99 * k / 200.0);
      const double r = std::sqrt(1.0 - z * z);
      const Vec3 d{0.6 * r, 0.8 * r, z};
      Rng a(k), b(k);
      const InterfaceCrossing byIndices = crossPlaneInterfaceZ(d, n1, n2, a);
      const InterfaceCrossing byPair = crossPlaneInterfaceZ(d, pair, b);
      EXPECT_EQ(byPair.transmitted, byIndices.transmitted) << n1 << " -> " << n2 << ", z " << z;
      EXPECT_NEAR(byPair.direction.x, byIndices.direction.x, 1e-14);
      EXPECT_NEAR(byPair.direction.y, byIndices.direction.y, 1e-14);
      EXPECT_NEAR(byPair.direction.z, byIndices.direction.z, 1e-14);
      EXPECT_TRUE(sameState(a, b));
    }
  }
}

}  // namespace
}  // namespace hylios::skin
