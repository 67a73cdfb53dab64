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

double FreckleField::multiplier(const glm::dvec3& pointCm) const {
  if (empty()) return 1;
  const glm::dvec3 cellPosition = pointCm / cellCm_;
  const glm::dvec3 base = glm::floor(cellPosition);
  double strongest = 0;  // largest (1 − (d/r)²)² among the freckles covering the point
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto ix = static_cast<std::int64_t>(base.x) + dx,
                   iy = static_cast<std::int64_t>(base.y) + dy,
                   iz = static_cast<std::int64_t>(base.z) + dz;
        const std::uint64_t cell =
            skin::mix64(seed_ ^ skin::mix64(static_cast<std::uint64_t>(ix)) ^
                        skin::mix64(static_cast<std::uint64_t>(iy) * 0x9E3779B97F4A7C15ULL + 1) ^
                        skin::mix64(static_cast<std::uint64_t>(iz) * 0xC2B2AE3D27D4EB4FULL + 2));
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
      }
  return 1 + (gain_ - 1) * strongest;
}

}  // namespace hylios
