// A small 3-vector for the walk's local frame (z points into the skin, along the inward normal).
#pragma once
#include <cmath>

namespace hylios::skin {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) { return v / length(v); }

/// An orthonormal basis (t, b, n) around unit vector n (Duff et al. 2017, "Building an
/// orthonormal basis, revisited"). Use it to turn a direction sampled about +z into one about n.
struct Frame {
  Vec3 t, b, n;
  explicit Frame(const Vec3& normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double bb = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * bb, -sign * n.x};
    b = {bb, sign + n.y * n.y * a, -n.y};
  }
  Vec3 toWorld(const Vec3& local) const { return t * local.x + b * local.y + n * local.z; }
  Vec3 toLocal(const Vec3& world) const { return {dot(world, t), dot(world, b), dot(world, n)}; }
};

/// The same from the cosines and sines of θ and φ (no trigonometric calls).
inline Vec3 directionAbout(const Vec3& axis, double cosTheta, double sinTheta, double cosPhi,
                           double sinPhi) {
  return Frame(axis).toWorld({sinTheta * cosPhi, sinTheta * sinPhi, cosTheta});
}

}  // namespace hylios::skin
