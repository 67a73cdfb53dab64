// Fresnel reflectance and refraction for one fixed pair of refractive indices, with the ratios
// precomputed: the same unpolarised formula as skin/fresnel.h (average of the s and p intensity
// reflectances, total internal reflection), with one division per call instead of three. Used on
// the walk's hot paths (melanosome walls) where the indices never change.
#pragma once
#include <cmath>

#include "skin/core/vector3.h"

namespace hylios::skin {

class FresnelPair {
 public:
  FresnelPair() = default;
  /// Light going from index nIncident into nTransmitted (both > 0).
  FresnelPair(double nIncident, double nTransmitted)
      : ratio_(nIncident / nTransmitted),
        ratioSquared_(ratio_ * ratio_),
        oneMinusRatioSquared_((1.0 - ratio_) * (1.0 + ratio_)),
        relative_(nTransmitted / nIncident),
        matched_(nIncident == nTransmitted) {}

  /// n1 = n2: no interface.
  bool matched() const { return matched_; }
  /// η = n1/n2, the factor of a refracted direction's tangential part.
  double ratio() const { return ratio_; }

  /// Reflectance at |cosIncident| (sign ignored); cosTransmitted receives the refraction cosine
  /// (0 under total internal reflection, where the reflectance is exactly 1). Matched indices
  /// give 0, as fresnel() does.
  double reflectance(double cosIncident, double& cosTransmitted) const {
    const double c = std::fabs(cosIncident) < 1.0 ? std::fabs(cosIncident) : 1.0;
    if (matched_) {  // no interface (also at grazing incidence)
      cosTransmitted = c;
      return 0.0;
    }
    // Snell: cos²t = (1 − η)(1 + η) + η²cos²i, accurate near the critical angle.
    const double cosTSquared = oneMinusRatioSquared_ + ratioSquared_ * c * c;
    if (cosTSquared <= 0.0) {
      cosTransmitted = 0.0;
      return 1.0;
    }
    const double t = std::sqrt(cosTSquared);
    cosTransmitted = t;
    // rs = (c − m t)/(c + m t), rp = (t − m c)/(t + m c), m = n2/n1; R = (rs² + rp²)/2.
    const double sNumerator = c - relative_ * t, sDenominator = c + relative_ * t;
    const double pNumerator = t - relative_ * c, pDenominator = t + relative_ * c;
    const double sN2 = sNumerator * sNumerator, sD2 = sDenominator * sDenominator;
    const double pN2 = pNumerator * pNumerator, pD2 = pDenominator * pDenominator;
    return 0.5 * (sN2 * pD2 + pN2 * sD2) / (sD2 * pD2);
  }

  /// Snell refraction of unit `direction` through the plane of unit `normal` (either orientation)
  /// given cosTransmitted from reflectance() (not a total internal reflection).
  Vec3 refract(const Vec3& direction, const Vec3& normal, double cosTransmitted) const {
    const double cosI = dot(direction, normal);  // signed
    const double normalPart = cosI > 0 ? cosTransmitted : -cosTransmitted;
    return direction * ratio_ + normal * (normalPart - ratio_ * cosI);
  }

 private:
  double ratio_ = 1;                 // η = n1/n2
  double ratioSquared_ = 1;          // η²
  double oneMinusRatioSquared_ = 0;  // 1 − η²
  double relative_ = 1;              // m = n2/n1
  bool matched_ = true;              // n1 = n2
};

}  // namespace hylios::skin
