#include "skin/spheroid.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {}

void checkProlateSpheroid(const ProlateSpheroid& s) {
  const double a = s.semiMinorAxis;
  const double c = s.semiMajorAxis;
  if (!std::isfinite(a) || !std::isfinite(c) || !(a > 0) || !(a <= c))
    throw std::invalid_argument("prolate spheroid needs 0 < a <= c (finite); got a = " +
                                std::to_string(a) + ", c = " + std::to_string(c));
}

double arcsinOverArgument(double b) {
  if (!(b >= 0 && b <= 1))
    throw std::invalid_argument("arcsinOverArgument: b = " + std::to_string(b) +
                                " is outside [0, 1]");
  // Below 1e-3 the series 1 + b²/6 + 3b⁴/40 + 5b⁶/112 is exact to double precision
  // (next term 35b⁸/1152 < 1e-25), while asin(b)/b would divide 0 by 0 at b = 0.
  if (b < 1e-3) {
    const double b2 = b * b;
    return 1.0 + b2 * (1.0 / 6.0 + b2 * (3.0 / 40.0 + b2 * (5.0 / 112.0)));
  }
  return std::asin(b) / b;
}

double eccentricity(const ProlateSpheroid& s) {
  checkProlateSpheroid(s);
  const double a = s.semiMinorAxis;
  const double c = s.semiMajorAxis;
  return std::sqrt((c - a) * (c + a)) / c;
}

double surfaceToVolumeRatio(const ProlateSpheroid& s) {
  const double b = eccentricity(s);  // checks s
  const double a = s.semiMinorAxis;
  const double c = s.semiMajorAxis;
  return 3.0 / (2.0 * a) * (a / c + arcsinOverArgument(b));  // Eq. 7
}

double surfaceArea(const ProlateSpheroid& s) {
  const double b = eccentricity(s);
  const double a = s.semiMinorAxis;
  const double c = s.semiMajorAxis;
  return 2.0 * kPi * a * a * (1.0 + (c / a) * arcsinOverArgument(b));
}

double volume(const ProlateSpheroid& s) {
  checkProlateSpheroid(s);
  return 4.0 / 3.0 * kPi * s.semiMinorAxis * s.semiMinorAxis * s.semiMajorAxis;
}

double crossSectionNormalToMajorAxis(const ProlateSpheroid& s) {
  checkProlateSpheroid(s);
  return kPi * s.semiMinorAxis * s.semiMinorAxis;
}

double crossSectionContainingMajorAxis(const ProlateSpheroid& s) {
  checkProlateSpheroid(s);
  return kPi * s.semiMinorAxis * s.semiMajorAxis;
}

double projectedArea(const ProlateSpheroid& s, double alphaRad) {
  checkProlateSpheroid(s);
  if (!std::isfinite(alphaRad)) throw std::invalid_argument("projectedArea: angle is not finite");
  const double a = s.semiMinorAxis;
  const double c = s.semiMajorAxis;
  const double cosA = std::cos(alphaRad);
  const double sinA = std::sin(alphaRad);
  return kPi * a * std::sqrt(a * a * cosA * cosA + c * c * sinA * sinA);
}

}  // namespace hylios::skin
