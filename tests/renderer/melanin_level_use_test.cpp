// The melanin levels' shares of a skin material (renderer/tracing/melanin_level_use.h) against
// closed forms, the walks per level they give, and SkinTableCache building each level's tables
// with its own number of walks.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "renderer/scene/data_paths.h"
#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/melanin_level_use.h"
#include "renderer/tracing/skin_table_cache.h"
#include "skin/core/constants.h"
#include "tests/support/test_folder.h"
#include "tests/support/test_spectra.h"

using namespace hylios;

namespace {

using hylios::test::spectra;

skin::Specimen s1() { return skin::loadSpecimen("S1", specimenDir()); }

FreckleField freckles(double densityPerCm2, double radiusCm, double gain) {
  SkinMaterialDesc::Freckles desc;
  desc.densityPerCm2 = densityPerCm2;
  desc.radiusCm = radiusCm;
  desc.melaninGain = gain;
  desc.seed = 3;
  return FreckleField(desc, {});
}

TEST(MelaninLevelUse, OneLevelTakesEverything) {
  const SkinWalkCache walks(s1(), 1, 1, {550}, spectra(), {}, SkinTableCache::kTableMelaninLevels);
  ASSERT_EQ(walks.levels(), 1);
  EXPECT_EQ(melaninLevelUse(walks, nullptr, 1, 1, freckles(0, 0.2, 4)), std::vector<double>{1.0});
}

TEST(MelaninLevelUse, FrecklesGiveTheirMeanMultiplier) {
  // Stochastic rounding keeps the mean: Σ_l use_l·m_l = E[m] over the plane. For freckles rare
  // enough not to overlap (density 0.25 cm⁻², r = 0.2 cm: 2 % of the plane), E[m] − 1 =
  // (g − 1)·ρ_v·∫_ball (1 − (d/r)²)² dV = (g − 1)·density·(16π/105)·r² (ρ_v = density/2r) =
  // 3·0.25·0.47872·0.04 = 0.014362. Each sample point is one rounded multiplier m_l, so the
  // shares give the per-point variance Σ use_l·m_l² − mean² and σ(mean) = √(variance/samples)
  // (about 6e-4 here); tolerance 4σ.
  const double density = 0.25, radius = 0.2, gain = 4;
  const FreckleField field = freckles(density, radius, gain);
  const SkinWalkCache walks(s1(), field.minMultiplier(), field.maxMultiplier(), {550}, spectra(),
                            {}, SkinTableCache::kTableMelaninLevels);
  const std::vector<double> use = melaninLevelUse(walks, nullptr, 1, 1, field);
  ASSERT_EQ(use.size(), 7u);
  EXPECT_NEAR(std::accumulate(use.begin(), use.end(), 0.0), 1.0, 1e-12);
  double mean = 0, square = 0;
  for (int l = 0; l < walks.levels(); ++l) {
    const double m = walks.levelMultiplier(l);
    mean += use[static_cast<std::size_t>(l)] * m;
    square += use[static_cast<std::size_t>(l)] * m * m;
  }
  const double sigma = std::sqrt((square - mean * mean) / static_cast<double>(kMelaninUseSamples));
  const double expected = (gain - 1) * density * (16 * kPi / 105) * radius * radius;
  EXPECT_NEAR(mean - 1, expected, 4 * sigma) << "sigma " << sigma;
  EXPECT_LT(sigma, 1e-3);
  EXPECT_GT(use[0], 0.95);  // the skin between the freckles
}

TEST(MelaninLevelUse, AConstantMapRoundsBetweenItsTwoLevels) {
  // Every texel 0.5 between multipliers 1 and 3: m = 2 everywhere, between levels k and k + 1 with
  // P(k + 1) = (2 − m_k)/(m_{k+1} − m_k); binomial σ = √(p(1 − p)/65536), tolerance 4σ.
  const TextureMap map(2, 2, {0.5f, 0.5f, 0.5f, 0.5f});
  const SkinWalkCache walks(s1(), 1, 3, {550}, spectra(), {}, SkinTableCache::kTableMelaninLevels);
  const std::vector<double> use = melaninLevelUse(walks, &map, 1, 3, freckles(0, 0.2, 4));
  int below = 0;
  while (walks.levelMultiplier(below + 1) < 2) ++below;
  const double mBelow = walks.levelMultiplier(below), mAbove = walks.levelMultiplier(below + 1);
  const double p = (2 - mBelow) / (mAbove - mBelow);
  const double sigma = std::sqrt(p * (1 - p) / static_cast<double>(kMelaninUseSamples));
  EXPECT_NEAR(use[static_cast<std::size_t>(below) + 1], p, 4 * sigma);
  EXPECT_NEAR(use[static_cast<std::size_t>(below)], 1 - p, 4 * sigma);
  for (int l = 0; l < walks.levels(); ++l) {
    if (l != below && l != below + 1) {
      EXPECT_EQ(use[static_cast<std::size_t>(l)], 0.0) << l;
    }
  }
}

TEST(LevelRayShares, SquareRootOfTheUseAtLeastAQuarter) {
  const std::vector<double> shares = levelRayShares({0.81, 0.09, 0.01, 0.0, 0.09});
  const std::vector<double> expected{1.0, 1.0 / 3, 0.25, 0.25, 1.0 / 3};
  ASSERT_EQ(shares.size(), expected.size());
  for (std::size_t l = 0; l < shares.size(); ++l) EXPECT_NEAR(shares[l], expected[l], 1e-15) << l;
  EXPECT_THROW(levelRayShares({}), std::invalid_argument);
  EXPECT_THROW(levelRayShares({0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(levelRayShares({0.5, -0.1}), std::invalid_argument);
  EXPECT_THROW(levelRayShares({0.5, std::nan("")}), std::invalid_argument);
}

TEST(SkinTableCache, EachLevelGetsItsShareOfTheWalks) {
  const std::filesystem::path folder = hylios::test::freshTestFolder("hylios_level_tables_");
  ExitTableCache cache(folder);
  const SkinWalkCache walks(s1(), 1, 4, {550}, spectra(), {}, 2);
  skin::ExitTableSettings settings = SkinTableCache::renderSettings(40);
  settings.raysByUse = false;  // every bin keeps N: the table's own ray count shows the share
  const SkinTableCache tables(walks, cache, settings, false, {1.0, 0.25});
  EXPECT_EQ(tables.raysPerBinByLevel(), (std::vector<std::uint64_t>{40, 10}));
  EXPECT_EQ(tables.describeRaysPerBin(walks), "x1 40, x4 10");
  EXPECT_EQ(tables.table(0, 0).settings().raysPerBin, 40u);
  EXPECT_EQ(tables.table(0, 1).settings().raysPerBin, 10u);
  EXPECT_THROW(SkinTableCache(walks, cache, settings, false, {1.0}), std::invalid_argument);
  EXPECT_THROW(SkinTableCache(walks, cache, settings, false, {1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(SkinTableCache(walks, cache, settings, false, {1.0, 1.5}), std::invalid_argument);
  std::filesystem::remove_all(folder);
}

}  // namespace
