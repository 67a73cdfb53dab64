// The scene camera: a pinhole (or thin lens) with a vertical field of view, placed by position,
// look-at point and up vector. Right-handed world; image x grows to the right and image y grows
// downwards (row 0 is the top of the image).
#pragma once
#include <glm/glm.hpp>

#include "renderer/scene/scene.h"
#include "renderer/tracing/embree_scene.h"

namespace hylios {

class Camera {
 public:
  /// Throws SceneError at desc.where for a degenerate placement (position = look-at, up parallel
  /// to the view direction), a field of view outside (0°, 180°) or a negative aperture.
  Camera(const CameraDesc& desc, int widthPixels, int heightPixels);

  /// The primary ray through image point (x, y) in pixels (fractional: pixel (i, j) spans
  /// [i, i+1) × [j, j+1)); (lensU, lensV) in [0, 1)² pick the point on the lens (ignored by a
  /// pinhole).
  Ray generateRay(double x, double y, double lensU, double lensV) const;

  const glm::dvec3& forward() const { return forward_; }

 private:
  glm::dvec3 position_, forward_, right_, up_;
  double tanHalfFov_, aspect_, apertureRadius_, focusDistance_;
  int width_, height_;
};

}  // namespace hylios
