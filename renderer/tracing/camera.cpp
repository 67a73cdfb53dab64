#include "renderer/tracing/camera.h"

#include <cmath>

#include "skin/core/constants.h"

namespace hylios {
namespace {

/// Concentric mapping of the unit square onto the unit disk (Shirley & Chiu 1997).
glm::dvec2 concentricDisk(double u, double v) {
  const double a = 2 * u - 1, b = 2 * v - 1;
  if (a == 0 && b == 0) return {0, 0};
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = (kPi / 4) * (b / a);
  } else {
    r = b;
    phi = kPi / 2 - (kPi / 4) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}
}  // namespace

Camera::Camera(const CameraDesc& desc, int widthPixels, int heightPixels)
    : position_(desc.position), width_(widthPixels), height_(heightPixels) {
  const glm::dvec3 view = desc.lookAt - desc.position;
  if (!(glm::length(view) > 0))
    throw SceneError(desc.where, "camera position and look_at coincide");
  forward_ = glm::normalize(view);
  const glm::dvec3 side = glm::cross(forward_, desc.up);
  if (!(glm::length(side) > 1e-12 * glm::length(desc.up)))
    throw SceneError(desc.where, "camera up vector is zero or parallel to the viewing direction");
  right_ = glm::normalize(side);
  up_ = glm::cross(right_, forward_);
  if (!(desc.verticalFovDeg > 0 && desc.verticalFovDeg < 180))
    throw SceneError(desc.where, "camera fov_deg must lie in (0, 180)");
  if (widthPixels <= 0 || heightPixels <= 0)
    throw SceneError(desc.where, "film resolution must be positive");
  if (!(desc.apertureRadius >= 0))
    throw SceneError(desc.where, "camera aperture radius must be >= 0");
  tanHalfFov_ = std::tan(0.5 * desc.verticalFovDeg * kPi / 180);
  aspect_ = static_cast<double>(widthPixels) / heightPixels;
  apertureRadius_ = desc.apertureRadius;
  focusDistance_ = desc.focusDistance > 0 ? desc.focusDistance : glm::length(view);
}

Ray Camera::generateRay(double x, double y, double lensU, double lensV) const {
  const double sx = (2 * x / width_ - 1) * tanHalfFov_ * aspect_;
  const double sy = (1 - 2 * y / height_) * tanHalfFov_;
  const glm::dvec3 direction = glm::normalize(forward_ + sx * right_ + sy * up_);
  if (apertureRadius_ <= 0) return {position_, direction};
  // Thin lens: every ray through the lens meets the pinhole ray on the plane of focus.
  const glm::dvec3 focus = position_ + direction * (focusDistance_ / glm::dot(direction, forward_));
  const glm::dvec2 lens = concentricDisk(lensU, lensV) * apertureRadius_;
  const glm::dvec3 origin = position_ + right_ * lens.x + up_ * lens.y;
  return {origin, glm::normalize(focus - origin)};
}

}  // namespace hylios
