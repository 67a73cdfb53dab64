// Drawing an index from a finite list of non-negative weights through their running sums (the
// exit tables' outcomes, offset cells and polar bins).
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace hylios::skin {

/// Running sums of `weights` (cdf[i] = weights[0] + … + weights[i]).
inline std::vector<double> cumulativeWeights(const std::vector<double>& weights) {
  std::vector<double> cdf(weights.size());
  double total = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) cdf[i] = total += weights[i];
  return cdf;
}

/// Index i with probability weights[i] / total, for u uniform in [0, 1) and cdf the running sums
/// (cdf.back() > 0); never an entry of weight 0.
inline std::size_t pickCumulative(const std::vector<double>& cdf, double u) {
  const double target = u * cdf.back();
  auto i = static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin());
  if (i < cdf.size()) return i;
  i = cdf.size() - 1;  // u·total rounded up to the total: the last entry of positive weight
  while (i > 0 && cdf[i] == cdf[i - 1]) --i;
  return i;
}

}  // namespace hylios::skin
