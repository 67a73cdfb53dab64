// The HyLIoS walk of one path for a bundle of wavelengths (issue 11): the geometry of a path is
// shared, every wavelength carries its own weight, and for every λ the weight has exactly the
// expectation of the per-wavelength analog walk (skin/skin_walk.h).
//
// What depends on λ, and how each dependence is carried (docs/interpretations.md, "Spectral walk"):
// | dependence                         | treatment                                                   |
// |------------------------------------|-------------------------------------------------------------|
// | absorption by the layers (Eq. 3)   | weight exp(−μa(λ)·ℓ) per layer stay, never sampled          |
// | melanin inside melanosomes         | the internal path (λ-free geometry) traced or drawn from the |
// |                                    | path-length table; weight exp(−μa_mel(λ)·ℓ_melanin)         |
// | Rayleigh (λ⁻⁴, once per pass)      | sampled with the hero's coefficient; path-density ratio     |
// | Algorithm 2's θo(λ), 780–1400 nm   | sampled with the hero's θo; path-density ratio              |
// | rough air–skin surface (n(λ))      | facet drawn once; reflection: Fresnel ratio; transmission:  |
// |                                    | the hero's refracted direction, density of each λ through   |
// |                                    | its own generalised half vector (Walter et al. 2007)        |
// | smooth bottom into a fixed index   | Fresnel ratio; transmitted directions per λ (path ends)     |
// | layer/layer and melanin/layer      | index ratios do not depend on λ (skin/layer_refractive_     |
// | interfaces                         | index.h): shared exactly                                    |
//
// Hero-wavelength sampling (Wilkie et al. 2014) with the balance heuristic over the bundle: each
// path draws its hero among the bundle's wavelengths (uniformly, or with WalkOptions::
// heroSharesByLaw in shares c_j, skin/hero_shares.h) and makes every λ-dependent choice with the
// hero's law; wavelength λ's score is f_λ/Σ_j c_j p_j, i.e. its transmittance times
// p_λ(path)/Σ_j c_j p_j(path). The mixture bounds that ratio by 1/c_λ whatever the bundle, and it
// is exact in expectation for every λ. The walk tracks log p_λ relative to a common factor.
// The ratio's expectation is exactly 1, so the tallies subtract its fluctuation as a control
// variate (skin/core/controlled_means.h, SkinTally).
// Russian roulette on the largest weight (checked at layer boundaries) ends paths unbiasedly.
// WalkOptions::splitFirstRayleigh splits a path at its first Rayleigh event into a forward and a
// backward branch of weight ½ (the phase function is even in cos θ): SpectralPath::backward.
// Degenerate ratios (a delta whose position depends on λ: the redraw cap's macro normal with
// different indices) give weight 0 to every λ whose delta lies elsewhere, which is still exact.
// Bundles that would make the ratios wide (θo = 0 against θo > 0, very different Rayleigh depths)
// are never formed: skin/spectral_bundle.h groups the wavelengths.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/fresnel_pair.h"
#include "skin/hero_shares.h"
#include "skin/layer.h"
#include "skin/melanosome_internal_walk.h"
#include "skin/melanosome_path_lengths.h"
#include "skin/sampling/polar_rejection_sampling.h"
#include "skin/skin_optics.h"
#include "skin/skin_walk.h"
#include "skin/surface_index_groups.h"

