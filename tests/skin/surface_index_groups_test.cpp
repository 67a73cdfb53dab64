// SurfaceIndexGroups (skin/surface_index_groups.h) against the kernels it groups
// (skin/spectral_weights.h) run on every member: the same bits for each member, from the air and
// from inside, forced or drawn, with members that share an index, with none shared, and with more
// distinct indices than the grouped form holds (the per-member fallback).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "skin/core/random.h"
#include "skin/spectral_weights.h"
#include "skin/surface_index_groups.h"

using namespace hylios::skin;

namespace {

Vec3 randomUnit(Rng& rng) {
  const double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

bool sameBits(double a, double b) {
  if (a == 0 && b == 0) return true;  // a zero's sign may differ (0 + (−0)); exp of either is 1
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectKernelsBits(const std::vector<double>& index) {
  const SurfaceIndexGroups groups(index);
  const std::size_t n = index.size();
  std::vector<double> inverse;
  for (const double v : index) inverse.push_back(1.0 / v);
  Rng rng(17, 0, n);
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 d = randomUnit(rng), t = randomUnit(rng), macro{0, 0, trial % 2 ? 1.0 : -1.0};
    const bool fromInside = trial % 4 >= 2, forced = trial % 8 >= 4;
    const double cosI = 2 * rng.uniform() - 1, aspectSquared = trial % 3 ? 0.01 : 2e5;
    std::vector<double> expectedLog(n), expectedOffset(n);
    for (std::size_t i = 0; i < n; ++i) expectedLog[i] = expectedOffset[i] = rng.uniform() - 0.5;
    std::vector<double> log = expectedLog, offset = expectedOffset;
    spectral_weights::addRefractionDensities(n, d, t, macro, index.data(), inverse.data(),
                                             fromInside, aspectSquared, forced, expectedLog.data(),
                                             expectedOffset.data());
    groups.addRefractionDensities(d, t, macro, fromInside, aspectSquared, forced, log.data(),
                                  offset.data());
    std::vector<double> expectedR(n), r(n, -1.0), expectedLogR(n, 0.25), logR(n, 0.25);
    spectral_weights::reflectances(n, cosI, index.data(), fromInside, expectedR.data());
    groups.reflectances(cosI, fromInside, r.data());
    spectral_weights::addLogReflectances(n, cosI, index.data(), fromInside, expectedLogR.data());
    groups.addLogReflectances(cosI, fromInside, logR.data());
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_TRUE(sameBits(log[i], expectedLog[i])) << "trial " << trial << ", member " << i;
      ASSERT_TRUE(sameBits(offset[i], expectedOffset[i])) << "trial " << trial << ", member " << i;
      ASSERT_TRUE(sameBits(r[i], expectedR[i])) << "trial " << trial << ", member " << i;
      ASSERT_TRUE(sameBits(logR[i], expectedLogR[i])) << "trial " << trial << ", member " << i;
    }
  }
}

}  // namespace

TEST(SurfaceIndexGroups, GroupsEqualIndicesInOrderOfFirstAppearance) {
  const SurfaceIndexGroups groups({1.57, 1.56, 1.56, 1.57, 1.55, 1.55, 1.55});
  EXPECT_EQ(groups.memberCount(), 7u);
  EXPECT_EQ(groups.groupCount(), 3u);
  const std::size_t expected[] = {0, 1, 1, 0, 2, 2, 2};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(groups.groupOf(i), expected[i]) << i;
}

TEST(SurfaceIndexGroups, SharedIndicesGiveEachMemberTheKernelsBits) {
  // Figure 1's visible band: 41 channels, runs of equal indices (Hale & Querry's three decimals).
  std::vector<double> index;
  for (int i = 0; i < 41; ++i) index.push_back(1.5712 - 0.0004 * (i / 3));
  expectKernelsBits(index);
  expectKernelsBits({1.55, 1.0, 1.55, 1.0, 2.5});  // matched indices and a dense medium
}

TEST(SurfaceIndexGroups, DistinctIndicesAndManyGroupsRunPerMember) {
  expectKernelsBits({1.55, 1.56, 1.57});
  std::vector<double> many;
  for (int i = 0; i < 100; ++i) many.push_back(1.4 + 0.001 * (i % 80));  // 80 groups > 64
  const SurfaceIndexGroups groups(many);
  EXPECT_EQ(groups.groupCount(), 80u);
  expectKernelsBits(many);
}
