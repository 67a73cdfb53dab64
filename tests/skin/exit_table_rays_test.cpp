// Walks per cosine bin by use (skin/exit_table_rays.h): the rule against hand values, the use
// estimate against Snell's law on a smooth surface, and tables built by use against tables built
// with every bin full (the same walks where a bin keeps them all).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "skin/core/constants.h"
#include "skin/exit_table.h"
#include "skin/exit_table_rays.h"
#include "skin/skin_optics.h"
#include "skin/specimen.h"
#include "tests/support/test_spectra.h"

using namespace hylios;
using namespace hylios::skin;

namespace {

TEST(ExitTableRays, RuleGivesHandValues) {
  // N_k = ceil(N · clamp((u / 0.1)², 1/64, 1)), at least 2.
  const std::vector<std::uint64_t> rays = raysByUse({0.2, 0.1, 0.05, 0.03, 0.01, 0.0}, 10000);
  const std::vector<std::uint64_t> expected{10000, 10000, 2500, 900, 157, 157};
  EXPECT_EQ(rays, expected);
  EXPECT_EQ(raysByUse({0.0, 0.05}, 100), (std::vector<std::uint64_t>{2, 25}));
  EXPECT_EQ(raysByUse({0.0, 1.0}, 2), (std::vector<std::uint64_t>{2, 2}));
}

TEST(ExitTableRays, UseOfASmoothSurfaceFollowsSnellsLaw) {
  // A smooth surface refracts every entered ray of an angle to one cosine, so a bin's use at that
  // angle is its linear-interpolation weight exactly; the worst case is the largest over the grid.
  WalkOptions smooth;
  smooth.roughSurface = false;
  const SkinWalk walk(test::s1Optics(550), smooth);
  const double n = walk.optics().layers[0].refractiveIndex;
  const int bins = 12;
  std::vector<double> expected(bins, 0.0);
  for (int g = 0; g < kUseAngles; ++g) {
    const double sinI = std::sin(0.5 * kPi * (g + 0.5) / kUseAngles);
    const double x = std::sqrt(1 - sinI * sinI / (n * n)) * bins - 1;
    if (x >= bins - 1) {
      expected.back() = 1;
      continue;
    }
    const auto k = static_cast<std::size_t>(x);
    const double upper = x - static_cast<double>(k);
    expected[k] = std::max(expected[k], 1 - upper);
    expected[k + 1] = std::max(expected[k + 1], upper);
  }
  const std::vector<double> use = worstCaseBinUse(walk, bins, 1);
  ASSERT_EQ(use.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(use[k], expected[k], 1e-9) << "bin " << k;
  // Below the critical cone (μ_t < √(1 − 1/n²) ≈ 0.76) no smooth entry reaches a bin.
  EXPECT_EQ(use[0], 0.0);
  EXPECT_EQ(use[7], 0.0);
}

TEST(ExitTableRays, RoughSurfaceS1ThinsOnlyTheLowBins) {
  const SkinWalk walk(test::s1Optics(550));
  const std::vector<double> use = worstCaseBinUse(walk, 12, 1);
  EXPECT_EQ(use, worstCaseBinUse(walk, 12, 1));  // deterministic
  // Tilted facets reach every bin, the low ones rarely (s = 0.1): ≈ 1 % for bins 0–3.
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_GT(use[k], 0.0) << k;
    EXPECT_LT(use[k], 0.03) << k;
  }
  for (std::size_t k = 8; k < 12; ++k) EXPECT_GT(use[k], 0.3) << k;
  const std::vector<std::uint64_t> rays = raysByUse(use, 10000);
  for (std::size_t k = 7; k < 12; ++k) EXPECT_EQ(rays[k], 10000u) << k;
  const std::uint64_t total = std::accumulate(rays.begin(), rays.end(), std::uint64_t{0});
  EXPECT_LT(total, 70000u);  // about half the 120 000 walks of equal bins
}

TEST(ExitTableRays, TablesByUseKeepTheFullBinsAndThinTheOthers) {
  const SkinWalk walk(test::s1Optics(450));
  ExitTableSettings equal;
  equal.raysPerBin = 3000;
  ExitTableSettings byUse = equal;
  byUse.raysByUse = true;
  const std::vector<std::uint64_t> rays = ExitTable::raysOfBins(walk, byUse);
  const ExitTable a = ExitTable::build(walk, equal), b = ExitTable::build(walk, byUse);
  EXPECT_NE(a.key(), b.key());
  int full = 0, thinned = 0;
  for (int k = 0; k < equal.cosineBins; ++k) {
    const BinStatistics x = a.statistics(k), y = b.statistics(k);
    EXPECT_EQ(y.rays, rays[static_cast<std::size_t>(k)]) << k;
    if (y.rays == equal.raysPerBin) {  // the same walks, so the same numbers
      ++full;
      EXPECT_EQ(x.subsurface.mean, y.subsurface.mean) << k;
      EXPECT_EQ(x.meanExitRadiusCm.mean, y.meanExitRadiusCm.mean) << k;
    } else {  // the first N_k of the same walks: within the thinned bin's own error
      ++thinned;
      EXPECT_NEAR(y.subsurface.mean, x.subsurface.mean, 4 * y.subsurface.standardError) << k;
    }
  }
  EXPECT_GE(full, 5);
  EXPECT_GE(thinned, 4);
  const auto path = std::filesystem::path(HYLIOS_BINARY_DIR) / "exit_table_rays_test.hxt";
  b.write(path);
  std::string why;
  const auto read = ExitTable::read(path, walk, byUse, &why);
  ASSERT_TRUE(read) << why;
  for (int k = 0; k < equal.cosineBins; ++k)
    EXPECT_EQ(read->statistics(k).rays, rays[static_cast<std::size_t>(k)]);
  EXPECT_FALSE(ExitTable::read(path, walk, equal, &why));  // another key
}

}  // namespace
