// The HyLIoS skin material: at a camera-path hit on skin, the paper's random walk
// (skin/skin_walk.h) simulates both the rough-surface reflection and the subsurface transport, and
// its outcome drives the path (paper Sec. 4; docs/architecture.md, "Data flow").
//
// | parameter (MaterialDesc::skin)  | meaning                                                      |
// |---------------------------------|--------------------------------------------------------------|
// | specimen, overrides             | the layered skin (Tables 1–2), loaded from scenes/specimens/ |
// | water_reduction                 | extra fraction r: water × (1 − r_specimen)(1 − r)            |
// | melanin_map, min, max           | UV texture t → melanin multiplier min + (max − min)·t        |
// | freckles                        | procedural spots (renderer/tracing/freckle_field.h), multiplier      |
//
// SPECTRAL ESTIMATOR (the default, scene key integrator.estimator = "spectral"): the camera path
// carries every channel of its band, and the walk is the spectral walk (skin/spectral_walk.h) of
// the band's channels at the hit's melanin level: one path with a weight per channel, so that no
// absorbed/escaped outcome is drawn per camera path — each channel's exit weight multiplies its
// throughput (expected value), and a surface or subsurface exit continues as below. In table mode
// the band's exit tables are sampled at once instead (skin/exit_table_bundle.h: the entry crossed
// by the band's spectral walk, one exit offset for every channel, each channel weighted by its
// table's P(subsurface) and density ratio). Everything else of this comment holds per channel
// with that weight. At a camera path's first skin hit the entry is split (WalkOptions::
// splitEntryReflection): a first facet whose mirror image of the ray leaves is scored at once as a
// surface branch of weight F_λ(h) along that mirror direction; the branch's law has a closed form
// (surfaceBranchDensity), so every light — area and environment too — gets next-event estimation
// with the lobe F_λ(h)·p(ω), combined with the branch's continuation by the power heuristic.
//
// ESTIMATOR. Reciprocity lets the walk start on the camera side: the camera ray, direction ω_c,
// hits skin at x. Local frame (skin::Frame): z = −n (into the skin, n the shading normal facing the
// ray), t and b span the tangent plane; the walk gets ω_c in that frame and runs for the specimen
// at x (melanin multiplier at x, stochastically rounded to a cached level, skin_walk_cache.h) at
// the path's wavelength. The walk is analog (no weights), so each outcome has probability:
//   absorbed (or event limit) — the path ends, contributing 0;
//   SurfaceReflection (probability R_s(ω_c)), direction ω_s — the path continues from x along the
//     walk's own ω_s, throughput unchanged. Area and environment lights are reached only by this
//     continuation, with MIS weight 1 (no light sampling for that vertex: the walk's density of
//     ω_s — multiple facet bounces, Fresnel-weighted facets, redraws — has no closed form). Delta
//     (point/spot) lights, which no continuation can hit, get next-event estimation with a model
//     lobe g(ω) — the single mirror reflection about a facet normal drawn from P_s (Sec. 4.3),
//     per solid angle g = [P_s(θ_h)/(2π sinθ_h)] / (4|ω·h|) / N(θ_c), h the half vector, N the
//     probability that such a reflection faces the ray and leaves the surface (tabulated per
//     material over cosθ_c). Contribution: g(ω_l)·I/d²; in expectation R_s·g·I/d².
//   SubsurfaceReflection (probability R_ss(ω_c)) at lateral offset (Δx, Δy) cm — the exit point x_o
//     is x + (Δx·t + Δy·b)/unitCm projected back onto the skin surface by probe rays along ∓n
//     (from 4|Δ| above, then from 4|Δ| below), then — for offsets beyond the local curvature —
//     towards the point |Δ| below x; only shapes of this material count. If all miss, x_o = x
//     (counted in RenderStats::exitFallbacks). The walk itself is plane-parallel: offsets
//     comparable to the radius of curvature (millimetres to centimetres in the near IR) are
//     approximations. The exit lobe is modelled as Lambertian about the shading normal n_o at x_o:
//     q(ω) = cosθ_o/π. Light is estimated at x_o by next-event estimation with q (all lights) plus
//     a continuation along a direction sampled from q, the two combined by the power heuristic
//     (delta lights: NEE only). The walk's own exit direction is not used for subsurface exits: MIS
//     needs the density of the continued direction, and only a sample from q has a known one, so
//     NEE and continuation sample the same lobe and their combination is unbiased for it.
// Energy: the expected throughput leaving a skin hit is R_s(ω_c) + R_ss(ω_c) = R(ω_c), the walk's
// total reflectance for that incidence, whatever the lobes; approximations affect only the angular
// distribution of delta-light highlights (g) and of subsurface exitance (q). Under a uniform
// environment L a skin pixel converges to L·R(ω_c) exactly (tests/renderer/integrator_test.cpp).
#pragma once
#include <glm/glm.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/scene/scene.h"
#include "renderer/scene/texture_map.h"
#include "renderer/tracing/embree_scene.h"
#include "renderer/tracing/freckle_field.h"
#include "renderer/tracing/skin_table_cache.h"
#include "renderer/tracing/skin_walk_cache.h"
#include "renderer/tracing/surface_vectors.h"
#include "skin/core/random.h"
#include "skin/exit_table_bundle.h"
#include "skin/skin_mode.h"
#include "skin/spectral_database.h"

