// The spectral walk at the stack's two ends (skin/spectral_walk.h): the rough air–skin surface,
// where each λ's facet and Fresnel factor enter its density, and the bottom of a truncated stack.
#include <cmath>
#include <utility>
#include <vector>

#include "skin/fresnel.h"
#include "skin/rough_surface.h"
#include "skin/spectral_walk_state.h"

namespace hylios::skin {
using spectral_walk_detail::kInfinity;

bool SpectralWalk::crossFacet(State& s, const Vec3& m, const Vec3& macro, bool delta,
                              bool fromInside, Rng& rng, bool forceTransmission) const {
  const double nFromH = fromInside ? surfaceIndex_[s.hero] : 1.0;
  const double nToH = fromInside ? 1.0 : surfaceIndex_[s.hero];
  const Vec3 d = s.direction;
  const double cosI = dot(d, m);
  const FresnelResult hero = fresnel(cosI, nFromH, nToH);
  const bool reflect = !forceTransmission && nFromH != nToH &&
                       (hero.reflectance >= 1.0 || rng.uniform() < hero.reflectance);
  auto indices = [&](std::size_t i) {
    return fromInside ? std::pair{surfaceIndex_[i], 1.0} : std::pair{1.0, surfaceIndex_[i]};
  };
  if (reflect) {
    s.direction = reflectDirection(d, m);
    // From inside beyond the critical angle of the smallest index, every λ reflects totally.
    const bool totalForAll =
        fromInside && 1.0 - cosI * cosI >= 1.0 / (smallestSurfaceIndex_ * smallestSurfaceIndex_);
    if (surfaceIndicesDiffer_ && !totalForAll)
      surfaceGroups_.addLogReflectances(cosI, fromInside, s.logDensity.data());
    return false;
  }
  const Vec3 t = refractDirection(d, m, nFromH, nToH, hero.cosTransmitted);
  s.direction = t;
  if (!surfaceIndicesDiffer_) {
    if (forceTransmission)  // one index: the target has the factor 1 − F, the proposal not
      for (std::size_t i = 0; i < wavelengthCount_; ++i) {
        s.logDensity[i] += std::log1p(-hero.reflectance);
        s.proposalOffset[i] -= std::log1p(-hero.reflectance);
      }
    return true;
  }
  if (!delta) {  // each λ's facet through the generalised half vector (skin/spectral_weights.h)
    surfaceGroups_.addRefractionDensities(d, t, macro, fromInside, aspectSquared_,
                                          forceTransmission, s.logDensity.data(),
                                          s.proposalOffset.data());
    return true;
  }
  for (std::size_t i = 0; i < wavelengthCount_; ++i) {
    // A point mass: only wavelengths that refract to the same direction share it.
    const auto [n1, n2] = indices(i);
    double& logDensity = s.logDensity[i];
    logDensity = n2 == nToH && n1 == nFromH
                     ? logDensity + std::log1p(-fresnelReflectance(cosI, n1, n2))
                     : -kInfinity;
  }
  return true;
}

bool SpectralWalk::crossSurface(State& s, bool fromInside, Rng& rng, bool splitEntry,
                                const FacetNumbers* firstFacet) const {
  const double towardFar = s.direction.z > 0 ? 1.0 : -1.0;
  bool onFarSide = false;
  for (int attempt = 0; attempt <= kMaxSurfaceBounces; ++attempt) {
    const double headingSign = onFarSide ? -towardFar : towardFar;
    const Vec3 macroNormal{0, 0, -headingSign};
    bool delta = !options_.roughSurface || attempt == kMaxSurfaceBounces;
    Vec3 m = macroNormal;
    if (!delta) {
      delta = true;
      for (int redraw = 0; redraw < kMaxFacetRedraws && delta; ++redraw) {
        const FacetNumbers* numbers = attempt == 0 && redraw == 0 ? firstFacet : nullptr;
        const PolarCosSin theta = facetPolar_->sample(rng, numbers ? &numbers->polar : nullptr);
        const Azimuth phi = numbers ? azimuthFromUniform(numbers->azimuth) : sampleAzimuth(rng);
        const Vec3 candidate =
            directionAbout(macroNormal, theta.cosTheta, theta.sinTheta, phi.cosPhi, phi.sinPhi);
        if (dot(s.direction, candidate) < 0) {
          m = candidate;
          delta = false;
        }
      }
    }
    const bool inSkin = fromInside != onFarSide;
    // The entry split (WalkOptions::splitEntryReflection): when the first facet's mirror image of
    // the ray leaves the surface, every λ scores that reflection with its Fresnel weight at once
    // and the path is forced through the facet (the Fresnel choice is not drawn).
    const Vec3 mirrored = reflectDirection(s.direction, m);
    const bool split =
        splitEntry && !fromInside && attempt == 0 && !delta && mirrored.z * towardFar < 0;
    if (split) {
      s.path.surfaceWeight.resize(wavelengthCount_);
      surfaceGroups_.reflectances(dot(s.direction, m), false, s.path.surfaceWeight.data());
      s.path.surfaceDirection = mirrored;
    }
    const bool transmitted = crossFacet(s, m, macroNormal, delta, inSkin, rng, split);
    if (transmitted) onFarSide = !onFarSide;
    const double awaySign = onFarSide ? towardFar : -towardFar;
    if (s.direction.z * awaySign > 0) return onFarSide;
    if (!options_.roughSurface) break;
  }
  s.direction.z = std::fabs(s.direction.z) * (onFarSide ? towardFar : -towardFar);
  return onFarSide;
}

bool SpectralWalk::crossBottom(State& s, Rng& rng) const {
  const Vec3 d = s.direction;
  const double nBelow = options_.belowRefractiveIndex;
  const FresnelResult hero = fresnel(d.z, bottomIndex_[s.hero], nBelow);
  const bool reflect = bottomIndex_[s.hero] != nBelow &&
                       (hero.reflectance >= 1.0 || rng.uniform() < hero.reflectance);
  if (reflect) s.direction = Vec3{d.x, d.y, -d.z};
  std::vector<Vec3>& out = s.path.transmittedDirection;
  if (!reflect) out.assign(wavelengthCount_, Vec3{});
  for (std::size_t i = 0; i < wavelengthCount_; ++i) {
    const FresnelResult f = fresnel(d.z, bottomIndex_[i], nBelow);
    if (wavelengthCount_ > 1)
      s.logDensity[i] += reflect ? std::log(f.reflectance) : std::log1p(-f.reflectance);
    if (!reflect) {
      const double ratio = bottomIndex_[i] / nBelow;
      out[i] = Vec3{d.x * ratio, d.y * ratio, std::copysign(f.cosTransmitted, d.z)};
    }
  }
  if (!reflect) s.direction = out[s.hero];
  return !reflect;
}

}  // namespace hylios::skin
