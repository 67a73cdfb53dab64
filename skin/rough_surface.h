// The rough air / stratum-corneum interface (paper Sec. 4.3): each crossing attempt perturbs the
// surface normal with the polar density P_s(θs) of aspect ratio s (uniform azimuth) and makes a
// Fresnel test on the perturbed normal. Used in both directions (entering and leaving the skin).
//
// Where the paper is silent (docs/interpretations.md): a sampled normal that faces away from the
// ray is redrawn; a reflected ray that still points into the surface, or a refracted ray that
// points back, meets the surface again (a new normal, a new Fresnel test), so no energy is lost.
// After kMaxSurfaceBounces attempts the smooth macro-surface normal is used, which always ends it.
//
// θs is drawn by the rejection sampler of skin/sampling/polar_rejection_sampling.h (same density as
// skin/sampling/surface_normal_sampling.h's inversion, several times cheaper); RoughSurface keeps
// its constants for one aspect ratio, the free functions build one per call.
#pragma once
#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/interface_crossing.h"
#include "skin/sampling/polar_rejection_sampling.h"

namespace hylios::skin {

inline constexpr int kMaxSurfaceBounces = 64;
/// Facet normals drawn per attempt until one faces the ray; after that the macro normal is used.
inline constexpr int kMaxFacetRedraws = 16;

class RoughSurface {
 public:
  /// Throws std::invalid_argument for s outside [1e-100, 1e10].
  explicit RoughSurface(double aspectRatio);
  /// See crossRoughSurface.
  InterfaceCrossing cross(const Vec3& direction, double nIncident, double nTransmitted,
                          Rng& rng) const;
  /// See sampleFacingSurfaceNormal.
  Vec3 facingNormal(const Vec3& direction, const Vec3& macroNormal, Rng& rng) const;

 private:
  SurfaceNormalPolarSampler polar_;
};

/// A ray travelling along `direction` (direction.z ≠ 0) meets the plane z = 0 going from index
/// nIncident into nTransmitted. transmitted = true means it ends on the far side.
InterfaceCrossing crossRoughSurface(const Vec3& direction, double nIncident, double nTransmitted,
                                    double aspectRatio, Rng& rng);

/// A microfacet normal about `macroNormal` (unit, pointing to the side the ray comes from), drawn
/// from P_s with aspect ratio s, facing the ray (dot(direction, m) < 0).
Vec3 sampleFacingSurfaceNormal(const Vec3& direction, const Vec3& macroNormal, double aspectRatio,
                               Rng& rng);

}  // namespace hylios::skin
