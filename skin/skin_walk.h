// The HyLIoS random walk of one ray through the six skin layers (paper Sec. 4, Fig. 5).
//
// Local frame: the skin surface is the plane z = 0, z grows into the skin, layers are stacked in
// the order of skin/layer.h. A ray enters from air (n = 1) through the rough surface (Sec. 4.3),
// then travels with free paths from all coefficients of its layer (Eq. 1, sampled as one summed
// coefficient with the event chosen in proportion): absorption by the layer's absorbers
// (Sec. 4.1), melanosome / melanosome-complex interactions (Sec. 4.2.2), Rayleigh scattering in
// the papillary dermis at most once per pass (Sec. 4.2.1). Every layer boundary is a Fresnel test
// with total internal reflection; the dermis–hypodermis boundary reflects everything diffusely.
//
// | parameter            | meaning                                                    |
// |----------------------|------------------------------------------------------------|
// | SkinOptics           | per-layer coefficients at one wavelength (skin_optics.h)   |
// | incident direction   | unit vector with z > 0 (travelling into the skin)          |
// | Rng                  | the ray's own random stream                                |
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/layer.h"
#include "skin/melanosome_interaction.h"
#include "skin/rough_surface.h"
#include "skin/skin_optics.h"

namespace hylios::skin {

/// How a ray's walk ended.
enum class PathEnd : std::uint8_t {
  SurfaceReflection,     ///< reflected by the rough surface without entering the skin
  SubsurfaceReflection,  ///< entered the skin and left it again through the surface
  Transmitted,           ///< left through the bottom of a truncated stack (WalkOptions)
  Absorbed,              ///< absorbed in `layer` (by an absorber or inside a melanosome)
  EventLimit,            ///< stopped after kMaxEvents (counted, never silently dropped)
};

struct SkinPath {
  PathEnd end = PathEnd::EventLimit;
  Layer layer = Layer::StratumCorneum;  ///< where it was absorbed (PathEnd::Absorbed)
  bool absorbedInMelanosome = false;
  Vec3 exitDirection;        ///< outside the skin: z < 0 reflected, z > 0 transmitted
  double exitOffsetXCm = 0;  ///< lateral exit position relative to the entry point
  double exitOffsetYCm = 0;
  std::uint32_t events = 0;  ///< interactions and interface tests on the way
};

/// Switches for the processes of the walk and the shape of the stack (defaults = the paper's
/// model).
struct WalkOptions {
  bool melanosomes = true;
  bool rayleigh = true;
  bool roughSurface = true;
  /// The deepest layer simulated. Above the reticular dermis (e.g. the epidermis-only samples of
  /// Fig. 8, deepest = StratumBasale) the stack ends in a smooth interface to a medium of index
  /// belowRefractiveIndex through which rays leave (PathEnd::Transmitted); with the reticular
  /// dermis the dermis–hypodermis junction reflects everything diffusely (Sec. 4.3).
  Layer deepestLayer = Layer::ReticularDermis;
  double belowRefractiveIndex = 1.0;
  /// Fast path (issue 5): a melanosome's absorption is drawn from its tabulated probability
  /// (skin/melanosome_path_lengths.h) instead of tracing the ray inside it.
  bool tabulatedMelanosomes = false;
  /// Spectral walk (skin/spectral_walk.h) only: book the absorbed weight per layer (one exp per
  /// layer stay and wavelength); without it only the total absorptance (1 − R − T) is scored.
  bool layerAbsorption = true;
  /// Spectral walk only, with layerAbsorption: also book the part of each layer's absorbed weight
  /// taken by melanin inside melanosomes (SkinTally::melanosomeAbsorptance); without it that
  /// quantity is not scored (the commands print no such column).
  bool melanosomeAbsorption = true;
  /// Spectral walk only (renders): at the first facet from air whose mirror image leaves the
  /// surface, score that reflection for every λ at once (SpectralPath::surfaceWeight, expected
  /// value) and force the path through the facet instead of drawing the Fresnel choice.
  bool splitEntryReflection = false;
  /// Spectral walk only (scalar curves): split a path at its first Rayleigh event into a forward
  /// and a backward branch of weight ½ each (SpectralPath::backward). Exact, since the Rayleigh
  /// phase function is even in cos θ.
  bool splitFirstRayleigh = false;
  /// Spectral walk only (scalar curves): heroes drawn in shares by the span of law each member
  /// stands for (skin/hero_shares.h) instead of uniformly; the balance heuristic takes the same
  /// shares, so every weight stays exact.
  bool heroSharesByLaw = false;
};

/// Distance travelled in each layer by one ray (cm), indexed by index(Layer); filled on request
/// (the effect planner's pilot run, skin/effect_plan.h).
struct LayerPathLengths {
  std::array<double, kLayerCount> cm{};
};

class SkinWalk {
 public:
  /// Hard bound on events per ray; the walk ends with PathEnd::EventLimit past it.
  static constexpr std::uint32_t kMaxEvents = 1u << 20;

  /// Throws std::invalid_argument when no layer down to options.deepestLayer has thickness, or
  /// when a process that is switched on has invalid constants (surface aspect ratio, melanosomes).
  explicit SkinWalk(const SkinOptics& optics, WalkOptions options = {});

  /// Follows one ray arriving from air along `incidentDirection` (z > 0). When `lengths` is not
  /// null, the distance travelled in each layer is added to it.
  SkinPath trace(const Vec3& incidentDirection, Rng& rng,
                 LayerPathLengths* lengths = nullptr) const;
  /// The first step of trace: the ray from air meets the (rough) skin surface.
  InterfaceCrossing enterFromAir(const Vec3& incidentDirection, Rng& rng) const;
  /// The rest of trace: a ray that has just crossed into the top layer at the entry point,
  /// travelling along `transmittedDirection` (z > 0). events starts at 1 (the entry crossing).
  SkinPath traceEntered(const Vec3& transmittedDirection, Rng& rng,
                        LayerPathLengths* lengths = nullptr) const;

  const SkinOptics& optics() const { return optics_; }
  const WalkOptions& options() const { return options_; }

 private:
  /// Per-layer constants, computed once per walk (the hot loop only reads them).
  struct Slab {
    Layer layer;
    double topCm, bottomCm;
    double refractiveIndex;
    double muA_perCm;
    double muAPlusMelanosome_perCm;    ///< absorption + melanosome coefficients
    double muTotalWithRayleigh_perCm;  ///< + Rayleigh (first scattering of a pass)
    double muTotalWithoutRayleigh_perCm;
  };
  InterfaceCrossing crossSurface(const Vec3& direction, double nFrom, double nTo, Rng& rng) const;

  SkinOptics optics_;
  WalkOptions options_;
  std::array<Slab, kLayerCount> slabs_{};
  std::array<MelanosomeLayer, kLayerCount> melanosomes_{};  ///< by slab, where it has melanosomes
  std::optional<RoughSurface> roughSurface_;                ///< set when options.roughSurface
  std::size_t slabCount_ = 0;  ///< layers of nonzero thickness, top to bottom
};

}  // namespace hylios::skin
