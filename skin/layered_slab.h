// The generic layered-slab problem of MCML (Wang, Jacques & Zheng 1995): a stack of plane-parallel
// Henyey–Greenstein layers between two ambient media, lit by a collimated pencil beam from above.
// It checks the transport core (Fresnel/TIR at every interface, stepping across layer boundaries,
// event selection, scattering) against published numbers; the HyLIoS walk reuses those parts.
//
// Coordinates: z points down into the stack, z = 0 at its top surface. Lengths in cm,
// coefficients in cm^-1. Photon i of a run uses Rng(seed, 0, i); chunks of photons are summed in
// chunk order, so a result is byte-identical at any thread count.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skin/core/enum_names.h"
#include "skin/core/random.h"
#include "skin/core/statistics.h"
#include "skin/core/vector3.h"

namespace hylios::skin {

/// One homogeneous layer.
struct SlabLayer {
  double refractiveIndex = 1.0;
  double muA_perCm = 0.0;    ///< absorption coefficient
  double muS_perCm = 0.0;    ///< scattering coefficient
  double anisotropyG = 0.0;  ///< Henyey–Greenstein mean cosine, -1 < g < 1
  double thicknessCm = 0.0;  ///< >= 0; +infinity allowed for the last layer (semi-infinite)
};

/// The whole problem: layers from top to bottom between ambient indices.
struct SlabProblem {
  double refractiveIndexAbove = 1.0;
  double refractiveIndexBelow = 1.0;  ///< unused when the last layer is semi-infinite
  std::vector<SlabLayer> layers;
  double incidenceAngleDeg = 0.0;  ///< polar angle of the incoming beam in the ambient, [0, 90)
  /// true: diffuse (cosine-weighted, Lambertian) illumination from above instead of the beam;
  /// incidenceAngleDeg is then ignored. Gives adding-doubling's URU/UTU.
  bool diffuseIncidence = false;
};

/// Throws std::invalid_argument naming the offending field (e.g. "layer 2: mus ...").
void validateSlabProblem(const SlabProblem& problem);

/// How absorption is scored. Analog: the photon dies where it is absorbed (the paper's way), each
/// packet scores in exactly one place. WeightWithRoulette: MCML's implicit capture — each
/// interaction deposits the fraction mua/mut of the weight and the packet goes on with the rest;
/// below weight 0.05 (MCML: 1e-4) it survives a Russian roulette with chance 1/10 and weight x10
/// (unbiased).
enum class AbsorptionScheme { Analog, WeightWithRoulette };
/// WeightWithRoulette's roulette, shared by the scalar and the lane walk: below this weight a
/// packet survives with kSlabRouletteSurvival and carries 1/kSlabRouletteSurvival. MCML rolls
/// below 1e-4; below 0.05 the walk ends its low-weight tails sooner at almost no variance (the
/// MCML sample: 1.15x the efficiency; docs/interpretations.md, "Generic slab").
inline constexpr double kSlabRouletteThreshold = 0.05;
inline constexpr double kSlabRouletteSurvival = 0.1;
/// Named "analog" / "weighted" on the command line (`hylios slab --scheme`).
inline constexpr EnumNames<AbsorptionScheme, 2> kAbsorptionSchemeNames{
    {{AbsorptionScheme::WeightWithRoulette, "weighted"}, {AbsorptionScheme::Analog, "analog"}}};

/// One packet's scores, in units of the incident power (the specular part is not in them).
struct PhotonScores {
  double diffuseReflectance = 0;        ///< weight leaving through the top surface
  double transmittance = 0;             ///< weight leaving through the bottom surface
  double unscatteredTransmittance = 0;  ///< the part of transmittance that never scattered
  double eventLimited = 0;  ///< weight still travelling after kSlabEventLimit events (not scored)
  std::vector<double> layerAbsorptance;  ///< weight absorbed per layer
};

/// Events (interactions and boundary meetings) after which a packet is stopped and its weight
/// booked as event-limited instead of reflected, transmitted or absorbed: a termination guarantee
/// for stacks that a packet would need billions of steps to leave (a thick layer that scatters
/// and never absorbs), as the skin walk's bound (docs/interpretations.md, "Event bound (slab)").
inline constexpr std::uint32_t kSlabEventLimit = std::uint32_t{1} << 20;

/// Traces single packets through a validated problem. Immutable after construction, so one walker
/// serves all threads.
class SlabWalker {
 public:
  /// eventLimit: events after which a packet stops as event-limited (>= 1; kSlabEventLimit).
  SlabWalker(const SlabProblem& problem, AbsorptionScheme scheme,
             std::uint32_t eventLimit = kSlabEventLimit);
  /// Fresnel reflectance of the top surface for the incoming light (deterministic: for diffuse
  /// light the hemispherical average 2 * integral of R(mu) mu dmu); packets start inside with
  /// weight 1 - specularReflectance().
  double specularReflectance() const { return specularReflectance_; }
  /// A packet's weight as it starts inside layer 1: 1 - specularReflectance().
  double launchWeight() const { return launchWeight_; }
  /// A packet's unit direction as it starts inside layer 1 (refracted beam; for diffuse light
  /// drawn with sampleDiffuseEntryCos, the azimuth fixed at 0: the stack cannot see it).
  Vec3 launchDirection(Rng& rng) const;
  /// For diffuse incidence: the cosine (in the ambient) of one packet's incoming direction, drawn
  /// from the density of the light that enters, 2 mu (1 - R(mu)) / (1 - specularReflectance()).
  double sampleDiffuseEntryCos(Rng& rng) const;
  std::size_t layerCount() const { return layers_.size(); }
  /// Runs one packet to its end and overwrites `scores` (its layerAbsorptance is resized).
  void trace(Rng& rng, PhotonScores& scores) const;

