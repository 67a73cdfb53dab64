// The geometry of a ray inside one melanosome (paper Sec. 4.2.2), shared by the exact interaction
// (MelanosomeLayer::absorbedInOne, which tests absorption on every chord) and the path-length table
// (skin/melanosome_path_lengths.h, which only sums the chords).
//
// Body frame, lengths in units of the semi-minor axis a (see skin/melanosome_interaction.h): the
// spheroid's axis is z, c = γ. The walk draws the orientation (Eq. 8), a point uniform over the
// silhouette, the Fresnel test at entry, then for each chord calls onChord(chord) — which may draw
// its own uniforms and returns true to stop the walk (absorbed) — and tests the far wall (Fresnel
// with total internal reflection; a reflected ray bounces diffusely about the inward normal).
// Uniforms are drawn in this order: cosα, the disk point (rejection), the entry test; per chord:
// onChord's own, the wall test, the bounce's disk point (rejection).
#pragma once
#include <cmath>

#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/fresnel_pair.h"
#include "skin/sampling/polar_rejection_sampling.h"

namespace hylios::skin {

/// Bound on internal wall bounces in one melanosome; past it the ray is let out through the wall
/// (with 1.7/1.4 and cosine-perturbed bounces the chance of reaching it is below 1e-300).
inline constexpr int kMaxMelanosomeBounces = 10000;

/// The constants of one melanosome shape and index pair: γ = c/a ≥ 1 and the two wall crossings.
struct MelanosomeGeometry {
  double aspect = 1;         ///< γ = c/a
  double inverseAspect = 1;  ///< 1/γ
  FresnelPair entering;      ///< surrounding layer → melanin
  FresnelPair leaving;       ///< melanin → surrounding layer
};

/// How the walk inside one melanosome ended.
enum class MelanosomeWalkEnd { ReflectedAtEntry, Stopped, Left };

namespace detail {
/// Outward unit normal of the spheroid (a = 1, c = γ) at the point whose unit-sphere image is p:
/// the gradient of x² + y² + z²/γ², i.e. (p.x, p.y, p.z/γ) normalised.
inline Vec3 melanosomeNormalAtImage(const Vec3& p, double inverseAspect) {
  const Vec3 gradient{p.x, p.y, p.z * inverseAspect};
  return gradient * (1.0 / std::sqrt(dot(gradient, gradient)));
}
}  // namespace detail

/// Traces one ray through one melanosome (see above). onChord(double chordOverA) -> bool.
template <class OnChord>
MelanosomeWalkEnd walkInsideMelanosome(const MelanosomeGeometry& g, Rng& rng, OnChord&& onChord) {
  // Eq. 8: |cosα| has density ∝ χ1 + (χ2 − χ1)m on [0, 1] with χ1 ∝ c = γ and χ2 ∝ a = 1; its
  // inverse is the stable root m = v(χ1 + χ2)/(χ1 + sqrt(χ1²(1 − v) + χ2²v)) (as in
  // melanosome_orientation_sampling.cpp).
  const double gamma = g.aspect;
  const double v = rng.uniform();
  const double cosAlpha = v * (gamma + 1.0) / (gamma + std::sqrt(gamma * gamma * (1.0 - v) + v));
  const double sinAlpha = std::sqrt((1.0 - cosAlpha) * (1.0 + cosAlpha));
  const Vec3 incoming{sinAlpha, 0.0, cosAlpha};
  // The silhouette (spheroid_intersection.h): in the unit-sphere image the ray runs along n ∝
  // (sinα, 0, cosα/γ); a point uniform on the unit disk normal to n (by rejection from the square,
  // basis t = (n_z, 0, −n_x) and the y axis), stepped back to the sphere's near side.
  const double imageZ = cosAlpha * g.inverseAspect;
  const double inverseLength = 1.0 / std::sqrt(sinAlpha * sinAlpha + imageZ * imageZ);
  const double nx = sinAlpha * inverseLength, nz = imageZ * inverseLength;
  const DiskPoint disk = sampleUnitDisk(rng);
  const double depth = std::sqrt(1.0 - disk.radiusSquared);
  Vec3 image{disk.x * nz - depth * nx, disk.y,
             -disk.x * nx - depth * nz};  // the entry point's image
  Vec3 normal = detail::melanosomeNormalAtImage(image, g.inverseAspect);
  double cosTransmitted = 0;
  const double entryReflectance = g.entering.reflectance(dot(incoming, normal), cosTransmitted);
  if (rng.uniform() < entryReflectance) return MelanosomeWalkEnd::ReflectedAtEntry;
  Vec3 d = g.entering.refract(incoming, normal, cosTransmitted);
  for (int bounce = 0; bounce < kMaxMelanosomeBounces; ++bounce) {
    // Exit: |P + tD|² = 1 in the image, D the image of d; t is also the body-frame path length
    // (the map is linear and d is unit). The two root forms avoid cancellation for either sign of
    // β.
    const Vec3 imageD{d.x, d.y, d.z * g.inverseAspect};
    const double alpha = dot(imageD, imageD), beta = dot(image, imageD);
    const double offset = dot(image, image) - 1.0;  // ≈ 0: on the surface
    const double discriminant = beta * beta - alpha * offset;
    const double root = discriminant > 0.0 ? std::sqrt(discriminant) : 0.0;
    double chord = beta <= 0.0 ? (root - beta) / alpha : -offset / (beta + root);
    if (!(chord > 0.0)) chord = 0.0;  // a surface point heading out: already at the exit
    if (onChord(chord)) return MelanosomeWalkEnd::Stopped;
    image += imageD * chord;
    normal = detail::melanosomeNormalAtImage(image, g.inverseAspect);
    double unused = 0;
    const double wallReflectance = g.leaving.reflectance(dot(d, normal), unused);
    if (rng.uniform() >= wallReflectance) return MelanosomeWalkEnd::Left;  // transmitted out
    d = Frame(-normal).toWorld(sampleCosineHemisphereByDisk(rng));  // diffuse bounce, inward normal
  }
  return MelanosomeWalkEnd::Left;
}

}  // namespace hylios::skin
