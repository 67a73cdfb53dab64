#include "skin/melanosome_path_lengths.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

#include "skin/core/random.h"
#include "skin/melanosome_internal_walk.h"

namespace hylios::skin {
namespace {
/// The table's own random stream (fixed, so a table depends on (γ, ρ, N) only).
constexpr std::uint64_t kPathLengthSeed = 0x6d656c616e6f736fULL;  // "melanoso"

void requireCoefficient(double muA_perMinorAxis) {
  if (!(muA_perMinorAxis >= 0 && std::isfinite(muA_perMinorAxis)))
    throw std::invalid_argument("MelanosomePathLengths: interior coefficient × a = " +
                                std::to_string(muA_perMinorAxis) + " is negative or not finite");
}

void requireTableInputs(double aspect, double indexRatio, std::size_t sampleCount) {
  if (!(aspect >= 1.0 && aspect <= 1e6))
    throw std::invalid_argument("MelanosomePathLengths: aspect c/a = " + std::to_string(aspect) +
                                " is outside [1, 1e6]");
  if (!(indexRatio > 0 && std::isfinite(indexRatio)))
    throw std::invalid_argument("MelanosomePathLengths: index ratio n_melanin/n_layer = " +
                                std::to_string(indexRatio) + " is not positive and finite");
  if (sampleCount < 2)
    throw std::invalid_argument("MelanosomePathLengths: need at least 2 samples, got " +
                                std::to_string(sampleCount));
}
}  // namespace

MelanosomePathLengths::MelanosomePathLengths(double aspect, double indexRatio,
                                             std::size_t sampleCount)
    : aspect_(aspect), indexRatio_(indexRatio) {
  requireTableInputs(aspect, indexRatio, sampleCount);
  MelanosomeGeometry geometry;
  geometry.aspect = aspect;
  geometry.inverseAspect = 1.0 / aspect;
  geometry.entering = FresnelPair(1.0, indexRatio);
  geometry.leaving = FresnelPair(indexRatio, 1.0);
  Rng rng(kPathLengthSeed);
  lengths_.resize(sampleCount);
  for (double& length : lengths_) {
    double sum = 0;
    const MelanosomeWalkEnd end = walkInsideMelanosome(geometry, rng, [&sum](double chord) {
      sum += chord;
      return false;  // no absorption: the whole path
    });
    if (end == MelanosomeWalkEnd::ReflectedAtEntry) ++reflectedAtEntry_;
    length = sum;
  }
  singleLengths_.assign(lengths_.begin(), lengths_.end());
}

double MelanosomePathLengths::absorptionProbability(double muA_perMinorAxis) const {
  requireCoefficient(muA_perMinorAxis);
  double sum = 0;
  for (double length : lengths_) sum -= std::expm1(-muA_perMinorAxis * length);
  return sum / static_cast<double>(lengths_.size());
}

double MelanosomePathLengths::survivalProbability(double muA_perMinorAxis) const {
  requireCoefficient(muA_perMinorAxis);
  double sum = 0;
  for (double length : lengths_) sum += std::exp(-muA_perMinorAxis * length);
  return sum / static_cast<double>(lengths_.size());
}

double MelanosomePathLengths::absorptionProbability(double muA_perMinorAxis, unsigned count) const {
  if (count == 0) return 0.0;
  return absorptionByCount(absorptionProbability(muA_perMinorAxis), count);
}

double MelanosomePathLengths::absorptionByCount(double oneMelanosome, unsigned count) {
  if (!(oneMelanosome >= 0.0 && oneMelanosome <= 1.0))
    throw std::invalid_argument("MelanosomePathLengths::absorptionByCount: probability " +
                                std::to_string(oneMelanosome) + " is outside [0, 1]");
  if (count == 0) return 0.0;
  // p1 = 1 gives log1p(−1) = −∞ and the result 1.
  return -std::expm1(static_cast<double>(count) * std::log1p(-oneMelanosome));
}

Estimate MelanosomePathLengths::meanPathLength() const {
  RunningStatistic statistic;
  for (double length : lengths_) statistic.add(length);
  return statistic.estimate();
}

double MelanosomePathLengths::reflectedAtEntryFraction() const {
  return static_cast<double>(reflectedAtEntry_) / static_cast<double>(lengths_.size());
}

std::shared_ptr<const MelanosomePathLengths> MelanosomePathLengths::shared(
    double aspect, double indexRatio, std::size_t sampleCount) {
  requireTableInputs(aspect, indexRatio, sampleCount);  // before any comparison (NaN keys)
  using Key = std::tuple<double, double, std::size_t>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const MelanosomePathLengths>> tables;
  const std::lock_guard<std::mutex> lock(mutex);
  const Key key{aspect, indexRatio, sampleCount};
  auto it = tables.find(key);
  if (it != tables.end()) return it->second;
  // Built under the lock (a few milliseconds, once per key); a constructor that throws stores
  // nothing.
  auto table = std::make_shared<const MelanosomePathLengths>(aspect, indexRatio, sampleCount);
  tables.emplace(key, table);
  return table;
}

double melanosomeTableKey(double x) {
  const double scale = std::pow(10.0, 11 - std::floor(std::log10(x)));
  return std::round(x * scale) / scale;
}

}  // namespace hylios::skin
