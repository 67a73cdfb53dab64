// Unpolarised Fresnel reflectance at a smooth interface, with total internal reflection, and the
// mirror / Snell directions. Plain functions in double precision, for the per-event hot path of the
// slab walk and the HyLIoS walk (paper Sec. 4: "Fresnel ... at every layer boundary").
#pragma once
#include "skin/core/vector3.h"

namespace hylios::skin {

/// Reflectance and the cosine of the transmitted angle for one crossing attempt.
struct FresnelResult {
  double reflectance = 1;  ///< unpolarised, in [0, 1]; exactly 1 under total internal reflection
  double cosTransmitted =
      0;  ///< cos of the refraction angle (>= 0); 0 under total internal reflection
};

/// Fresnel reflectance and transmitted cosine for light meeting the interface at |cosThetaIncident|
/// (the cosine between the ray and the interface normal; its sign is ignored) going from index
/// nIncident into nTransmitted. Average of the s and p intensity reflectances (Born & Wolf,
/// Sec. 1.5). Returns reflectance 0 when the indices match, 1 beyond the critical angle. Stable at
/// cos -> 0 (grazing: reflectance -> 1) and cos = 1 (normal: ((n1-n2)/(n1+n2))^2).
FresnelResult fresnel(double cosThetaIncident, double nIncident, double nTransmitted);

/// Just the reflectance of fresnel().
inline double fresnelReflectance(double cosThetaIncident, double nIncident, double nTransmitted) {
  return fresnel(cosThetaIncident, nIncident, nTransmitted).reflectance;
}

/// Mirror reflection of `direction` about the plane with unit normal `normal` (either side).
inline Vec3 reflectDirection(const Vec3& direction, const Vec3& normal) {
  return direction - normal * (2.0 * dot(direction, normal));
}

/// Snell refraction of the unit `direction` through the plane with unit `normal` (either
/// orientation) from nIncident into nTransmitted. `cosTransmitted` is fresnel(...).cosTransmitted
/// for this crossing (must not be a total internal reflection). The result is a unit vector on
/// the far side of the plane.
Vec3 refractDirection(const Vec3& direction, const Vec3& normal, double nIncident,
                      double nTransmitted, double cosTransmitted);

}  // namespace hylios::skin
