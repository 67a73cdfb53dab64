#include "skin/skin_walk.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "skin/cosine_sampling.h"
#include "skin/interface_crossing.h"
#include "skin/melanosome_interaction.h"
#include "skin/rayleigh_sampling.h"
#include "skin/rough_surface.h"

namespace hylios::skin {
namespace {
constexpr double kAirRefractiveIndex = 1.0;
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Free path for total coefficient mu (Eq. 1); infinite when nothing attenuates.
double sampleFreePathCm(double mu_perCm, Rng& rng) {
  return mu_perCm > 0 ? -std::log1p(-rng.uniform()) / mu_perCm : kInfinity;
}
}  // namespace

SkinWalk::SkinWalk(const SkinOptics& optics, WalkOptions options)
    : optics_(optics), options_(options) {
  double depthCm = 0;
  for (Layer layer : kAllLayers) {
    if (index(layer) > index(options.deepestLayer)) break;
    const LayerOptics& lo = optics[layer];
    if (!(lo.thicknessCm > 0)) continue;  // empty layers take no part in the walk
    slabs_[slabCount_++] = Slab{layer,
                                depthCm,
                                depthCm + lo.thicknessCm,
                                lo.refractiveIndex,
                                lo.muATotal_perCm,
                                options.melanosomes ? lo.melanosome.mu_perCm : 0.0,
                                options.rayleigh ? lo.muRayleigh_perCm : 0.0};
    depthCm += lo.thicknessCm;
  }
  if (slabCount_ == 0)
    throw std::invalid_argument("skin walk: every layer has zero thickness; there is no skin to walk in");
}

SkinPath SkinWalk::trace(const Vec3& incidentDirection, Rng& rng) const {
  SkinPath path;
  const double roughness = optics_.surfaceAspectRatio;
  auto crossSurface = [&](const Vec3& d, double nFrom, double nTo) {
    return options_.roughSurface ? crossRoughSurface(d, nFrom, nTo, roughness, rng)
                                   : crossPlaneInterfaceZ(d, nFrom, nTo, rng);
  };
  const InterfaceCrossing entry = crossSurface(incidentDirection, kAirRefractiveIndex, slabs_[0].refractiveIndex);
  path.events = 1;
  if (!entry.transmitted) {
    path.end = PathEnd::SurfaceReflection;
    path.exitDirection = entry.direction;
    return path;
  }
  Vec3 position{0, 0, 0};
  Vec3 d = entry.direction;
  std::size_t k = 0;
  bool rayleighAvailable = true;  // Rayleigh acts at most once per pass through the layer (Sec. 4.2.1)
  while (path.events < kMaxEvents) {
    ++path.events;
    const Slab& slab = slabs_[k];
    const double muRayleigh = rayleighAvailable ? slab.muRayleigh_perCm : 0.0;
    const double muTotal = slab.muA_perCm + slab.muMelanosome_perCm + muRayleigh;
    const double toBoundaryCm = d.z > 0   ? (slab.bottomCm - position.z) / d.z
                                : d.z < 0 ? (slab.topCm - position.z) / d.z
                                          : kInfinity;
    const double freePathCm = sampleFreePathCm(muTotal, rng);
    if (freePathCm < toBoundaryCm) {
      position += d * freePathCm;
      const double pick = rng.uniform() * muTotal;  // which coefficient's event came first
      if (pick < slab.muA_perCm) {
        path.end = PathEnd::Absorbed;
        path.layer = slab.layer;
        return path;
      }
      if (pick < slab.muA_perCm + slab.muMelanosome_perCm) {
        const MelanosomeEvent event = interactWithMelanosomes(d, optics_, slab.layer, rng);
        if (event.absorbed) {
          path.end = PathEnd::Absorbed;
          path.layer = slab.layer;
          path.absorbedInMelanosome = true;
          return path;
        }
        d = event.direction;
        continue;
      }
      const double thetaR = sampleRayleighPolar(rng.uniform());  // Algorithm 1's density
      const double phi = kTwoPi * rng.uniform();
      d = perturbDirection(d, std::cos(thetaR), phi);
      rayleighAvailable = false;
      continue;
    }
    if (!std::isfinite(toBoundaryCm)) break;  // parallel to the layers with nothing to stop it
    position += d * toBoundaryCm;
    position.z = d.z > 0 ? slab.bottomCm : slab.topCm;
    if (d.z < 0 && k == 0) {  // the skin surface, from inside
      const InterfaceCrossing exit = crossSurface(d, slab.refractiveIndex, kAirRefractiveIndex);
      if (exit.transmitted) {
        path.end = PathEnd::SubsurfaceReflection;
        path.exitDirection = exit.direction;
        path.exitOffsetXCm = position.x;
        path.exitOffsetYCm = position.y;
        return path;
      }
      d = exit.direction;
      continue;
    }
    if (d.z > 0 && k + 1 == slabCount_) {
      if (options_.deepestLayer == Layer::ReticularDermis) {  // dermis–hypodermis: reflectance 1, diffuse
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const Vec3 local = sampleCosineHemisphere(u1, u2);
        d = Vec3{local.x, local.y, -local.z};
        continue;
      }
      const InterfaceCrossing bottom =
          crossPlaneInterfaceZ(d, slab.refractiveIndex, options_.belowRefractiveIndex, rng);
      if (bottom.transmitted) {
        path.end = PathEnd::Transmitted;
        path.exitDirection = bottom.direction;
        path.exitOffsetXCm = position.x;
        path.exitOffsetYCm = position.y;
        return path;
      }
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
