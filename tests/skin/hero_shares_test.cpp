// Hero shares by law (skin/hero_shares.h): hand values of the widths, the uniform cases, the
// draw's frequencies by chi-square against the shares, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/random.h"
#include "skin/hero_shares.h"
#include "tests/support/chi2.h"

namespace hylios::skin {
namespace {

TEST(HeroShares, WidthsByLawHandValues) {
  // θo halving from member to member, one τ: gaps ln 2 / 0.25 = 2.7726 reaches; widths
  // 1 + 1.3863, 2.7726, 1 + 1.3863 (by hand: 2.3863 / 7.5452 = 0.316267).
  const HeroShares three({0.08, 0.04, 0.02}, {1.0, 1.0, 1.0});
  ASSERT_FALSE(three.uniform());
  EXPECT_NEAR(three.shares()[0], 0.3162675, 1e-7);
  EXPECT_NEAR(three.shares()[1], 0.3674650, 1e-7);
  EXPECT_NEAR(three.shares()[2], 0.3162675, 1e-7);
  EXPECT_NEAR(three.logScaledShares()[1], std::log(3 * 0.3674650), 1e-6);
  // A member with its neighbour's law: width g/2 on its other side only (0.183733).
  const HeroShares four({0.08, 0.04, 0.04, 0.02}, {0.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(four.shares()[0], 0.3162675, 1e-7);
  EXPECT_NEAR(four.shares()[1], 0.1837325, 1e-7);
  // Both laws at once: each gap is the distance in reaches, √((ln ½/0.25)² + (ln 4/0.6)²) =
  // 3.60910; the middle member's share g/(2 + 2g) = 0.391519.
  const HeroShares both({0.08, 0.04, 0.02}, {1.0, 4.0, 16.0}, HeroShareReach{0.25, 0.6});
  EXPECT_NEAR(both.shares()[1], 0.391519, 1e-6);
  // θo = 0 for all (a point mass) leaves τ alone: ln 2/0.6 = 1.1552 between members.
  const HeroShares tauOnly({0.0, 0.0, 0.0}, {1.0, 2.0, 4.0});
  const double g = std::log(2.0) / 0.6;
  EXPECT_NEAR(tauOnly.shares()[1], g / (2 + 2 * g), 1e-12);
}

TEST(HeroShares, UniformWhereNoLawDiffersAndByDefault) {
  const HeroShares same({0.05, 0.05, 0.05}, {2.0, 2.0, 2.0});
  EXPECT_TRUE(same.uniform());
  const HeroShares plain(4);
  EXPECT_TRUE(plain.uniform());
  for (double c : plain.shares()) EXPECT_DOUBLE_EQ(c, 0.25);
  for (double l : plain.logScaledShares()) EXPECT_EQ(l, 0.0);
  // The uniform draw is the walk's former ⌊u·n⌋, so uniform bundles keep their random streams.
  EXPECT_EQ(plain.draw(0.0), 0u);
  EXPECT_EQ(plain.draw(0.2499), 0u);
  EXPECT_EQ(plain.draw(0.25), 1u);
  EXPECT_EQ(plain.draw(0.999999), 3u);
  EXPECT_EQ(HeroShares(1).draw(0.7), 0u);
}

TEST(HeroShares, DrawFollowsTheSharesChiSquare) {
  // The θo ramp's first curve bundle: 785–940 nm, θo ∝ 1400 − λ.
  std::vector<double> angle, tau;
  for (double w = 785; w <= 940; w += 5) {
    angle.push_back(0.0872665 * (1400 - w) / 620);
    tau.push_back(0.9 * std::pow(785 / w, 4));
  }
  const HeroShares shares(angle, tau);
  std::vector<double> observed(angle.size(), 0.0), expected(angle.size(), 0.0);
  Rng rng(3);
  constexpr int kDraws = 200000;
  for (int k = 0; k < kDraws; ++k) observed[shares.draw(rng.uniform())] += 1;
  for (std::size_t j = 0; j < angle.size(); ++j) expected[j] = kDraws * shares.shares()[j];
  EXPECT_TRUE(test::chi2Accepts(test::chi2FromCounts(observed, expected)));
  // The ends stand for one reach beyond the bundle: more paths than any member inside.
  EXPECT_GT(shares.shares().back(), 2 * shares.shares()[angle.size() / 2]);
}

TEST(HeroShares, RefusesBadInput) {
  EXPECT_THROW(HeroShares(0), std::invalid_argument);
  EXPECT_THROW(HeroShares({}, {}), std::invalid_argument);
  EXPECT_THROW(HeroShares({0.1, 0.2}, {1.0}), std::invalid_argument);
  EXPECT_THROW(HeroShares({0.1, -0.2}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(HeroShares({0.1, NAN}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(HeroShares({0.1, 0.2}, {1.0, INFINITY}), std::invalid_argument);
  EXPECT_THROW(HeroShares({0.1, 0.2}, {1.0, 1.0}, HeroShareReach{0.0, 0.6}), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
