#include "skin/skin_walk.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "skin/interface_crossing.h"
#include "skin/sampling/exponential_ziggurat.h"
#include "skin/sampling/polar_rejection_sampling.h"
#include "skin/sampling/rayleigh_sampling.h"

namespace hylios::skin {
namespace {
constexpr double kAirRefractiveIndex = 1.0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Free path for total coefficient mu (Eq. 1): a standard exponential (the ziggurat) over mu;
/// infinite when nothing attenuates.
double sampleFreePathCm(double mu_perCm, Rng& rng) {
  return mu_perCm > 0 ? sampleStandardExponential(rng) / mu_perCm : kInfinity;
}

}  // namespace

SkinWalk::SkinWalk(const SkinOptics& optics, WalkOptions options)
    : optics_(optics), options_(options) {
  double depthCm = 0;
  for (Layer layer : kAllLayers) {
    if (index(layer) > index(options.deepestLayer)) break;
    const LayerOptics& lo = optics[layer];
    if (!(lo.thicknessCm > 0)) continue;  // empty layers take no part in the walk
    const double muMelanosome = options.melanosomes ? lo.melanosome.mu_perCm : 0.0;
    const double muRayleigh = options.rayleigh ? lo.muRayleigh_perCm : 0.0;
    const double muAPlusMelanosome = lo.muATotal_perCm + muMelanosome;
    if (muMelanosome > 0)
      melanosomes_[slabCount_] =
          MelanosomeLayer(optics, layer,
                          options.tabulatedMelanosomes ? MelanosomeAbsorption::Tabulated
                                                       : MelanosomeAbsorption::Traced);
    slabs_[slabCount_++] = Slab{layer,
                                depthCm,
                                depthCm + lo.thicknessCm,
                                lo.refractiveIndex,
                                lo.muATotal_perCm,
                                muAPlusMelanosome,
                                muAPlusMelanosome + muRayleigh,
                                muAPlusMelanosome};
    depthCm += lo.thicknessCm;
  }
  if (slabCount_ == 0)
    throw std::invalid_argument(
        "skin walk: every layer has zero thickness; there is no skin to walk in");
  if (options.roughSurface) roughSurface_.emplace(optics.surfaceAspectRatio);
}

InterfaceCrossing SkinWalk::crossSurface(const Vec3& d, double nFrom, double nTo, Rng& rng) const {
  return roughSurface_ ? roughSurface_->cross(d, nFrom, nTo, rng)
                       : crossPlaneInterfaceZ(d, nFrom, nTo, rng);
}

InterfaceCrossing SkinWalk::enterFromAir(const Vec3& incidentDirection, Rng& rng) const {
  return crossSurface(incidentDirection, kAirRefractiveIndex, slabs_[0].refractiveIndex, rng);
}

SkinPath SkinWalk::trace(const Vec3& incidentDirection, Rng& rng, LayerPathLengths* lengths) const {
  const InterfaceCrossing entry = enterFromAir(incidentDirection, rng);
  if (entry.transmitted) return traceEntered(entry.direction, rng, lengths);
  SkinPath path;
  path.events = 1;
  path.end = PathEnd::SurfaceReflection;
  path.exitDirection = entry.direction;
  return path;
}

SkinPath SkinWalk::traceEntered(const Vec3& transmittedDirection, Rng& rng,
                                LayerPathLengths* lengths) const {
  SkinPath path;
  path.events = 1;
  Vec3 position{0, 0, 0};
  // Ends the walk with the ray leaving the skin at `position` along `direction` (outside it).
  auto leave = [&path, &position](PathEnd end, const Vec3& direction) {
    path.end = end;
    path.exitDirection = direction;
    path.exitOffsetXCm = position.x;
    path.exitOffsetYCm = position.y;
    return path;
  };
  Vec3 d = transmittedDirection;
  std::size_t k = 0;
  bool rayleighAvailable =
      true;  // Rayleigh acts at most once per pass through the layer (Sec. 4.2.1)
  while (path.events < kMaxEvents) {
    ++path.events;
    const Slab& slab = slabs_[k];
    const double muTotal =
        rayleighAvailable ? slab.muTotalWithRayleigh_perCm : slab.muTotalWithoutRayleigh_perCm;
    const double toBoundaryCm = d.z > 0   ? (slab.bottomCm - position.z) / d.z
                                : d.z < 0 ? (slab.topCm - position.z) / d.z
                                          : kInfinity;
    const double freePathCm = sampleFreePathCm(muTotal, rng);
    if (freePathCm < toBoundaryCm) {
      if (lengths) lengths->cm[index(slab.layer)] += freePathCm;
      position += d * freePathCm;
      const double pick = rng.uniform() * muTotal;  // which coefficient's event came first
      if (pick < slab.muA_perCm) {
        path.end = PathEnd::Absorbed;
        path.layer = slab.layer;
        return path;
      }
      if (pick < slab.muAPlusMelanosome_perCm) {
        const MelanosomeEvent event = melanosomes_[k].interact(d, rng);
        if (event.absorbed) {
          path.end = PathEnd::Absorbed;
          path.layer = slab.layer;
          path.absorbedInMelanosome = true;
          return path;
        }
        d = event.direction;
        continue;
      }
      const double cosR = sampleRayleighCos(rng.uniform());  // Algorithm 1's density
      const double sinR = std::sqrt((1.0 - cosR) * (1.0 + cosR));
      const Azimuth phi = sampleAzimuth(rng);
      d = directionAbout(d, cosR, sinR, phi.cosPhi, phi.sinPhi);
      rayleighAvailable = false;
      continue;
    }
    if (!std::isfinite(toBoundaryCm)) break;  // parallel to the layers with nothing to stop it
    if (lengths) lengths->cm[index(slab.layer)] += toBoundaryCm;
    position += d * toBoundaryCm;
    position.z = d.z > 0 ? slab.bottomCm : slab.topCm;
    if (d.z < 0 && k == 0) {  // the skin surface, from inside
      const InterfaceCrossing exit =
          crossSurface(d, slab.refractiveIndex, kAirRefractiveIndex, rng);
      if (exit.transmitted) return leave(PathEnd::SubsurfaceReflection, exit.direction);
      d = exit.direction;
      continue;
    }
    if (d.z > 0 && k + 1 == slabCount_) {
      if (options_.deepestLayer ==
          Layer::ReticularDermis) {  // dermis–hypodermis: reflectance 1, diffuse
        const Vec3 local = sampleCosineHemisphereByDisk(rng);
        d = Vec3{local.x, local.y, -local.z};
        continue;
      }
      const InterfaceCrossing bottom =
          crossPlaneInterfaceZ(d, slab.refractiveIndex, options_.belowRefractiveIndex, rng);
      if (bottom.transmitted) return leave(PathEnd::Transmitted, bottom.direction);
      d = bottom.direction;
      continue;
    }
    const std::size_t next = d.z > 0 ? k + 1 : k - 1;
    const InterfaceCrossing crossing =
        crossPlaneInterfaceZ(d, slab.refractiveIndex, slabs_[next].refractiveIndex, rng);
    d = crossing.direction;
    if (crossing.transmitted) {
      k = next;
      if (slabs_[k].layer == Layer::PapillaryDermis) rayleighAvailable = true;  // a new pass
    }
  }
  path.end = PathEnd::EventLimit;
  return path;
}

}  // namespace hylios::skin