namespace hylios {

/// How a walk at a skin hit ended, in world terms.
struct SkinScatter {
  enum class Kind {
    Absorbed,
    EventLimit,
    SurfaceReflection,
    SubsurfaceReflection
  } kind = Kind::Absorbed;
  glm::dvec3 point;            ///< entry point (surface) or projected exit point (subsurface)
  glm::dvec3 shadingNormal;    ///< at `point`, on the side the light left from
  glm::dvec3 geometricNormal;  ///< at `point`, same side
  glm::dvec3 direction;        ///< SurfaceReflection: the walk's exit direction (world, unit)
  bool exitFallback = false;   ///< SubsurfaceReflection: no surface found, exit at the entry point
  /// Spectral walk with the entry split: the surface reflection scored at once (weights in the
  /// caller's array) along surfaceDirection from the entry point, besides the main outcome.
  bool surfaceBranch = false;
  glm::dvec3 surfaceDirection{0};
  /// Table mode, spectral, subsurface exit: the exit weights' first-stage part was written to the
  /// caller's entryWeights (skin::SpectralPath::exitEntryWeight).
  bool entryWeights = false;
};

class SkinMaterial {
 public:
  /// `specimen` already has the material's overrides applied; `materialIndex` is this material's
  /// index in SceneDesc::materials (exit points must land on shapes of this material).
  /// SkinMode::Table samples exit tables (skin/exit_table.h, from ExitTableCache::shared(), with
  /// SkinTableCache::kTableMelaninLevels levels) instead of walking; Walk runs the exact walk.
  /// `bundles` not empty selects the spectral estimator: in walk mode one spectral walk per bundle
  /// and level; in table mode tables built from spectral walks (SkinTableCache's spectral build,
  /// full model, no effect plan).
  SkinMaterial(const MaterialDesc& desc, const skin::Specimen& specimen, std::size_t materialIndex,
               double unitCm, const std::vector<double>& channelWavelengths,
               const skin::SpectralDatabase& spectra,
               skin::SkinMode skinMode = skin::SkinMode::Walk,
               double effectTolerance = skin::kDefaultEffectTolerance,  ///< ε, skin/effect_plan.h
               const std::vector<std::vector<std::size_t>>& bundles = {},
               std::uint64_t tableRaysPerBin = kDefaultTableRaysPerBin);

  /// Melanin multiplier at a hit: melanin map (by uv) × freckles (by position in cm).
  double melaninMultiplier(const SurfaceHit& hit) const;

  /// Runs the walk for a ray travelling along `direction` that hit skin at `hit`.
  /// `materialOfShape[i]` is the material index of shape i.
  SkinScatter scatter(const SurfaceHit& hit, const glm::dvec3& direction, std::size_t channel,
                      const EmbreeScene& geometry, const std::vector<std::size_t>& materialOfShape,
                      skin::Rng& rng) const;

