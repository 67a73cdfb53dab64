#include "renderer/tracing/freckle_field.h"

#include <algorithm>
#include <cmath>

#include "skin/core/random.h"

namespace hylios {
namespace {
double hashUniform(std::uint64_t h) {
  return static_cast<double>(skin::mix64(h) >> 11) * 0x1.0p-53;
}
}  // namespace

FreckleField::FreckleField(const SkinMaterialDesc::Freckles& desc, const SourceLocation& where)
    : densityPerCm2_(desc.densityPerCm2),
      radiusCm_(desc.radiusCm),
      gain_(desc.melaninGain),
      seed_(desc.seed) {
  if (!(densityPerCm2_ >= 0) || !std::isfinite(densityPerCm2_))
    throw SceneError(where, "freckle density must be a finite number >= 0");
  if (empty()) {
    cellCm_ = 1;
    candidatesPerCell_ = 0;
    presenceProbability_ = 0;
    return;
  }
  if (!(radiusCm_ > 0) || !std::isfinite(radiusCm_))
    throw SceneError(where, "freckle radius must be > 0");
  if (!(gain_ >= 0) || !std::isfinite(gain_))
    throw SceneError(where, "freckle melanin gain must be >= 0");
  cellCm_ = 2 * radiusCm_;
  const double volumeDensity = densityPerCm2_ / (2 * radiusCm_);
  const double perCell = volumeDensity * cellCm_ * cellCm_ * cellCm_;
  if (perCell > 1e4)
    throw SceneError(where, "freckle density × radius² is too large (freckles cover everything)");
  candidatesPerCell_ = std::max(1, static_cast<int>(std::ceil(perCell)));
  presenceProbability_ = perCell / candidatesPerCell_;
}

double FreckleField::minMultiplier() const { return empty() ? 1.0 : std::min(1.0, gain_); }
double FreckleField::maxMultiplier() const { return empty() ? 1.0 : std::max(1.0, gain_); }

double FreckleField::strongestInCell(std::int64_t ix, std::int64_t iy, std::int64_t iz,
                                     const glm::dvec3& pointCm) const {
  const std::uint64_t cell =
      skin::mix64(seed_ ^ skin::mix64(static_cast<std::uint64_t>(ix)) ^
                  skin::mix64(static_cast<std::uint64_t>(iy) * 0x9E3779B97F4A7C15ULL + 1) ^
                  skin::mix64(static_cast<std::uint64_t>(iz) * 0xC2B2AE3D27D4EB4FULL + 2));
  double strongest = 0;
  for (int k = 0; k < candidatesPerCell_; ++k) {
    const std::uint64_t h = cell + 4 * static_cast<std::uint64_t>(k) * 0x632BE59BD9B4E019ULL;
    if (hashUniform(h) >= presenceProbability_) continue;
    const glm::dvec3 centre =
        (glm::dvec3(ix, iy, iz) +
         glm::dvec3(hashUniform(h + 1), hashUniform(h + 2), hashUniform(h + 3))) *
        cellCm_;
    const glm::dvec3 offset = pointCm - centre;
    const double q = glm::dot(offset, offset) / (radiusCm_ * radiusCm_);
    if (q < 1) strongest = std::max(strongest, (1 - q) * (1 - q));
  }
  return strongest;
}

double FreckleField::multiplier(const glm::dvec3& pointCm) const {
  if (empty()) return 1;
  const glm::dvec3 cellPosition = pointCm / cellCm_;
  const glm::dvec3 base = glm::floor(cellPosition);
  // A centre lies inside its cell and covers points within r = half a cell of it, so along each
  // axis only the point's own cell and the neighbour on its nearer side can hold a covering
  // freckle, and a neighbouring cell whose box is r or more away holds none: at most 8 of the 27
  // cells around the point are looked at, usually fewer.
  std::int64_t near[3];
  double gapSquared[3];  // squared distance (in cells) from the point to the near neighbour's box
  for (int a = 0; a < 3; ++a) {
    const double f = cellPosition[a] - base[a];
    near[a] = f < 0.5 ? -1 : 1;
    gapSquared[a] = f < 0.5 ? f * f : (1 - f) * (1 - f);
  }
  const auto ix = static_cast<std::int64_t>(base.x), iy = static_cast<std::int64_t>(base.y),
             iz = static_cast<std::int64_t>(base.z);
  double strongest = 0;  // largest (1 − (d/r)²)² among the freckles covering the point
  for (int corner = 0; corner < 8; ++corner) {
    double boxGapSquared = 0;
    std::int64_t step[3];
    for (int a = 0; a < 3; ++a) {
      const bool neighbour = (corner >> a) & 1;
      step[a] = neighbour ? near[a] : 0;
      boxGapSquared += neighbour ? gapSquared[a] : 0.0;
    }
    if (boxGapSquared >= 0.25) continue;  // (r / cell)² = 1/4
    strongest =
        std::max(strongest, strongestInCell(ix + step[0], iy + step[1], iz + step[2], pointCm));
  }
  return 1 + (gain_ - 1) * strongest;
}

}  // namespace hylios