namespace hylios::skin {

/// One spectral path's outcome: a shared end and geometry, a score per wavelength of the bundle.
struct SpectralPath {
  PathEnd end = PathEnd::EventLimit;  ///< Absorbed: ended by Russian roulette (scores 0)
  Vec3 exitDirection;                 ///< shared exit direction (reflection; rough-surface exits)
  double exitOffsetXCm = 0, exitOffsetYCm = 0;
  std::uint32_t events = 0;
  /// Per λ: the weight that leaves with the path (reflectance / transmittance score; for
  /// EventLimit the weight still carried when the walk was stopped).
  std::vector<double> exitWeight;
  /// Per λ (ExitTableBundle's subsurface exits only; empty otherwise): exitWeight without the
  /// second stage's mixture ratio π_λ(c)/mean_h π_h(c), i.e. the entry's ratio × the subsurface
  /// share. Given the entry, exitWeight − exitEntryWeight has expectation 0: the renderer's
  /// control variate for the exit point's light (renderer/tracing/integrator.h).
  std::vector<double> exitEntryWeight;
  /// Per λ: transmitted directions through a smooth bottom (PathEnd::Transmitted only; depend on
  /// λ).
  std::vector<Vec3> transmittedDirection;
  /// Per λ: the weight reflected by the surface at entry while the path went on into the skin
  /// (empty when the entry was sampled; then a surface reflection is end = SurfaceReflection).
  std::vector<double> surfaceWeight;
  Vec3 surfaceDirection;
  /// Per λ: absorbed weight, estimated as MIS ratio − exits (exact in expectation: 1 − R − T).
  std::vector<double> absorbedTotal;
  /// Per layer and λ, at index(layer)·N + λ for a bundle of N (WalkOptions::layerAbsorption):
  /// weight absorbed on the way, booked per stay in a layer (layers' absorbers and melanosomes
  /// together; empty otherwise). Layer by layer, so that per-λ loops read contiguous values.
  std::vector<double> absorbed;
  /// The same places: the part of `absorbed` taken by melanin inside melanosomes (each stay's loss
  /// shared by optical depth; empty without WalkOptions::melanosomeAbsorption).
  std::vector<double> absorbedInMelanosomes;

  /// A path split at its first Rayleigh event (WalkOptions::splitFirstRayleigh): this path
  /// holds the forward branch, backward[0] the backward one, each scored with weight ½ (its
  /// weights above already include the ½; its surfaceWeight is empty: the entry's is this
  /// path's). splitAtEvent: the events both branches share (counted in each one's `events`).
  bool split = false;
  std::uint32_t splitAtEvent = 0;
  std::vector<SpectralPath> backward;  ///< holds one path when split (kept for reuse)

  /// The walk's workspace (kept to avoid allocations per path).
  struct Stay {
    std::size_t slab;
    double cm, melaninCm, roulette;
  };
  std::vector<Stay> stays;
  std::vector<double> scratch;
  std::vector<double> work;  ///< per-λ arrays of SpectralWalk::finish (skin/spectral_weights.h)
  std::vector<float> singleWork;  ///< stayLosses' scratch
};

/// Uniform numbers in [0, 1) for the first facet of the rough surface a path from air meets, e.g. a
/// pixel's stratified or low-discrepancy sample (renderer/tracing/pixel_sampler.h): the polar
/// angle's first rejection trial (SurfaceNormalPolarSampler::sample) and the azimuth
/// (azimuthFromUniform). Any uniform numbers keep every weight exact in expectation; later facets
/// and redraws come from the path's Rng.
struct FacetNumbers {
  std::array<double, 2> polar{};
  double azimuth = 0;
};

/// A spectral path's surface entry alone (SpectralWalk::enter), for samplers that tabulate what
/// follows (skin/exit_table_bundle.h): the densities of the crossing per λ, so that the rest of the
/// path can join the same one-sample MIS over the bundle.
struct SpectralEntry {
  Vec3 direction;        ///< transmitted direction (z > 0), the same for every λ
  std::size_t hero = 0;  ///< the wavelength whose law made the crossing (by the hero shares)
  /// Per λ, up to one common additive constant: log p_λ, the density of the crossing under λ's
  /// own law (target), and log q_λ, the density with which hero λ would have proposed it (they
  /// differ by the Fresnel factor of a forced transmission, WalkOptions::splitEntryReflection),
  /// plus log(n·c_λ) where the shares are not uniform (WalkOptions::heroSharesByLaw).
  std::vector<double> logTarget, logProposal;
};

/// Tabulated melanosomes (WalkOptions::tabulatedMelanosomes): each melanosome met draws its
/// internal path length from a table of this many traced paths (skin/melanosome_path_lengths.h), 4×
/// the analog table's, so its sampling error (≈ 0.1 % of one melanosome's absorption) stays far
/// below the noise of any curve.
inline constexpr std::size_t kSpectralMelanosomeTableSamples = std::size_t{1} << 18;

/// Russian roulette: below this largest weight a path survives with probability weight / it.
/// 0.3 instead of 0.05 ended the S1 curve's faint paths sooner: 0.89x its time at the same
/// variance (0.6 raised it 5-17 %; docs/benchmarks.md, session 27).
inline constexpr double kSpectralRouletteWeight = 0.3;

class SpectralWalk {
 public:
  /// `bundle` holds the optics of one specimen at each wavelength of the bundle (at least one).
  /// Throws std::invalid_argument when the wavelengths cannot share a path: different thicknesses,
  /// melanosome geometry, surface roughness or layer index ratios, θo zero for some but not all,
  /// or a smooth surface (options.roughSurface false) with different surface indices; and for
  /// everything SkinWalk rejects.
  SpectralWalk(const std::vector<SkinOptics>& bundle, WalkOptions options = {});

