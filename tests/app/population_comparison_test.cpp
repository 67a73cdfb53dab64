// A modelled curve against a measured population's group (app/population_comparison.h), on a
// hand-made population whose envelope and excesses are worked out below.
#include <gtest/gtest.h>

#include "app/population_comparison.h"

namespace hylios {
namespace {

/// Three subjects on 300, 500 and 1000 nm: lowest / median / highest are 0.1/0.2/0.3 at 300 nm,
/// 0.3/0.4/0.5 at 500 nm and 0.5/0.6/0.7 at 1000 nm.
SkinPopulation threeSubjects() {
  const std::vector<double> w = {300, 500, 1000};
  return SkinPopulation{
      {{"a", w, {0.1, 0.5, 0.6}}, {"b", w, {0.2, 0.3, 0.7}}, {"c", w, {0.3, 0.4, 0.5}}}};
}

TEST(PopulationComparison, CountsInsideAndFindsTheLargestExcessPerRegion) {
  const std::vector<double> w = {300, 500, 1000};
  // 300 nm: 0.35 is 0.05 above the highest, 2σ = 0.02 does not reach; 500 nm: 0.29 is 0.01 below
  // the lowest, within 2σ = 0.02 (inside); 1000 nm: 0.8 is 0.1 above the highest.
  const std::vector<skin::Estimate> model = {{0.35, 0.01}, {0.29, 0.01}, {0.8, 0.01}};
  const PopulationComparison c =
      compareWithPopulation("S9", w, model, 8, threeSubjects(), {0, 1, 2}, "all");
  ASSERT_EQ(c.regions.size(), 4u);  // 250–314, 400–704, 705–1304 nm hold one each, then all
  EXPECT_DOUBLE_EQ(c.regions[0].firstNm, 300);
  EXPECT_EQ(c.regions[0].inside, 0u);
  EXPECT_NEAR(c.regions[0].worstExcess, 0.05, 1e-12);
  EXPECT_NEAR(c.regions[0].rmsToMedian, 0.15, 1e-12);
  EXPECT_EQ(c.regions[1].inside, 1u);
  EXPECT_EQ(c.regions[1].worstExcess, 0.0);
  EXPECT_NEAR(c.regions[2].worstExcess, 0.1, 1e-12);
  const PopulationRegion& all = c.regions.back();
  EXPECT_EQ(all.count, 3u);
  EXPECT_EQ(all.inside, 1u);
  EXPECT_DOUBLE_EQ(all.worstExcessNm, 1000);
  EXPECT_NEAR(all.rmsToMedian, std::sqrt((0.15 * 0.15 + 0.11 * 0.11 + 0.2 * 0.2) / 3), 1e-12);
  // Below the range: a negative excess.
  const PopulationComparison dark = compareWithPopulation("S9", w, {{0.05, 0}, {0.4, 0}, {0.6, 0}},
                                                          8, threeSubjects(), {0, 1, 2}, "all");
  EXPECT_NEAR(dark.regions.back().worstExcess, -0.05, 1e-12);
}

TEST(PopulationComparison, TableHasARowPerComparisonAndAColumnPerRegion) {
  const std::vector<double> w = {300, 500, 1000};
  const std::vector<skin::Estimate> model = {{0.35, 0.01}, {0.29, 0.01}, {0.8, 0.01}};
  const SkinPopulation p = threeSubjects();
  const std::string md =
      populationTable({compareWithPopulation("S9", w, model, 8, p, {0, 1, 2}, "all"),
                       compareWithPopulation("S9", w, model, 8, p, {0}, "a")});
  EXPECT_NE(md.find("| comparison | 300–300 nm | 500–500 nm | 1000–1000 nm | 300–1000 nm |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| S9 vs all, 8° | 0/1 (+0.0500 at 300) | 1/1 | 0/1 (+0.1000 at 1000) |"),
            std::string::npos)
      << md;
  EXPECT_THROW(populationTable({compareWithPopulation("S9", w, model, 8, p, {0}, "a"),
                                compareWithPopulation("S9", {300}, {{0.1, 0}}, 8, p, {0}, "a")}),
               std::invalid_argument);
}

TEST(PopulationComparison, BadRequestsAreErrors) {
  const SkinPopulation p = threeSubjects();
  EXPECT_THROW(compareWithPopulation("S9", {300, 500}, {{0.1, 0}}, 8, p, {0}, "a"),
               std::invalid_argument);
  EXPECT_THROW(compareWithPopulation("S9", {300}, {{0.1, 0}}, 8, p, {}, "a"),
               std::invalid_argument);
  EXPECT_THROW(compareWithPopulation("S9", {200}, {{0.1, 0}}, 8, p, {0}, "a"), std::out_of_range);
  EXPECT_THROW(compareWithPopulation("S9", {500, 300}, {{0.1, 0}, {0.1, 0}}, 8, p, {0}, "a"),
               std::invalid_argument);
}

}  // namespace
}  // namespace hylios