  /// A layer as the walk uses it: depth range, extinction, absorbed fraction per interaction,
  /// asymmetry, and the indices of the layer and of its neighbours above and below.
  struct LayerData {
    double zTopCm, zBottomCm, muT_perCm, absorptionProbability, g, n, nAbove, nBelow;
  };
  const std::vector<LayerData>& layers() const { return layers_; }
  AbsorptionScheme scheme() const { return scheme_; }
  bool diffuseIncidence() const { return diffuseIncidence_; }
  std::uint32_t eventLimit() const { return eventLimit_; }

 private:
  std::vector<LayerData> layers_;
  AbsorptionScheme scheme_;
  std::uint32_t eventLimit_;
  double specularReflectance_ = 0;
  double launchWeight_ = 1;
  double launchSinTheta_ = 0, launchCosTheta_ = 1;
  bool diffuseIncidence_ = false;
  double nAmbientAbove_ = 1;
};

struct SlabRunOptions {
  std::uint64_t photons = 100000;
  std::uint64_t seed = 1;
  AbsorptionScheme scheme = AbsorptionScheme::Analog;
  /// Weighted scheme only: true traces eight packets at once in single-precision lanes
  /// (skin/layered_slab_lanes.h, the same laws) when single precision represents the stack
  /// (SlabLaneWalker::represents), else as false; false one packet at a time in double
  /// precision (SlabWalker::trace, the reference the lane walk is tested against).
  bool laneWalk = true;
  /// Events after which a packet stops as event-limited (>= 1); smaller only in tests.
  std::uint32_t eventLimit = kSlabEventLimit;
};

/// Totals over all packets, per incident photon. Rd excludes the specular part; Tt includes the
/// unscattered beam. specular + Rd + Tt + absorptance + eventLimited = 1 (exactly per packet for
/// Analog, in expectation for WeightWithRoulette).
struct SlabResult {
  double specularReflectance = 0;
  Estimate diffuseReflectance, transmittance, unscatteredTransmittance, absorptance;
  Estimate diffuseTransmittance;  ///< transmittance - unscatteredTransmittance
  Estimate eventLimited;  ///< weight stopped by kSlabEventLimit (0 for every sensible stack)
  std::vector<Estimate> layerAbsorptance;
  std::uint64_t photons = 0;
};

/// Validates, then runs options.photons packets in parallel (TBB, current thread limit).
SlabResult simulateLayeredSlab(const SlabProblem& problem, const SlabRunOptions& options);

}  // namespace hylios::skin
