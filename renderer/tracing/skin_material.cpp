#include "renderer/tracing/skin_material.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "renderer/tracing/melanin_level_use.h"
#include "renderer/tracing/surface_vectors.h"
#include "skin/core/constants.h"
#include "skin/core/vector3.h"
#include "skin/fresnel.h"
#include "skin/rough_surface.h"
#include "skin/sampling/surface_normal_sampling.h"

namespace hylios {
namespace {

constexpr int kLobeTableSize = 65;
constexpr int kLobeTableStrata = 96;  // stratified facet normals per table entry (per dimension)

/// Facet-normal density per steradian about the macro normal: P_s(θ)/(2π sinθ).
double facetDensityPerSr(double s, double cosTheta) {
  const double theta = std::acos(std::clamp(cosTheta, -1.0, 1.0));
  const double t = std::max(theta, 1e-7);  // P_s ∝ sinθ near 0: the ratio is finite there
  return skin::surfaceNormalPolarDensity(s, t) / (2 * kPi * std::sin(t));
}

/// The stratified facet normals drawn from P_s (kLobeTableStrata polar strata × as many azimuths),
/// in the local frame where the macro normal is −z; the same for every table entry, so drawn once
/// (each polar inversion is a Newton solve).
std::vector<skin::Vec3> stratifiedFacetNormals(double s) {
  std::vector<skin::Vec3> normals;
  normals.reserve(static_cast<std::size_t>(kLobeTableStrata) * kLobeTableStrata);
  for (int i = 0; i < kLobeTableStrata; ++i) {
    const double theta = skin::sampleSurfaceNormalPolar(s, (i + 0.5) / kLobeTableStrata);
    const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    for (int j = 0; j < kLobeTableStrata; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kLobeTableStrata;
      normals.push_back({sinTheta * std::cos(phi), sinTheta * std::sin(phi), -cosTheta});
    }
  }
  return normals;
}

/// Over facets drawn from P_s for a ray at cosθ_i (stratified quadrature over `normals`): the
/// probability that a facet faces the ray (P_f, the walk's redraw test) and that it faces the ray
/// and mirrors it out of the surface (N). Local frame: the ray travels along +z into the surface.
struct FacetFractions {
  double facing = 0, leaving = 0;
};
FacetFractions facetFractions(const std::vector<skin::Vec3>& normals, double cosIncident) {
  const double sinIncident = std::sqrt(std::max(0.0, 1 - cosIncident * cosIncident));
  const skin::Vec3 d{sinIncident, 0, cosIncident};
  int facing = 0, leaving = 0;
  for (const skin::Vec3& m : normals) {
    const double dm = skin::dot(d, m);
    if (!(dm < 0)) continue;
    ++facing;
    const skin::Vec3 out = d - m * (2 * dm);
    if (out.z < 0) ++leaving;
  }
  const double n = static_cast<double>(normals.size());
  return {facing / n, leaving / n};
}

/// Linear interpolation in a table over cosθ = i / (size − 1).
double interpolateOverCosine(const std::vector<double>& table, double cosine) {
  const double x = std::clamp(cosine, 0.0, 1.0) * static_cast<double>(table.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), table.size() - 2);
  const double f = x - static_cast<double>(i);
  return (1 - f) * table[i] + f * table[i + 1];
}

}  // namespace

skin::Specimen loadMaterialSpecimen(const MaterialDesc& desc,
                                    const std::filesystem::path& specimenDir) {
  try {
    skin::Specimen specimen = skin::loadSpecimen(desc.skin.specimen, specimenDir);
    for (const auto& o : desc.skin.overrides) skin::applyOverride(specimen, o);
    const double extra = desc.skin.waterReduction;
    if (!(extra >= 0 && extra <= 1))
      throw SceneError(desc.where, "water reduction must lie in [0, 1]");
    specimen.waterReduction = 1 - (1 - specimen.waterReduction) * (1 - extra);
    skin::validateSpecimen(specimen);
    return specimen;
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(desc.where, std::string("skin material '") + desc.name + "': " + e.what());
  }
}

