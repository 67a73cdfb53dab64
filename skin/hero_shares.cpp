#include "skin/hero_shares.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hylios::skin {
namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("hero shares: " + what);
}

/// ln(b/a) / reach where the law varies (both positive and different), else 0.
double lawStep(double a, double b, double reach) {
  return a > 0 && b > 0 && a != b ? std::log(b / a) / reach : 0.0;
}
}  // namespace

HeroShares::HeroShares(std::size_t members)
    : shares_(members, members > 0 ? 1.0 / static_cast<double>(members) : 0.0),
      logScaledShares_(members, 0.0) {
  require(members > 0, "a bundle of no members");
}

HeroShares::HeroShares(const std::vector<double>& meanAngleRad,
                       const std::vector<double>& rayleighDepth, const HeroShareReach& reach) {
  const std::size_t n = meanAngleRad.size();
  require(n > 0 && rayleighDepth.size() == n,
          std::to_string(n) + " angles and " + std::to_string(rayleighDepth.size()) +
              " Rayleigh depths (one of each per member, at least one member)");
  for (std::size_t i = 0; i < n; ++i)
    require(std::isfinite(meanAngleRad[i]) && meanAngleRad[i] >= 0 &&
                std::isfinite(rayleighDepth[i]) && rayleighDepth[i] >= 0,
            "member " + std::to_string(i) + " has θo " + std::to_string(meanAngleRad[i]) +
                " and τ " + std::to_string(rayleighDepth[i]) + " (both must be finite, ≥ 0)");
  require(std::isfinite(reach.logAngle) && reach.logAngle > 0 &&
              std::isfinite(reach.logRayleighDepth) && reach.logRayleighDepth > 0,
          "the reaches must be positive and finite");
  std::vector<double> width(n, 0.0);
  double gaps = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double gap =
        std::hypot(lawStep(meanAngleRad[i], meanAngleRad[i + 1], reach.logAngle),
                   lawStep(rayleighDepth[i], rayleighDepth[i + 1], reach.logRayleighDepth));
    width[i] += 0.5 * gap;
    width[i + 1] += 0.5 * gap;
    gaps += gap;
  }
  if (gaps == 0) {  // one law for all (or one member): uniform shares
    *this = HeroShares(n);
    return;
  }
  width.front() += 1.0;  // one reach beyond each end
  width.back() += 1.0;
  double total = 0;
  for (double& w : width) total += (w = std::max(w, kLeastWidth));
  shares_.resize(n);
  cumulative_.resize(n);
  logScaledShares_.resize(n);
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    shares_[i] = width[i] / total;
    sum += shares_[i];
    cumulative_[i] = sum;
    logScaledShares_[i] = std::log(static_cast<double>(n) * shares_[i]);
  }
  cumulative_.back() = 1.0;
  uniform_ = false;
}

std::size_t HeroShares::draw(double u) const {
  const std::size_t n = shares_.size();
  if (uniform_) return std::min(n - 1, static_cast<std::size_t>(u * static_cast<double>(n)));
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  return std::min(n - 1, static_cast<std::size_t>(it - cumulative_.begin()));
}

}  // namespace hylios::skin
