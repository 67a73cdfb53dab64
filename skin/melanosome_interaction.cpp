#include "skin/melanosome_interaction.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/exponential_polar_sampling.h"
#include "skin/polar_rejection_sampling.h"
#include "skin/spheroid.h"

namespace hylios::skin {
namespace {
void requirePositiveIndex(double n, const char* what) {
  if (!(n > 0 && std::isfinite(n)))
    throw std::invalid_argument(std::string("melanosome interaction: ") + what + " " +
                                std::to_string(n) + " is not positive and finite");
}

/// Outward unit normal of the spheroid (a = 1, c = γ) at the point whose unit-sphere image is p:
/// the gradient of x² + y² + z²/γ², i.e. (p.x, p.y, p.z/γ) normalised.
Vec3 normalAtImage(const Vec3& p, double inverseAspect) {
  const Vec3 gradient{p.x, p.y, p.z * inverseAspect};
  return gradient * (1.0 / std::sqrt(dot(gradient, gradient)));
}
}  // namespace

MelanosomeLayer::MelanosomeLayer(double semiMinor, double semiMajor, double interiorMuA,
                                 double nLayer, double nMelanin) {
  checkProlateSpheroid({semiMinor, semiMajor});
  if (!(interiorMuA >= 0 && std::isfinite(interiorMuA)))
    throw std::invalid_argument("melanosome interaction: interior absorption coefficient " +
                                std::to_string(interiorMuA) + " is negative or not finite");
  requirePositiveIndex(nLayer, "layer refractive index");
  requirePositiveIndex(nMelanin, "melanin refractive index");
  entering_ = FresnelPair(nLayer, nMelanin);
  leaving_ = FresnelPair(nMelanin, nLayer);
  aspect_ = semiMajor / semiMinor;
  inverseAspect_ = semiMinor / semiMajor;
  muA_perMinorAxis_ = interiorMuA * semiMinor;
}

MelanosomeLayer::MelanosomeLayer(const SkinOptics& optics, Layer layer)
    : MelanosomeLayer(optics[layer].melanosome.semiMinorAxisCm, optics[layer].melanosome.semiMajorAxisCm,
                      optics.melanosomeInteriorMuA_perCm, optics[layer].refractiveIndex,
                      optics.melaninRefractiveIndex) {
  const MelanosomeOptics& m = optics[layer].melanosome;
  inComplexes_ = m.inComplexes;
  if (inComplexes_) {
    if (!(m.melanosomesPerComplex >= 0 && m.melanosomesPerComplex < 1e9))
      throw std::invalid_argument("melanosome interaction: " + std::to_string(m.melanosomesPerComplex) +
                                  " melanosomes per complex in " + std::string(layerName(layer)) +
                                  " is outside [0, 1e9)");
    const double whole = std::floor(m.melanosomesPerComplex);
    wholeCount_ = static_cast<unsigned>(whole);
    fractionalCount_ = m.melanosomesPerComplex - whole;
  }
  meanAngleRad_ = optics.meanScatteringAngleRad;
  const bool angleOk = meanAngleRad_ == 0.0 || (meanAngleRad_ >= kMinExponentialMeanAngleRad &&
                                                meanAngleRad_ <= kMaxExponentialMeanAngleRad);
  if (!angleOk)
    throw std::invalid_argument("melanosome interaction: mean scattering angle " +
                                std::to_string(meanAngleRad_) + " rad must be 0 or in [1e-300, 1e6]");
}

unsigned MelanosomeLayer::melanosomesToMeet(Rng& rng) const {
  if (!inComplexes_) return 1;
  return wholeCount_ + (rng.uniform() < fractionalCount_ ? 1u : 0u);
}

bool MelanosomeLayer::absorbedInOne(Rng& rng) const {
  // Body frame, lengths in units of a (see the header). Eq. 8: |cosα| has density ∝ χ1 + (χ2 − χ1)m
  // on [0, 1] with χ1 ∝ c = γ and χ2 ∝ a = 1; its inverse is the stable root
  // m = v(χ1 + χ2)/(χ1 + sqrt(χ1²(1 − v) + χ2²v)) (as in melanosome_orientation_sampling.cpp).
  const double gamma = aspect_;
  const double v = rng.uniform();
  const double cosAlpha = v * (gamma + 1.0) / (gamma + std::sqrt(gamma * gamma * (1.0 - v) + v));
  const double sinAlpha = std::sqrt((1.0 - cosAlpha) * (1.0 + cosAlpha));
  const Vec3 incoming{sinAlpha, 0.0, cosAlpha};
  // The silhouette (spheroid_intersection.h): in the unit-sphere image the ray runs along n ∝
  // (sinα, 0, cosα/γ); a point uniform on the unit disk normal to n (by rejection from the square,
  // basis t = (n_z, 0, −n_x) and the y axis), stepped back to the sphere's near side.
  const double imageZ = cosAlpha * inverseAspect_;
  const double inverseLength = 1.0 / std::sqrt(sinAlpha * sinAlpha + imageZ * imageZ);
  const double nx = sinAlpha * inverseLength, nz = imageZ * inverseLength;
  const DiskPoint disk = sampleUnitDisk(rng);
  const double depth = std::sqrt(1.0 - disk.radiusSquared);
  Vec3 image{disk.x * nz - depth * nx, disk.y, -disk.x * nx - depth * nz};  // the entry point's image
  Vec3 normal = normalAtImage(image, inverseAspect_);
  double cosTransmitted = 0;
  const double entryReflectance = entering_.reflectance(dot(incoming, normal), cosTransmitted);
  if (rng.uniform() < entryReflectance) return false;  // reflected off the wall: never inside
  Vec3 d = entering_.refract(incoming, normal, cosTransmitted);
  for (int bounce = 0; bounce < kMaxMelanosomeBounces; ++bounce) {
    // Exit: |P + tD|² = 1 in the image, D the image of d; t is also the body-frame path length
    // (the map is linear and d is unit). The two root forms avoid cancellation for either sign of β.
    const Vec3 imageD{d.x, d.y, d.z * inverseAspect_};
    const double alpha = dot(imageD, imageD), beta = dot(image, imageD);
    const double offset = dot(image, image) - 1.0;  // ≈ 0: on the surface
    const double discriminant = beta * beta - alpha * offset;
    const double root = discriminant > 0.0 ? std::sqrt(discriminant) : 0.0;
    double chord = beta <= 0.0 ? (root - beta) / alpha : -offset / (beta + root);
    if (!(chord > 0.0)) chord = 0.0;  // a surface point heading out: already at the exit
    // Eq. 1 with the melanin coefficient; 1 − u is exact, so log(1 − u) = log1p(−u).
    if (muA_perMinorAxis_ > 0 && -std::log(1.0 - rng.uniform()) < muA_perMinorAxis_ * chord)
      return true;
    image += imageD * chord;
    normal = normalAtImage(image, inverseAspect_);
    double unused = 0;
    const double wallReflectance = leaving_.reflectance(dot(d, normal), unused);
    if (rng.uniform() >= wallReflectance) return false;  // transmitted out of the melanosome
    // Diffuse bounce about the inward normal.
    d = Frame(-normal).toWorld(sampleCosineHemisphereByDisk(rng));
  }
  return false;
}

MelanosomeEvent MelanosomeLayer::interact(const Vec3& direction, Rng& rng) const {
  MelanosomeEvent event;
  const unsigned count = melanosomesToMeet(rng);
  for (unsigned i = 0; i < count; ++i) {
    ++event.melanosomesMet;
    if (absorbedInOne(rng)) {
      event.absorbed = true;
      return event;
    }
  }
  const PolarCosSin theta = sampleExponentialPolarCosSin(meanAngleRad_, rng);  // Algorithm 2
  const Azimuth phi = sampleAzimuth(rng);
  event.direction = directionAbout(direction, theta.cosTheta, theta.sinTheta, phi.cosPhi, phi.sinPhi);
  return event;
}

MelanosomeEvent interactWithMelanosomes(const Vec3& direction, const SkinOptics& optics, Layer layer,
                                        Rng& rng) {
  return MelanosomeLayer(optics, layer).interact(direction, rng);
}

bool absorbedInMelanosome(const Vec3& direction, double semiMinorCm, double semiMajorCm,
                          double interiorMuA_perCm, double nLayer, double nMelanin, Rng& rng) {
  if (!(std::fabs(dot(direction, direction) - 1.0) <= 1e-6))
    throw std::invalid_argument("absorbedInMelanosome: the direction is not a unit vector");
  return MelanosomeLayer(semiMinorCm, semiMajorCm, interiorMuA_perCm, nLayer, nMelanin).absorbedInOne(rng);
}

}  // namespace hylios::skin