SkinMaterial::SkinMaterial(const MaterialDesc& desc, const skin::Specimen& specimen,
                           std::size_t materialIndex, double unitCm,
                           const std::vector<double>& channelWavelengths,
                           const skin::SpectralDatabase& spectra, skin::SkinMode skinMode,
                           double effectTolerance,
                           const std::vector<std::vector<std::size_t>>& bundles,
                           std::uint64_t tableRaysPerBin)
    : materialIndex_(materialIndex),
      unitCm_(unitCm),
      aspectRatio_(specimen.surfaceFoldAspectRatio),
      freckles_(desc.skin.freckles, desc.where) {
  if (!(unitCm > 0) || !std::isfinite(unitCm))
    throw SceneError(desc.where, "unit_cm must be a positive number");
  if (!desc.skin.melaninMap.empty()) {
    melaninMap_ = std::make_unique<TextureMap>(desc.skin.melaninMap, desc.where);
    mapMin_ = desc.skin.melaninMapMin;
    mapMax_ = desc.skin.melaninMapMax;
  }
  if (!(mapMin_ >= 0) || !(mapMax_ >= 0) || !std::isfinite(mapMin_) || !std::isfinite(mapMax_))
    throw SceneError(desc.where, "melanin map multipliers must be finite and >= 0");
  const double lo = std::min(mapMin_, mapMax_) * freckles_.minMultiplier();
  const double hi = std::max(mapMin_, mapMax_) * freckles_.maxMultiplier();
  const bool tableMode = skinMode == skin::SkinMode::Table;
  const bool spectralTables = tableMode && !bundles.empty();
  walks_ = std::make_unique<SkinWalkCache>(
      specimen, lo, hi, channelWavelengths, spectra, desc.where,
      tableMode ? SkinTableCache::kTableMelaninLevels : SkinWalkCache::kMelaninLevels,
      spectralTables ? 0.0 : effectTolerance, bundles);
  if (tableMode) {  // a level's tables get walks by the share of the skin it covers
    const std::vector<double> shares =
        levelRayShares(melaninLevelUse(*walks_, melaninMap_.get(), mapMin_, mapMax_, freckles_));
    tables_ = std::make_unique<SkinTableCache>(*walks_, ExitTableCache::shared(),
                                               SkinTableCache::renderSettings(tableRaysPerBin),
                                               spectralTables, shares);
  }
  if (spectralTables)  // each band's tables sampled at once, the entry crossed by its walk
    for (int level = 0; level < walks_->levels(); ++level)
      for (std::size_t b = 0; b < bundles.size(); ++b) {
        std::vector<const skin::ExitTable*> members;
        for (std::size_t channel : bundles[b]) members.push_back(&tables_->table(channel, level));
        tableBundles_.emplace_back(walks_->spectralWalk(b, level), std::move(members));
      }
  const std::vector<skin::Vec3> facetNormals = stratifiedFacetNormals(aspectRatio_);
  for (int i = 0; i < kLobeTableSize; ++i) {
    const double cosine = static_cast<double>(i) / (kLobeTableSize - 1);
    const FacetFractions f = facetFractions(facetNormals, cosine);
    lobeNormalisation_.push_back(f.leaving);
    facetFacing_.push_back(f.facing);
  }
  for (std::size_t c = 0; c < walks_->channels(); ++c)
    surfaceIndex_.push_back(
        walks_->walk(c, 0).optics()[skin::Layer::StratumCorneum].refractiveIndex);
}

double SkinMaterial::melaninMultiplier(const SurfaceHit& hit) const {
  double m = 1;
  if (melaninMap_) {
    const double t = hit.hasUv ? melaninMap_->lookup(hit.uv) : 0.0;
    m = mapMin_ + (mapMax_ - mapMin_) * t;
  }
  return m * freckles_.multiplier(hit.position * unitCm_);
}

double SkinMaterial::surfaceLobeNormalisation(double cosIncident) const {
  return interpolateOverCosine(lobeNormalisation_, cosIncident);
}

