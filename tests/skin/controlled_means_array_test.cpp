// ControlledMeansArray (skin/core/controlled_means_array.h): each member's sums are bit for bit
// those of a ControlledMeans fed the same paths one by one (zeros, negative scores and both folds
// included), and misuse is an error.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "skin/core/controlled_means_array.h"
#include "skin/core/random.h"
#include "tests/support/state_bytes.h"

namespace hylios::skin {
namespace {

TEST(ControlledMeansArray, EachMemberIsTheControlledMeansOfItsPaths) {
  constexpr std::size_t kMembers = 7, kQuantities = 3;
  ControlledMeansArray array(kMembers, kQuantities);
  std::vector<ControlledMeans> one(kMembers, ControlledMeans(kQuantities));
  Rng rng(5, 11, 0);
  std::vector<double> u(kMembers), t(kQuantities * kMembers);
  for (int path = 0; path < 500; ++path) {
    const unsigned fold = static_cast<unsigned>(path % 2);
    for (std::size_t i = 0; i < kMembers; ++i) {
      u[i] = 3.0 * rng.uniform();
      for (std::size_t k = 0; k < kQuantities; ++k) {
        const double x = rng.uniform();  // a third zeros, some negative (absorbed = ratio − exits)
        t[k * kMembers + i] = x < 0.33 ? 0.0 : (x < 0.5 ? -x : x * u[i]);
      }
    }
    array.beginPath(u.data(), fold);
    for (std::size_t k = 0; k < kQuantities; ++k)
      if (k != 1 || path % 3 != 0) array.add(k, &t[k * kMembers]);  // quantity 1 skipped: zeros
    for (std::size_t i = 0; i < kMembers; ++i) {
      double scores[kQuantities];
      for (std::size_t k = 0; k < kQuantities; ++k)
        scores[k] = k == 1 && path % 3 == 0 ? 0.0 : t[k * kMembers + i];
      one[i].add(scores, u[i], fold);
    }
  }
  for (std::size_t i = 0; i < kMembers; ++i) {
    const ControlledMeans member = array.member(i);
    EXPECT_EQ(member.count(), 500u);
    EXPECT_EQ(hylios::test::stateBytes(member), hylios::test::stateBytes(one[i])) << "member " << i;
    for (std::size_t k = 0; k < kQuantities; ++k) {
      EXPECT_EQ(member.estimate(k).mean, one[i].estimate(k).mean);
      EXPECT_EQ(member.estimate(k).standardError, one[i].estimate(k).standardError);
    }
  }
}

TEST(ControlledMeansArray, MisuseIsAnError) {
  ControlledMeansArray array(2, 1);
  const double u[2] = {1, 1}, t[2] = {0.5, 0.5};
  EXPECT_THROW(array.add(0, t), std::logic_error);  // before any path
  EXPECT_THROW(array.beginPath(u, 2), std::invalid_argument);
  array.beginPath(u, 1);
  EXPECT_THROW(array.add(1, t), std::invalid_argument);
  EXPECT_THROW(array.member(2), std::invalid_argument);
  array.add(0, t);
  EXPECT_EQ(array.member(1).estimate(0).mean, 0.5);
}

}  // namespace
}  // namespace hylios::skin
