// The layered slab's weighted walk (implicit capture with roulette, skin/layered_slab.h) for eight
// packets at once, one per single-precision lane (skin/core/float_lanes.h): the same laws, step
// for step, as SlabWalker::trace with AbsorptionScheme::WeightWithRoulette, so the same
// expectations; only the arithmetic (float instead of double) and the random numbers differ.
//
// | walk step            | lanes                                                               |
// |----------------------|---------------------------------------------------------------------|
// | packet i's numbers   | xoshiro128+ seeded from Rng(seed, 0, i) (skin/core/lane_random.h);  |
// |                      | its launch direction (diffuse light) drawn from that Rng first      |
// | free path            | −ln(1 − u), u on the grid k·2⁻²⁴: the exponential law cut at 16.6   |
// |                      | optical depths (a mass of 6e−8 moved to the cut)                    |
// | Fresnel coin         | one uniform per boundary meeting (also for matched indices)         |
// | roulette             | below weight 0.05, survive with P = 1677722/2²⁴ (0.1 on the grid)   |
// |                      | and carry 1/P: unbiased on the grid                                 |
// | scattering           | skin/sampling/henyey_greenstein_lanes.h                             |
// | scores               | a packet's own scores, written at its end to its row                |
//
// A lane whose packet ends takes the next packet of the range, so the lanes stay full; each
// packet's row depends on its index alone, and the caller sums rows in index order: results are
// the same at any thread count and on every machine (the AVX2 clone and the SSE2 baseline compute
// the same bits; skin/CMakeLists.txt compiles the file without fused multiply-adds).
#pragma once
#include <cstdint>
#include <vector>

#include "skin/layered_slab.h"

namespace hylios::skin {

class SlabLaneWalker {
 public:
  /// Columns of a packet's row of scores.
  static constexpr std::size_t kDiffuseReflectance = 0, kTransmittance = 1,
                               kUnscatteredTransmittance = 2, kEventLimited = 3,
                               kFirstLayerAbsorptance = 4;

  /// Whether single precision represents `walker`'s stack: every extinction coefficient 0 or in
  /// [1e-30, 1e30] cm⁻¹, every depth at most 1e30 cm (the last layer may be semi-infinite), and
  /// every layer of non-zero thickness at least 1e-30 cm and 2⁻¹⁰ of its bottom depth thick, so
  /// that its boundaries stay about a thousand float spacings apart; and an event limit below
  /// 2³¹. simulateLayeredSlab runs the scalar walk for a stack that fails this.
  static bool represents(const SlabWalker& walker);

  /// `walker` (kept by reference: it must outlive this) must use AbsorptionScheme::
  /// WeightWithRoulette and be represented (represents()); throws std::invalid_argument
  /// otherwise.
  explicit SlabLaneWalker(const SlabWalker& walker);

  /// Scores per packet: the three exits, the event-limited weight (kSlabEventLimit, as the
  /// scalar walk) and one absorptance per layer.
  std::size_t scoresPerPacket() const { return kFirstLayerAbsorptance + layerCount_; }

  /// Traces packets first..last-1 and writes packet i's row at scores + (i − first) · stride.
  void trace(std::uint64_t seed, std::uint64_t first, std::uint64_t last, double* scores) const;

  const SlabWalker& walker() const { return walker_; }

  /// Per layer (index k) and per boundary (index 2k for leaving k upwards, 2k + 1 downwards).
  struct Tables {
    std::vector<float> zTop, zBottom, muT, inverseMuT, absorptionProbability;
    std::vector<float> g, oneMinusG, twoTimesG, twoOneMinusGSquared, twoOnePlusGSquared;
    std::vector<float> eta, etaSquared, oneMinusEtaSquared, relativeIndex;
    std::vector<std::int32_t> matched;
  };

  const Tables& tables() const { return tables_; }

  /// A packet's start inside layer 1 in float: the beam's direction (x, 0, z) and the weight.
  struct Launch {
    float ux, uz, weight;
  };
  const Launch& launchState() const { return launch_; }

 private:
  const SlabWalker& walker_;
  std::size_t layerCount_;
  Tables tables_;
  Launch launch_{};
};

}  // namespace hylios::skin