double SkinMaterial::surfaceBranchDensity(const glm::dvec3& incident, const glm::dvec3& normal,
                                          const glm::dvec3& outgoing) const {
  const double cosIn = -glm::dot(incident, normal), cosOut = glm::dot(outgoing, normal);
  if (!(cosIn > 0) || !(cosOut > 0)) return 0;
  const glm::dvec3 halfVector = glm::normalize(outgoing - incident);
  const double cosFacet = glm::dot(halfVector, normal);
  const double faces = interpolateOverCosine(facetFacing_, cosIn);
  if (!(cosFacet > 0) || !(faces > 0)) return 0;
  // The first facing facet among kMaxFacetRedraws draws: density D·1{facing}/P_f, drawn at all
  // with probability 1 − (1 − P_f)^R (else the macro normal, which the split does not use).
  const double drawn = 1 - std::pow(1 - faces, skin::kMaxFacetRedraws);
  return facetDensityPerSr(aspectRatio_, cosFacet) /
         (4 * std::fabs(glm::dot(outgoing, halfVector))) * drawn / faces;
}

double SkinMaterial::surfaceFresnel(std::size_t channel, double cosFacet) const {
  return skin::fresnelReflectance(cosFacet, 1.0, surfaceIndex_.at(channel));
}

double SkinMaterial::surfaceLobeDensity(const glm::dvec3& incident, const glm::dvec3& normal,
                                        const glm::dvec3& outgoing) const {
  const double cosIn = -glm::dot(incident, normal), cosOut = glm::dot(outgoing, normal);
  if (!(cosIn > 0) || !(cosOut > 0)) return 0;
  const glm::dvec3 halfVector = glm::normalize(outgoing - incident);  // the mirroring facet normal
  const double cosFacet = glm::dot(halfVector, normal);
  if (!(cosFacet > 0)) return 0;
  const double norm = surfaceLobeNormalisation(cosIn);
  if (!(norm > 0)) return 0;
  return facetDensityPerSr(aspectRatio_, cosFacet) /
         (4 * std::fabs(glm::dot(outgoing, halfVector))) / norm;
}

SkinScatter SkinMaterial::scatter(const SurfaceHit& hit, const glm::dvec3& direction,
                                  std::size_t channel, const EmbreeScene& geometry,
                                  const std::vector<std::size_t>& materialOfShape,
                                  skin::Rng& rng) const {
  // Normals facing the arriving ray (a back-face hit is treated as skin seen from outside).
  const FacingNormals normals = faceTheRay(direction, hit.geometricNormal, hit.shadingNormal);
  const skin::Frame frame(toSkin(-normals.shading));  // z into the skin
  const skin::Vec3 incident = frame.toLocal(toSkin(direction));
  const int level = walks_->level(melaninMultiplier(hit), rng.uniform());
  const skin::SkinPath path = tables_ ? tables_->table(channel, level).sample(incident, rng)
                                      : walks_->walk(channel, level).trace(incident, rng);
  return exitOf(hit, direction, normals, frame, path.end, path.exitDirection, path.exitOffsetXCm,
                path.exitOffsetYCm, geometry, materialOfShape);
}