  std::size_t size() const { return wavelengthCount_; }
  const WalkOptions& options() const { return options_; }

  /// Follows one path arriving from air along `incidentDirection` (z > 0); `path` is reused.
  void trace(const Vec3& incidentDirection, Rng& rng, SpectralPath& path) const {
    trace(incidentDirection, rng, path, options_.splitEntryReflection);
  }
  /// The same with the entry split (WalkOptions::splitEntryReflection) chosen per call, and the
  /// first facet's numbers from `firstFacet` (may be null: from `rng`).
  void trace(const Vec3& incidentDirection, Rng& rng, SpectralPath& path, bool splitEntryReflection,
             const FacetNumbers* firstFacet = nullptr) const;
  /// The surface crossing of trace() alone. Returns true when the path entered the skin; then
  /// `entry` holds its direction, hero and densities, and `path` only the surface weights of a
  /// split entry (SpectralPath::surfaceWeight). Otherwise `path` is the surface reflection, scored
  /// exactly as trace() scores it. `firstFacet` as for trace().
  bool enter(const Vec3& incidentDirection, Rng& rng, SpectralPath& path, SpectralEntry& entry,
             bool splitEntryReflection, const FacetNumbers* firstFacet = nullptr) const;
  /// A path that has just crossed into the skin along `transmittedDirection` (unit, z > 0), the
  /// same for every wavelength (like SkinWalk::traceEntered; exit tables are built from these).
  void traceEntered(const Vec3& transmittedDirection, Rng& rng, SpectralPath& path) const;

 private:
  struct Slab {
    Layer layer = Layer::StratumCorneum;
    double topCm = 0, bottomCm = 0;
    double referenceIndex = 1;           ///< the index at the first wavelength (ratios are λ-free)
    double muMelanosome_perCm = 0;       ///< Eq. 6 (λ-free)
    bool hasRayleigh = false;            ///< some λ has a Rayleigh coefficient here
    std::vector<double> muA_perCm;       ///< per λ
    std::vector<float> muA_perCmSingle;  ///< the same in float (stayLosses' series)
    std::vector<double> muRayleigh_perCm;  ///< per λ (empty without Rayleigh)
    std::vector<double> logRayleigh;       ///< per λ: log muRayleigh_perCm
    double leastMuA_perCm = 0;             ///< min over λ of muA_perCm
    double largestMuA_perCm = 0;           ///< max over λ of muA_perCm
    /// 1/μ of the free paths (a multiply per event instead of a division): melanosomes alone,
    /// and per hero with Rayleigh (empty without Rayleigh); +∞ where μ = 0 (not used there).
    double inverseMuMelanosomeCm = std::numeric_limits<double>::infinity();
    std::vector<double> inverseMuScatterCm;
    /// The crossings into the next deeper and shallower slab (precomputed ratios; unused at the
    /// stack's ends).
    FresnelPair intoDeeper, intoShallower;
  };
  struct Melanosomes {  ///< a layer's melanosome shape (λ-free)
    MelanosomeGeometry geometry;
    double semiMinorAxisCm = 0;
    unsigned count = 1;  ///< melanosomes per meeting: m in complexes, 1 dispersed
    std::shared_ptr<const MelanosomePathLengths> table;  ///< tabulated mode
  };
  class State;

