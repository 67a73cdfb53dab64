#include "skin/rough_surface.h"

#include <cmath>

namespace hylios::skin {

RoughSurface::RoughSurface(double aspectRatio) : polar_(aspectRatio) {}

Vec3 RoughSurface::facingNormal(const Vec3& direction, const Vec3& macroNormal, Rng& rng) const {
  for (int attempt = 0; attempt < kMaxFacetRedraws; ++attempt) {
    const PolarCosSin theta = polar_.sample(rng);
    const Azimuth phi = sampleAzimuth(rng);
    const Vec3 m =
        directionAbout(macroNormal, theta.cosTheta, theta.sinTheta, phi.cosPhi, phi.sinPhi);
    if (dot(direction, m) < 0) return m;
  }
  return macroNormal;  // the macro normal always faces a ray that crosses the plane
}

InterfaceCrossing RoughSurface::cross(const Vec3& direction, double nIncident, double nTransmitted,
                                      Rng& rng) const {
  const double towardFar = direction.z > 0 ? 1.0 : -1.0;  // z sign of travel into the far side
  Vec3 d = direction;
  bool onFarSide = false;
  for (int attempt = 0; attempt <= kMaxSurfaceBounces; ++attempt) {
    // The ray heads toward the plane from its current side; the macro normal points back at it.
    const double headingSign = onFarSide ? -towardFar : towardFar;
    const Vec3 macroNormal{0, 0, -headingSign};
    const Vec3 m = attempt < kMaxSurfaceBounces ? facingNormal(d, macroNormal, rng) : macroNormal;
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

InterfaceCrossing crossRoughSurface(const Vec3& direction, double nIncident, double nTransmitted,
                                    double aspectRatio, Rng& rng) {
  return RoughSurface(aspectRatio).cross(direction, nIncident, nTransmitted, rng);
}

Vec3 sampleFacingSurfaceNormal(const Vec3& direction, const Vec3& macroNormal, double aspectRatio,
                               Rng& rng) {
  return RoughSurface(aspectRatio).facingNormal(direction, macroNormal, rng);
}

}  // namespace hylios::skin
