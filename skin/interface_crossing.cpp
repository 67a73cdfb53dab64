#include "skin/interface_crossing.h"

#include <cmath>

#include "skin/fresnel.h"

namespace hylios::skin {

InterfaceCrossing crossPlaneInterfaceZ(const Vec3& direction, double nIncident, double nTransmitted,
                                       Rng& rng) {
  if (nIncident == nTransmitted) return {direction, true};
  const FresnelResult f = fresnel(direction.z, nIncident, nTransmitted);
  if (f.reflectance >= 1.0 || rng.uniform() < f.reflectance)
    return {{direction.x, direction.y, -direction.z}, false};
  const double ratio = nIncident / nTransmitted;
  return {{direction.x * ratio, direction.y * ratio, std::copysign(f.cosTransmitted, direction.z)},
          true};
}

InterfaceCrossing crossPlaneInterfaceZ(const Vec3& direction, const FresnelPair& indices,
                                       Rng& rng) {
  if (indices.matched()) return {direction, true};
  double cosTransmitted = 0;
  const double reflectance = indices.reflectance(direction.z, cosTransmitted);
  if (reflectance >= 1.0 || rng.uniform() < reflectance)
    return {{direction.x, direction.y, -direction.z}, false};
  const double ratio = indices.ratio();
  return {{direction.x * ratio, direction.y * ratio, std::copysign(cosTransmitted, direction.z)},
          true};
}

InterfaceCrossing crossInterface(const Vec3& direction, const Vec3& normal, double nIncident,
                                 double nTransmitted, Rng& rng) {
  if (nIncident == nTransmitted) return {direction, true};
  const FresnelResult f = fresnel(dot(direction, normal), nIncident, nTransmitted);
  if (f.reflectance >= 1.0 || rng.uniform() < f.reflectance)
    return {reflectDirection(direction, normal), false};
  return {refractDirection(direction, normal, nIncident, nTransmitted, f.cosTransmitted), true};
}

}  // namespace hylios::skin
