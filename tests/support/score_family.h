// Many Monte Carlo comparisons judged as one family: a test that compares hundreds of estimates
// at a fixed 4σ fails by chance in a few per cent of seed choices (630 scores at 4σ: 4 %). Each
// score here is a difference of independent estimates over its combined standard error, ~N(0, 1)
// when the estimators agree; the family passes when every |z| stays within the two-sided bound
// that all `count` scores keep with probability 1 − falseAlarmRate (Bonferroni: each may exceed
// it with probability falseAlarmRate / count). 630 scores at 1 %: |z| ≤ 4.32.
//
// Header-only; used by the tests that compare a faster estimator with the exact one it replaces.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hylios::test {

/// The z that `comparisons` standard normal scores all stay within (|z| ≤ bound) with
/// probability at least 1 − falseAlarmRate: the two-sided tail erfc(z/√2) = rate / comparisons,
/// solved by bisection.
inline double familyWiseZ(std::size_t comparisons, double falseAlarmRate = 0.01) {
  const double perComparison = falseAlarmRate / static_cast<double>(comparisons);
  double below = 0.0, above = 40.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (below + above);
    (std::erfc(mid / std::sqrt(2.0)) > perComparison ? below : above) = mid;
  }
  return above;
}

/// z of a difference of two independent estimates over their combined standard error σ; with
/// σ = 0 it is 0 for no difference and infinite otherwise (outside any bound).
inline double zScore(double difference, double sigma) {
  return sigma > 0 ? difference / sigma : (difference == 0 ? 0.0 : INFINITY);
}

/// Collects named z scores; `expectWithinFamilyWiseBound` fails once, listing every score
/// outside the family's bound (a non-finite score is always outside).
class ScoreFamily {
 public:
  void add(std::string what, double z) { scores_.emplace_back(std::move(what), z); }
  std::size_t size() const { return scores_.size(); }

  void expectWithinFamilyWiseBound(double falseAlarmRate = 0.01) const {
    ASSERT_FALSE(scores_.empty()) << "no score was compared";
    const double bound = familyWiseZ(scores_.size(), falseAlarmRate);
    std::ostringstream failures;
    for (const auto& [what, z] : scores_)
      if (!(std::fabs(z) <= bound)) failures << what << " (z = " << z << ")\n";
    EXPECT_TRUE(failures.str().empty()) << scores_.size() << " scores, family-wise bound |z| ≤ "
                                        << bound << " (false alarm " << falseAlarmRate << "):\n"
                                        << failures.str();
  }

 private:
  std::vector<std::pair<std::string, double>> scores_;
};

}  // namespace hylios::test
