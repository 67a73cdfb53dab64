#include "skin/melanosome_interaction.h"

#include <cmath>

#include "skin/cosine_sampling.h"
#include "skin/exponential_polar_sampling.h"
#include "skin/fresnel.h"
#include "skin/melanosome_orientation_sampling.h"
#include "skin/spheroid_intersection.h"

namespace hylios::skin {
namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;

unsigned melanosomesToMeet(const MelanosomeOptics& m, Rng& rng) {
  if (!m.inComplexes) return 1;
  const double whole = std::floor(m.melanosomesPerComplex);
  const double fraction = m.melanosomesPerComplex - whole;
  return static_cast<unsigned>(whole) + (rng.uniform() < fraction ? 1u : 0u);
}
}  // namespace

bool absorbedInMelanosome(const Vec3& direction, double semiMinorCm, double semiMajorCm,
                          double interiorMuA_perCm, double nLayer, double nMelanin, Rng& rng) {
  // Random numbers are drawn into named locals: argument evaluation order is unspecified in C++,
  // and the same seed must give the same ray with any compiler.
  const ProlateSpheroid spheroid{semiMinorCm, semiMajorCm};
  const double uPolar = rng.uniform(), uAzimuth = rng.uniform();
  const Vec3 axis = sampleMelanosomeAxis(spheroid, direction, uPolar, uAzimuth);  // Eq. 8
  const double uSilhouette1 = rng.uniform(), uSilhouette2 = rng.uniform();
  const SpheroidSurfacePoint entry =
      sampleSilhouetteEntry(spheroid, axis, direction, uSilhouette1, uSilhouette2);
  const FresnelResult in = fresnel(dot(direction, entry.outwardNormal), nLayer, nMelanin);
  if (rng.uniform() < in.reflectance) return false;  // reflected off the wall: never inside
  Vec3 d = refractDirection(direction, entry.outwardNormal, nLayer, nMelanin, in.cosTransmitted);
  Vec3 p = entry.position;
  for (int bounce = 0; bounce < kMaxMelanosomeBounces; ++bounce) {
    const SpheroidExit exit = distanceToSpheroidExit(spheroid, axis, p, d);
    const double chordCm = exit.distance;
    const double freePathCm = interiorMuA_perCm > 0 ? -std::log1p(-rng.uniform()) / interiorMuA_perCm
                                                    : chordCm + 1.0;
    if (freePathCm < chordCm) return true;  // Eq. 1 with the melanin coefficient
    p = exit.position;
    const Vec3 outward = exit.outwardNormal;
    const FresnelResult out = fresnel(dot(d, outward), nMelanin, nLayer);
    if (rng.uniform() >= out.reflectance) return false;  // transmitted out of the melanosome
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const Vec3 local = sampleCosineHemisphere(u1, u2);
    d = Frame(-outward).toWorld(local);  // diffuse bounce about the inward normal
  }
  return false;
}

MelanosomeEvent interactWithMelanosomes(const Vec3& direction, const SkinOptics& optics, Layer layer,
                                        Rng& rng) {
  const LayerOptics& lo = optics[layer];
  const MelanosomeOptics& m = lo.melanosome;
  MelanosomeEvent event;
  const unsigned count = melanosomesToMeet(m, rng);
  for (unsigned i = 0; i < count; ++i) {
    ++event.melanosomesMet;
    if (absorbedInMelanosome(direction, m.semiMinorAxisCm, m.semiMajorAxisCm,
                             optics.melanosomeInteriorMuA_perCm, lo.refractiveIndex,
                             optics.melaninRefractiveIndex, rng)) {
      event.absorbed = true;
      return event;
    }
  }
  const double thetaM = sampleExponentialPolar(optics.meanScatteringAngleRad, rng.uniform());  // Algorithm 2
  const double phi = kTwoPi * rng.uniform();
  event.direction = perturbDirection(direction, std::cos(thetaM), phi);
  return event;
}

}  // namespace hylios::skin
