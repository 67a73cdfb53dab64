#include "renderer/tracing/light_selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "skin/core/constants.h"
#include "skin/core/random.h"

namespace hylios {
namespace {

constexpr std::uint64_t kReceiverSeed = 0x6c69676874ULL;  // "light": the points' fixed stream

}  // namespace

std::vector<double> lightSelectionProbabilities(const std::vector<double>& contribution) {
  const std::size_t n = contribution.size();
  std::vector<double> p(n, n > 0 ? 1.0 / static_cast<double>(n) : 0.0);
  const double total = std::accumulate(contribution.begin(), contribution.end(), 0.0);
  if (!(total > 0) || !std::isfinite(total)) return p;
  for (std::size_t i = 0; i < n; ++i)
    p[i] = (1 - kDefensiveLightShare) * contribution[i] / total +
           kDefensiveLightShare / static_cast<double>(n);
  return p;
}

std::vector<glm::dvec3> receiverPoints(const EmbreeScene& geometry,
                                       const std::vector<std::size_t>& shapes) {
  std::vector<double> areaCdf;
  double total = 0;
  for (std::size_t shape : shapes) areaCdf.push_back(total += geometry.shapeArea(shape));
  std::vector<glm::dvec3> points;
  if (!(total > 0)) return points;
  skin::Rng rng(kReceiverSeed);
  for (int i = 0; i < kReceiverPoints; ++i) {
    const double u = (i + rng.uniform()) / kReceiverPoints * total;  // stratified over the area
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(areaCdf.begin(), areaCdf.end(), u) -
                                 areaCdf.begin()),
        shapes.size() - 1);
    points.push_back(
        geometry.sampleArea(shapes[k], rng.uniform(), rng.uniform(), rng.uniform()).position);
  }
  return points;
}

double areaLightSolidAngle(const EmbreeScene& geometry, std::size_t shape,
                           const glm::dvec3& receiver, std::size_t receiverIndex) {
  skin::Rng rng(kReceiverSeed, 1 + shape, receiverIndex);
  double sum = 0;
  for (int k = 0; k < kLightPoints; ++k) {
    const AreaSample a = geometry.sampleArea(shape, rng.uniform(), rng.uniform(), rng.uniform());
    const glm::dvec3 toReceiver = receiver - a.position;
    const double d2 = glm::dot(toReceiver, toReceiver);
    if (!(d2 > 0)) return kPi;  // the receiver lies on the light
    const double cosLight = glm::dot(a.normal, toReceiver) / std::sqrt(d2);
    if (cosLight > 0) sum += cosLight / (d2 * a.pdfArea);
  }
  return std::min(kPi, sum / kLightPoints);
}

}  // namespace hylios
