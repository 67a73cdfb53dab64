#include "skin/spheroid_intersection.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {

constexpr double kSurfaceTolerance = 1e-6;  // in the normalised radius² of the unit-sphere image

void requireUnit(const Vec3& v, const char* what, const char* where) {
  const double lengthSquared = dot(v, v);
  if (!(std::fabs(lengthSquared - 1.0) <= 1e-6)) {
    throw std::invalid_argument(std::string(where) + ": " + what + " has length² " +
                                std::to_string(lengthSquared) + ", expected a unit vector");
  }
}

/// Body frame: z along the symmetry axis. Maps to and from the unit-sphere image.
struct SpheroidFrame {
  Frame body;
  double a, c;

  SpheroidFrame(const ProlateSpheroid& s, const Vec3& axis, const char* where)
      : body(axis), a(s.semiMinorAxis), c(s.semiMajorAxis) {
    checkProlateSpheroid(s);
    requireUnit(axis, "axis", where);
  }
  /// World vector -> its image under diag(1/a, 1/a, 1/c) in the body frame.
  Vec3 toUnitSphere(const Vec3& world) const {
    const Vec3 local = body.toLocal(world);
    return {local.x / a, local.y / a, local.z / c};
  }
  Vec3 fromUnitSphere(const Vec3& image) const {
    return body.toWorld({image.x * a, image.y * a, image.z * c});
  }
  /// Outward normal at the surface point whose unit-sphere image is `image`: the gradient of
  /// x²/a² + y²/a² + z²/c², i.e. (image.x/a, image.y/a, image.z/c) in the body frame.
  Vec3 normalAtImage(const Vec3& image) const {
    return normalize(body.toWorld({image.x / a, image.y / a, image.z / c}));
  }
};

}  // namespace

double spheroidSilhouetteArea(const ProlateSpheroid& spheroid, const Vec3& axis,
                              const Vec3& direction) {
  const SpheroidFrame frame(spheroid, axis, "spheroidSilhouetteArea");
  requireUnit(direction, "direction", "spheroidSilhouetteArea");
  const double cosAlpha = dot(direction, axis);
  const double sin2Alpha = std::fmax(0.0, (1.0 - cosAlpha) * (1.0 + cosAlpha));  // rounding only
  const double a = frame.a, c = frame.c;
  return kPi * a * std::sqrt(a * a * cosAlpha * cosAlpha + c * c * sin2Alpha);
}

SpheroidSurfacePoint sampleSilhouetteEntry(const ProlateSpheroid& spheroid, const Vec3& axis,
                                           const Vec3& direction, double u1, double u2) {
  const SpheroidFrame frame(spheroid, axis, "sampleSilhouetteEntry");
  requireUnit(direction, "direction", "sampleSilhouetteEntry");
  requireUniformSample(u1, "sampleSilhouetteEntry (u1)");
  requireUniformSample(u2, "sampleSilhouetteEntry (u2)");
  // In the unit-sphere image the ray travels along n; pick a point uniform on the unit disk
  // normal to n and step back to the sphere's near side: depth sqrt(1 − r²) = sqrt(1 − u1) > 0.
  const Vec3 n = normalize(frame.toUnitSphere(direction));
  const Frame disk(n);
  const double r = std::sqrt(u1);
  const double phi = kTwoPi * u2;
  const Vec3 image = disk.toWorld({r * std::cos(phi), r * std::sin(phi), -std::sqrt(1.0 - u1)});
  return {frame.fromUnitSphere(image), frame.normalAtImage(image)};
}

Vec3 spheroidOutwardNormal(const ProlateSpheroid& spheroid, const Vec3& axis,
                           const Vec3& surfacePoint) {
  const SpheroidFrame frame(spheroid, axis, "spheroidOutwardNormal");
  const Vec3 image = frame.toUnitSphere(surfacePoint);
  if (!(dot(image, image) > 0.0)) {
    throw std::invalid_argument("spheroidOutwardNormal: the centre has no normal");
  }
  return frame.normalAtImage(image);
}

SpheroidExit distanceToSpheroidExit(const ProlateSpheroid& spheroid, const Vec3& axis,
                                    const Vec3& pointInside, const Vec3& direction) {
  const SpheroidFrame frame(spheroid, axis, "distanceToSpheroidExit");
  requireUnit(direction, "direction", "distanceToSpheroidExit");
  // |P + tD|² = 1 in the image: α t² + 2β t + γ = 0 with γ <= 0 inside; the exit is the root t >=
  // 0.
  const Vec3 p = frame.toUnitSphere(pointInside);
  const Vec3 d = frame.toUnitSphere(direction);
  const double alpha = dot(d, d), beta = dot(p, d), gamma = dot(p, p) - 1.0;
  if (!(gamma <= kSurfaceTolerance)) {
    throw std::invalid_argument(
        "distanceToSpheroidExit: the point lies outside the spheroid "
        "(normalised radius² = " +
        std::to_string(gamma + 1.0) + ")");
  }
  // γ <= 0 makes the discriminant non-negative; a point on the surface may leave it at −ulp.
  const double root = std::sqrt(std::fmax(0.0, beta * beta - alpha * gamma));
  // The two algebraic forms of the same root; each avoids cancellation for its sign of β.
  double t = beta <= 0.0 ? (root - beta) / alpha : -gamma / (beta + root);
  // A surface point heading outward (γ ≈ +ulp, β > 0) has t ≈ −ulp: it is already at the exit.
  t = std::fmax(t, 0.0);
  const Vec3 exitImage = p + d * t;
  return {t, pointInside + direction * t, frame.normalAtImage(exitImage)};
}

}  // namespace hylios::skin
