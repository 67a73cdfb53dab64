// Fast exact rejection samplers for the walk's hot path, drawing as many uniforms as they need
// from the ray's Rng. The two polar laws (the one-uniform inversions of
// skin/sampling/exponential_polar_sampling.h and skin/sampling/surface_normal_sampling.h solve a
// CDF by Newton steps and cost ~2,500 instructions) return the cosine and sine of θ directly, which
// is what a perturbed direction needs. A uniform point in the unit disk (from the square,
// acceptance π/4) gives a uniform azimuth's cosine and sine without trigonometric calls or square
// roots (its doubled angle), and with Malley's construction (lift the disk point to the
// hemisphere) a cosine-weighted direction.
//
// Algorithm 2's law, p(θ) ∝ e^{−θ/θo} sinθ on [0, π]: proposal Gamma(2, θo), density
// ∝ θ e^{−θ/θo} on [0, ∞), drawn as θo·(E1 + E2) with E standard exponentials from the ziggurat
// (skin/sampling/exponential_ziggurat.h); accepted with probability sinθ/θ (≤ 1) when
// θ ≤ π. The acceptance rate is ≈ 1 − θo² (0.992 at the paper's θo = 5°). Above θo = 0.5 rad
// (acceptance < 0.8, never used by the model, whose θo ≤ 5°) the inversion sampler is used.
//
// Sec. 4.3's law, P_s(θ) ∝ sinθ/(s²cos²θ + sin²θ)² on [0, π/2): with tanθ = s·tanψ and c = cosψ
// in [0, 1] (derived here) the density of c is ∝ h(c) = sqrt(s² + (1 − s²)c²), and
//   cosθ = c/h(c),  sinθ = s·sqrt(1 − c²)/h(c).
// h is drawn by rejection: for s < 1 from the envelope s + sqrt(1 − s²)·c ≥ h (acceptance ≥ 1/√2;
// the linear density is inverted by a stable quadratic root), for s ≥ 1 from the constant s ≥ h
// (acceptance ≥ π/4). The test (u·envelope)² ≤ h² needs no square root.
#pragma once
#include <array>
#include <cmath>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/core/vector3.h"

namespace hylios::skin {

struct PolarCosSin {
  double cosTheta = 1;
  double sinTheta = 0;
  double thetaRad = 0;  ///< θ itself (filled by sampleExponentialPolarCosSin only)
};

/// A point uniform in the unit disk, with its squared radius (< 1).
struct DiskPoint {
  double x = 0, y = 0, radiusSquared = 0;
};
inline DiskPoint sampleUnitDisk(Rng& rng) {
  for (;;) {
    const double x = 2.0 * rng.uniform() - 1.0, y = 2.0 * rng.uniform() - 1.0;
    const double r2 = x * x + y * y;
    if (r2 < 1.0) return {x, y, r2};
  }
}

/// cos φ and sin φ of an azimuth φ uniform on [0, 2π): twice the angle of a uniform disk point,
/// (x² − y², 2xy)/r² (von Neumann's doubled angle: uniform again, and no square root).
struct Azimuth {
  double cosPhi = 1, sinPhi = 0;
};
inline Azimuth sampleAzimuth(Rng& rng) {
  for (;;) {
    const DiskPoint p = sampleUnitDisk(rng);
    if (p.radiusSquared > 1e-200) {  // the direction of the centre is undefined
      const double inverseRadiusSquared = 1.0 / p.radiusSquared;
      return {(p.x - p.y) * (p.x + p.y) * inverseRadiusSquared,
              2.0 * p.x * p.y * inverseRadiusSquared};
    }
  }
}

/// The azimuth 2πu for u uniform in [0, 1): uniform, from one number (a stratified one keeps its
/// strata).
inline Azimuth azimuthFromUniform(double u) {
  const double phi = kTwoPi * u;
  return {std::cos(phi), std::sin(phi)};
}

/// A unit direction about +z with density cosθ/π per steradian (z > 0; Malley's method: the disk
/// point lifted to the hemisphere, same law as skin/sampling/cosine_sampling.h's
/// sampleCosineHemisphere).
inline Vec3 sampleCosineHemisphereByDisk(Rng& rng) {
  const DiskPoint p = sampleUnitDisk(rng);
  return {p.x, p.y, std::sqrt(1.0 - p.radiusSquared)};
}

/// θ from Algorithm 2's density with mean angle θo (radians, 0 or in [1e-300, 1e6]; 0 gives θ = 0).
/// Throws std::invalid_argument for θo outside that set.
PolarCosSin sampleExponentialPolarCosSin(double meanAngleRad, Rng& rng);

/// Precomputed constants of P_s for one aspect ratio s in [1e-100, 1e10] (throws otherwise).
class SurfaceNormalPolarSampler {
 public:
  explicit SurfaceNormalPolarSampler(double aspectRatio);
  /// `firstTrial` (may be null): the two uniform numbers in [0, 1) of the first rejection trial,
  /// e.g. a pixel's stratified pair; later trials draw from `rng`. Every trial's pair is uniform
  /// and independent of the others', so the accepted θ has the same law either way.
  PolarCosSin sample(Rng& rng, const std::array<double, 2>* firstTrial = nullptr) const;
  double aspectRatio() const { return s_; }

 private:
  double s_;             // s
  double s2_;            // s²
  double slope_;         // k = sqrt(1 − s²) for s < 1 (envelope s + k·c); 0 for s >= 1
  double k2_;            // 1 − s² (may be negative)
  double envelopeArea_;  // s + k/2 for s < 1
};

}  // namespace hylios::skin
