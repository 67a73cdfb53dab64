#include "skin/rough_surface.h"

#include <cmath>

#include "skin/surface_normal_sampling.h"

namespace hylios::skin {
namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr int kMaxNormalRedraws = 16;
}  // namespace

Vec3 sampleFacingSurfaceNormal(const Vec3& direction, const Vec3& macroNormal, double aspectRatio,
                               Rng& rng) {
  for (int attempt = 0; attempt < kMaxNormalRedraws; ++attempt) {
    const double thetaS = sampleSurfaceNormalPolar(aspectRatio, rng.uniform());
    const double phi = kTwoPi * rng.uniform();
    const Vec3 m = perturbDirection(macroNormal, std::cos(thetaS), phi);
    if (dot(direction, m) < 0) return m;
  }
  return macroNormal;  // the macro normal always faces a ray that crosses the plane
}

InterfaceCrossing crossRoughSurface(const Vec3& direction, double nIncident, double nTransmitted,
                                    double aspectRatio, Rng& rng) {
  const double towardFar = direction.z > 0 ? 1.0 : -1.0;  // z sign of travel into the far side
  Vec3 d = direction;
  bool onFarSide = false;
  for (int attempt = 0; attempt <= kMaxSurfaceBounces; ++attempt) {
    // The ray heads toward the plane from its current side; the macro normal points back at it.
    const double headingSign = onFarSide ? -towardFar : towardFar;
    const Vec3 macroNormal{0, 0, -headingSign};
    const Vec3 m = attempt < kMaxSurfaceBounces
                       ? sampleFacingSurfaceNormal(d, macroNormal, aspectRatio, rng)
                       : macroNormal;
    const double nFrom = onFarSide ? nTransmitted : nIncident;
    const double nTo = onFarSide ? nIncident : nTransmitted;
    const InterfaceCrossing crossing = crossInterface(d, m, nFrom, nTo, rng);
    if (crossing.transmitted) onFarSide = !onFarSide;
    d = crossing.direction;
    const double awaySign = onFarSide ? towardFar : -towardFar;  // leaving the plane on this side
    if (d.z * awaySign > 0) return {d, onFarSide};
  }
  // Unreachable: the last attempt uses the macro normal, whose reflection and refraction both
  // leave the plane. Kept as a defined result rather than undefined behaviour.
  return {Vec3{d.x, d.y, std::fabs(d.z) * (onFarSide ? towardFar : -towardFar)}, onFarSide};
}

}  // namespace hylios::skin
