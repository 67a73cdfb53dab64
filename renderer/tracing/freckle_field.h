// Procedural freckles: seeded random spots that raise (or lower) the melanin content of skin.
//
// Freckle centres form a random point set in 3-D space (in cm), built on a jittered grid of cell
// size 2·radius: each cell holds K = ceil(λ) candidate centres at hashed uniform positions, each
// present with probability λ/K, where λ = ρ_v·(2r)³ and ρ_v = densityPerCm2 / (2r) is the volume
// density. A locally flat surface then meets, on average, densityPerCm2 centres per cm² within
// distance r of it (those are the visible freckles). A freckle changes the melanin multiplier by
//   m(d) = 1 + (gain − 1)·(1 − (d/r)²)²   for 3-D distance d < r (1 outside),
// and where freckles overlap the one with the largest |m − 1| wins. Everything follows from
// (seed, cell) through skin::mix64, so the pattern is the same at any thread count and any run.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

#include "renderer/scene/scene.h"

namespace hylios {

class FreckleField {
 public:
  /// Throws SceneError at `where` for a negative density or gain or a non-positive radius.
  FreckleField(const SkinMaterialDesc::Freckles& desc, const SourceLocation& where);

  bool empty() const { return !(densityPerCm2_ > 0); }
  double densityPerCm2() const { return densityPerCm2_; }
  /// The melanin multiplier at a point in cm (1 away from freckles).
  double multiplier(const glm::dvec3& pointCm) const;
  /// Range of multiplier(): [min(1, gain), max(1, gain)].
  double minMultiplier() const;
  double maxMultiplier() const;

 private:
  /// The largest (1 − (d/r)²)² among the freckles of grid cell (ix, iy, iz) covering the point.
  double strongestInCell(std::int64_t ix, std::int64_t iy, std::int64_t iz,
                         const glm::dvec3& pointCm) const;

  double densityPerCm2_, radiusCm_, gain_;
  std::uint64_t seed_;
  double cellCm_;
  int candidatesPerCell_;
  double presenceProbability_;
};

}  // namespace hylios
