// The family-wise bound of tests/support/score_family.h against hand values of the normal law's
// quantiles, and the family's verdict on planted scores.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/support/score_family.h"

using hylios::test::familyWiseZ;
using hylios::test::ScoreFamily;

TEST(FamilyWiseZ, IsTheNormalQuantileOfTheShareOfTheFalseAlarmRate) {
  EXPECT_NEAR(familyWiseZ(1, 0.05), 1.959964, 1e-6);    // z_{0.975}
  EXPECT_NEAR(familyWiseZ(1, 0.01), 2.575829, 1e-6);    // z_{0.995}
  EXPECT_NEAR(familyWiseZ(20, 0.05), 3.023341, 1e-6);   // z_{1 − 0.00125}
  EXPECT_NEAR(familyWiseZ(630, 0.01), 4.316211, 1e-6);  // z_{1 − 7.94e-6}
  EXPECT_GT(familyWiseZ(631, 0.01), familyWiseZ(630, 0.01));
}

TEST(ScoreFamily, FailsOnAScoreOutsideTheBoundOrNotFinite) {
  ScoreFamily passing;
  for (int i = 0; i < 630; ++i) passing.add("score", 4.3);
  passing.expectWithinFamilyWiseBound();

  ScoreFamily outside;
  for (int i = 0; i < 629; ++i) outside.add("score", 0.0);
  outside.add("the planted one", 4.4);
  EXPECT_NONFATAL_FAILURE(outside.expectWithinFamilyWiseBound(), "the planted one (z = 4.4)");

  ScoreFamily notFinite;
  notFinite.add("nan", std::numeric_limits<double>::quiet_NaN());
  EXPECT_NONFATAL_FAILURE(notFinite.expectWithinFamilyWiseBound(), "nan (z = nan)");
}
