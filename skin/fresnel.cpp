#include "skin/fresnel.h"

#include <cmath>

namespace hylios::skin {

FresnelResult fresnel(double cosThetaIncident, double nIncident, double nTransmitted) {
  if (nIncident == nTransmitted) return {0.0, std::fmin(1.0, std::fabs(cosThetaIncident))};
  // |cos| may exceed 1 by a rounding error when the direction is a product of rotations.
  const double cosI = std::fmin(1.0, std::fabs(cosThetaIncident));
  const double ratio = nIncident / nTransmitted;
  // Snell: sin t = (n1/n2) sin i, so cos^2 t = 1 - ratio^2 (1 - cos^2 i). Written as
  // (1 - ratio)(1 + ratio) + ratio^2 cos^2 i it keeps its accuracy near the critical angle, where
  // R depends on cos t like a square root.
  const double cosTSquared = (1.0 - ratio) * (1.0 + ratio) + ratio * ratio * cosI * cosI;
  if (cosTSquared <= 0.0) return {1.0, 0.0};  // total internal reflection
  const double cosT = std::sqrt(cosTSquared);
  // Amplitude ratios for s and p polarisation. The denominators are 0 only if cosI = cosT = 0,
  // which the TIR test above excludes.
  const double n1cosI = nIncident * cosI, n2cosT = nTransmitted * cosT;
  const double n2cosI = nTransmitted * cosI, n1cosT = nIncident * cosT;
  const double rs = (n1cosI - n2cosT) / (n1cosI + n2cosT);
  const double rp = (n1cosT - n2cosI) / (n1cosT + n2cosI);
  return {0.5 * (rs * rs + rp * rp), cosT};
}

Vec3 refractDirection(const Vec3& direction, const Vec3& normal, double nIncident,
                      double nTransmitted, double cosTransmitted) {
  const double ratio = nIncident / nTransmitted;
  const double cosI = dot(direction, normal);  // signed: > 0 if travelling along `normal`
  // Tangential part scales by n1/n2; the normal part becomes cosT on the same side as before.
  const Vec3 tangential = direction - normal * cosI;
  const double normalPart = std::copysign(cosTransmitted, cosI);
  return tangential * ratio + normal * normalPart;
}

}  // namespace hylios::skin