  void traceEntered(State& s, Rng& rng) const;
  /// A new path along `direction`: one event (its surface crossing), no offset, the hero drawn.
  void startPath(State& s, const Vec3& direction, Rng& rng) const;
  /// The crossing from air; false when the surface reflected the path, which is then scored.
  bool enterFromAir(State& s, Rng& rng, bool splitEntryReflection,
                    const FacetNumbers* firstFacet) const;
  /// The hero: by heroShares_ (uniform unless WalkOptions::heroSharesByLaw).
  std::size_t drawHero(Rng& rng) const;
  /// The rough (or smooth) surface crossing of Sec. 4.3 from air (fromInside false) or from the
  /// skin; returns whether the ray ended on the far side, updating s.direction and densities.
  /// `firstFacet` (may be null) supplies the first facet's numbers.
  bool crossSurface(State& s, bool fromInside, Rng& rng, bool splitEntry = false,
                    const FacetNumbers* firstFacet = nullptr) const;
  /// One Fresnel test on facet m (the macro normal when `delta`); true when transmitted.
  bool crossFacet(State& s, const Vec3& m, const Vec3& macro, bool delta, bool fromInside, Rng& rng,
                  bool forceTransmission = false) const;
  /// The smooth bottom of a truncated stack into options.belowRefractiveIndex; true when through.
  bool crossBottom(State& s, Rng& rng) const;
  /// Ends the stay in the current slab: adds its path lengths (and records it for layer
  /// absorption).
  void endStay(State& s) const;
  /// Russian roulette on the largest weight; false when the path was ended.
  bool survivesRoulette(State& s, Rng& rng) const;
  /// Splits s at its first Rayleigh event (scattering cosine ±|cosR|, azimuth phi): traces the
  /// backward branch into s.path.backward[0] to its end, and leaves s as the forward branch.
  void splitAtRayleigh(State& s, double cosR, double sinR, const Azimuth& phi, Rng& rng) const;
  /// Ends the path: `end`, scores = roulette × transmittance × MIS ratio × the branch's weight
  /// (0 when `scores` false).
  void finish(State& s, PathEnd end, bool scores) const;
  /// Adds the densities deferred in s (State::angleCount and the Rayleigh sums) to s.logDensity.
  void settleDensities(State& s) const;
  void meetMelanosomes(State& s, std::size_t k, Rng& rng) const;
  /// Three uniform path-length table indices from one random number, onto s's pending indices.
  static void drawTableIndices(State& s, Rng& rng);
  /// The last pending table index (drawn first when none is pending).
  static std::uint32_t takeTableIndex(State& s, Rng& rng);

  WalkOptions options_;
  std::size_t wavelengthCount_ = 0;
  std::vector<Slab> slabs_;
  std::vector<std::optional<Melanosomes>> melanosomes_;  ///< by slab
  std::vector<double> melaninMuA_perCm_;                 ///< per λ: inside melanosomes
  std::vector<float> melaninMuA_perCmSingle_;            ///< the same in float
  double leastMelaninMuA_perCm_ = 0;
  double largestMelaninMuA_perCm_ = 0;
  std::vector<double> meanAngleRad_;           ///< per λ: θo of Algorithm 2
  std::vector<double> logAngleNormalisation_;  ///< per λ: log of p(θ)·e^{θ/θo}/sinθ
  bool anglesDiffer_ = false;
  std::vector<double> surfaceIndex_;  ///< per λ: the top layer's index
  SurfaceIndexGroups surfaceGroups_;  ///< surfaceIndex_'s distinct values
  std::vector<double> bottomIndex_;   ///< per λ: the deepest layer's index
  bool surfaceIndicesDiffer_ = false;
  bool splitsRayleigh_ = false;  ///< paths split at their first Rayleigh event
  double smallestSurfaceIndex_ = 1;
  std::optional<SurfaceNormalPolarSampler> facetPolar_;
  double aspectSquared_ = 1;
  HeroShares heroShares_;
};

}  // namespace hylios::skin