  /// The spectral estimator: the walk for bundle `bundle` (a band's channels, given to the
  /// constructor) at `hit`; weights[i] receives the exit weight of the bundle's i-th channel (the
  /// factor on the path throughput; all 0 when the walk was ended by Russian roulette, which is
  /// reported as Absorbed). In table mode the band's tables are sampled at once (throws
  /// std::logic_error when the tables were built per wavelength, i.e. without bundles).
  /// With `surfaceWeights` (not null) the entry split is on: a surface reflection that a single
  /// facet sends out is scored into surfaceWeights[i] and the walk goes on into the skin
  /// (SkinScatter::surfaceBranch; skin/skin_walk.h, WalkOptions::splitEntryReflection).
  /// `exitSample` (table mode; may be null): a stratified uniform pair for the exit's draw
  /// (skin/exit_table_bundle.h), used in place of two numbers from `rng`. `entryWeights` (may be
  /// null): gets the exit weights without the second stage's ratio where there is one
  /// (SkinScatter::entryWeights). `firstFacet` (may be null): stratified numbers for the rough
  /// surface's first facet at entry (skin::FacetNumbers), in table and walk mode.
  SkinScatter scatterSpectral(const SurfaceHit& hit, const glm::dvec3& direction,
                              std::size_t bundle, const EmbreeScene& geometry,
                              const std::vector<std::size_t>& materialOfShape, skin::Rng& rng,
                              double* weights, double* surfaceWeights = nullptr,
                              const std::array<double, 2>* exitSample = nullptr,
                              double* entryWeights = nullptr,
                              const skin::FacetNumbers* firstFacet = nullptr) const;

  /// The model lobe g (per sr) of a surface reflection into `outgoing` for a ray travelling along
  /// `incident` onto a surface with outward normal `normal` (all unit, world).
  double surfaceLobeDensity(const glm::dvec3& incident, const glm::dvec3& normal,
                            const glm::dvec3& outgoing) const;
  /// N(cosθ) of the header comment (probability that a single facet reflection faces the ray
  /// and leaves the surface), interpolated from the table.
  double surfaceLobeNormalisation(double cosIncident) const;
  /// The split entry's surface branch (SkinScatter::surfaceBranch): the density (per sr) with which
  /// the walk's first facet, the first of kMaxFacetRedraws draws from P_s that faces the ray,
  /// mirrors a ray travelling along `incident` into `outgoing`: D(h)/(4|ω·h|) · (1 − (1 −
  /// P_f)^R)/P_f, h the half vector, P_f(θ_c) the probability that a drawn facet faces the ray
  /// (tabulated like N); 0 for directions that do not leave. The branch's weight is F_λ(h) times
  /// the arriving throughput, so F_λ(h) times this density is its exact lobe: next-event
  /// estimation with it is combined with the branch's continuation by MIS (integrator.cpp).
  double surfaceBranchDensity(const glm::dvec3& incident, const glm::dvec3& normal,
                              const glm::dvec3& outgoing) const;
  /// F of the air–stratum corneum interface at `channel` for a facet at cosine cosFacet to the
  /// ray (the walk's Fresnel reflectance of that facet).
  double surfaceFresnel(std::size_t channel, double cosFacet) const;

  const SkinWalkCache& walks() const { return *walks_; }
  /// The exit tables in table mode, else null.
  const SkinTableCache* tables() const { return tables_.get(); }
  double surfaceAspectRatio() const { return aspectRatio_; }

 private:
  /// The walk's exit in world terms: the entry frame, the path's end, offset and direction.
  /// `normals` face the arriving ray, `frame` is the walk's (z into the skin).
  SkinScatter exitOf(const SurfaceHit& hit, const glm::dvec3& direction,
                     const FacingNormals& normals, const skin::Frame& frame, skin::PathEnd end,
                     const skin::Vec3& exitDirection, double offsetXCm, double offsetYCm,
                     const EmbreeScene& geometry,
                     const std::vector<std::size_t>& materialOfShape) const;

  std::size_t materialIndex_;
  double unitCm_;
  double aspectRatio_;
  std::unique_ptr<TextureMap> melaninMap_;
  double mapMin_ = 1, mapMax_ = 1;
  FreckleField freckles_;
  std::unique_ptr<SkinWalkCache> walks_;
  std::unique_ptr<SkinTableCache> tables_;  ///< table mode only
  /// Table mode with spectral tables: per level and band ([level * bands + band]), the band's
  /// tables sampled at once (skin/exit_table_bundle.h).
  std::vector<skin::ExitTableBundle> tableBundles_;
  std::vector<double> lobeNormalisation_;  ///< N at cosθ = i / (size − 1)
  std::vector<double> facetFacing_;        ///< P_f at cosθ = i / (size − 1)
  std::vector<double> surfaceIndex_;       ///< per channel: the stratum corneum's index
};

/// The specimen of a skin material: loaded by name or path (specimenDir for names), overrides
/// applied in order, water reduction combined. Throws SceneError at desc.where.
skin::Specimen loadMaterialSpecimen(const MaterialDesc& desc,
                                    const std::filesystem::path& specimenDir);

}  // namespace hylios