SkinScatter SkinMaterial::scatterSpectral(const SurfaceHit& hit, const glm::dvec3& direction,
                                          std::size_t bundle, const EmbreeScene& geometry,
                                          const std::vector<std::size_t>& materialOfShape,
                                          skin::Rng& rng, double* weights, double* surfaceWeights,
                                          const std::array<double, 2>* exitSample,
                                          double* entryWeights,
                                          const skin::FacetNumbers* firstFacet) const {
  if (tables_ && tableBundles_.empty())
    throw std::logic_error("SkinMaterial::scatterSpectral: the tables were built per wavelength");
  const FacingNormals normals = faceTheRay(direction, hit.geometricNormal, hit.shadingNormal);
  const skin::Frame frame(toSkin(-normals.shading));
  const skin::Vec3 incident = frame.toLocal(toSkin(direction));
  const int level = walks_->level(melaninMultiplier(hit), rng.uniform());
  const skin::SpectralWalk& walk = walks_->spectralWalk(bundle, level);
  thread_local skin::SpectralPath path;  // reused: the walk keeps its per-λ arrays there
  const bool split = surfaceWeights != nullptr;
  path.exitEntryWeight.clear();
  if (tables_)
    tableBundles_[static_cast<std::size_t>(level) * walks_->bundles() + bundle].sample(
        incident, rng, path, split, exitSample, firstFacet);
  else
    walk.trace(incident, rng, path, split, firstFacet);
  if (path.split)  // one exit per path here (WalkOptions::splitFirstRayleigh is for curves)
    throw std::logic_error("skin material: a spectral path split at a Rayleigh event");
  for (std::size_t i = 0; i < walk.size(); ++i) weights[i] = path.exitWeight[i];
  SkinScatter out = exitOf(hit, direction, normals, frame, path.end, path.exitDirection,
                           path.exitOffsetXCm, path.exitOffsetYCm, geometry, materialOfShape);
  if (entryWeights && out.kind == SkinScatter::Kind::SubsurfaceReflection &&
      path.exitEntryWeight.size() == walk.size()) {
    out.entryWeights = true;
    for (std::size_t i = 0; i < walk.size(); ++i) entryWeights[i] = path.exitEntryWeight[i];
  }
  if (surfaceWeights && !path.surfaceWeight.empty()) {
    out.surfaceBranch = true;
    out.surfaceDirection = glm::normalize(toGlm(frame.toWorld(path.surfaceDirection)));
    for (std::size_t i = 0; i < walk.size(); ++i) surfaceWeights[i] = path.surfaceWeight[i];
  }
  return out;
}

SkinScatter SkinMaterial::exitOf(const SurfaceHit& hit, const glm::dvec3& direction,
                                 const FacingNormals& normals, const skin::Frame& frame,
                                 skin::PathEnd end, const skin::Vec3& exitDirection,
                                 double offsetXCm, double offsetYCm, const EmbreeScene& geometry,
                                 const std::vector<std::size_t>& materialOfShape) const {
  const glm::dvec3 &ng = normals.geometric, &ns = normals.shading;
  SkinScatter out;
  out.point = hit.position;
  out.shadingNormal = ns;
  out.geometricNormal = ng;
  switch (end) {
    case skin::PathEnd::Absorbed:
    case skin::PathEnd::Transmitted:
      out.kind = SkinScatter::Kind::Absorbed;
      return out;
    case skin::PathEnd::EventLimit:
      out.kind = SkinScatter::Kind::EventLimit;
      return out;
    case skin::PathEnd::SurfaceReflection:
      out.kind = SkinScatter::Kind::SurfaceReflection;
      out.direction = glm::normalize(toGlm(frame.toWorld(exitDirection)));
      return out;
    case skin::PathEnd::SubsurfaceReflection:
      break;
  }
  out.kind = SkinScatter::Kind::SubsurfaceReflection;
  const glm::dvec3 offset = (toGlm(frame.t) * offsetXCm + toGlm(frame.b) * offsetYCm) / unitCm_;
  const double offsetLength = glm::length(offset);
  if (!(offsetLength > 0)) return out;
  const glm::dvec3 planePoint = hit.position + offset;
  const double probe = 4 * offsetLength;
  // Probes: from above looking down, from below looking up (both along the entry normal; exact on
  // a plane), then — for offsets beyond the local curvature, where the normal line misses the
  // surface — from the tangent-plane point towards a point one offset length below the entry.
  const glm::dvec3 below = hit.position - ns * offsetLength;
  const Ray probes[3] = {
      {planePoint + ns * probe, -ns, 2 * probe},
      {planePoint - ns * probe, ns, 2 * probe},
      {planePoint, glm::normalize(below - planePoint), glm::length(below - planePoint)}};
  for (const Ray& ray : probes) {
    const std::optional<SurfaceHit> found = geometry.intersect(ray);
    if (!found || materialOfShape[found->shape] != materialIndex_) continue;
    out.point = found->position;
    // Same side convention as at the entry (front faces by winding, or outward for spheres).
    const bool flip = glm::dot(direction, hit.geometricNormal) > 0;
    out.geometricNormal = flip ? -found->geometricNormal : found->geometricNormal;
    out.shadingNormal = flip ? -found->shadingNormal : found->shadingNormal;
    return out;
  }
  out.exitFallback = true;
  return out;
}

}  // namespace hylios
