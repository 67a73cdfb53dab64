// The spectral walk's state along one path (skin/spectral_walk.h), shared by the files that walk
// it: skin/spectral_walk.cpp (the flights, scatterings, stays and the path's end) and
// skin/spectral_walk_surface.cpp (the rough air–skin surface and the stack's bottom). Not part of
// the library's interface.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "skin/spectral_walk.h"
#include "skin/spectral_weights.h"

namespace hylios::skin::spectral_walk_detail {
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// log(1/kSpectralRouletteWeight): the roulette's depth bound while no roulette was survived.
inline const double kRouletteDepthBoundAtOne = std::log(1.0 / kSpectralRouletteWeight);
/// The most indices drawn ahead (a complex's melanosomes, rounded up to three).
inline constexpr unsigned kPendingTableIndices = 48;

/// The walk's progress along one path: everything but the SpectralPath it writes, so that a path
/// split at a Rayleigh event continues as two copies of it (SpectralWalk::splitAtRayleigh).
struct PathProgress {
  Vec3 position{0, 0, 0};
  Vec3 direction;
  std::size_t slab = 0;
  std::size_t hero = 0;
  bool rayleighAvailable = true;
  double roulette = 1;                          ///< product of 1/P over the roulettes survived
  double branchWeight = 1;                      ///< ½ in each branch of a split path
  double stayCm = 0, stayMelaninCm = 0;         ///< path in the current slab since the stay began
  std::array<double, kLayerCount> pathCm{};     ///< by slab: path travelled there (λ-free)
  std::array<double, kLayerCount> melaninCm{};  ///< by slab: path inside melanin (λ-free)
  /// The optical depth of the least absorbed λ, summed stay by stay (Russian roulette's bound),
  /// and the depth below which roulette × e^{−depth} stays above kSpectralRouletteWeight.
  double leastDepth = 0;
  double rouletteDepthBound = kRouletteDepthBoundAtOne;
  /// Sums whose per-λ densities SpectralWalk::settleDensities adds to logDensity once, at the end
  /// (each λ's log density is linear in them): Algorithm 2's scatterings (count, Σθ), and by slab
  /// the path flown while Rayleigh was available and the Rayleigh events.
  unsigned angleCount = 0;
  double angleSumRad = 0;
  std::array<double, kLayerCount> rayleighCm{};
  std::array<unsigned, kLayerCount> rayleighEvents{};
  /// Tabulated melanosomes: path-length table indices drawn ahead of the meeting that uses them,
  /// so that their loads were prefetched (SpectralWalk::meetMelanosomes); used last in, first out.
  std::array<std::uint32_t, kPendingTableIndices> pendingIndex;
  unsigned pendingCount = 0;
  std::vector<double> logDensity;  ///< per λ: log p_λ(path) up to a common factor
  /// Per hero j: log(n·c_j) + log q_j(path) − log p_j(path), c_j hero j's share (1/n: uniform)
  /// and q_j the density with which hero j proposed the path (p_j except after a forced
  /// transmission, where q_j lacks the Fresnel factor).
  std::vector<double> proposalOffset;
};
}  // namespace hylios::skin::spectral_walk_detail

namespace hylios::skin {
/// The walk's state for one path (the per-λ arrays live in the SpectralPath, reused across paths).
class SpectralWalk::State : public spectral_walk_detail::PathProgress {
 public:
  State(SpectralPath& p, std::size_t n, bool layers, bool melanosomes)
      : path(p), ratio(p.scratch), stays(p.stays) {
    startPath(n, layers, melanosomes);
    logDensity.assign(n, 0.0);
    proposalOffset.assign(n, 0.0);
  }
  /// The state of `other`'s path so far, continued into `p` (a branch: p's weights zero, no
  /// surface weight of its own, the progress and stays so far copied).
  State(SpectralPath& p, const State& other)
      : PathProgress(other), path(p), ratio(p.scratch), stays(p.stays) {
    startPath(other.logDensity.size(), !other.path.absorbed.empty(),
              !other.path.absorbedInMelanosomes.empty());
    p.events = other.path.events;
    p.exitOffsetXCm = other.path.exitOffsetXCm;
    p.exitOffsetYCm = other.path.exitOffsetYCm;
    stays = other.stays;
  }
  SpectralPath& path;
  std::vector<double>& ratio;              ///< scratch for MIS ratios
  std::vector<SpectralPath::Stay>& stays;  ///< the stays so far (per-layer absorption only)

  /// Per λ: p_λ / Σ_j c_j q_j (1 for a single wavelength sampled by its own law), into `out`.
  void misRatios(std::vector<double>& out) const {
    const std::size_t n = logDensity.size();
    out.assign(n, 1.0);
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j)
      top = std::max({top, logDensity[j], logDensity[j] + proposalOffset[j]});
    if (!std::isfinite(top)) return out.assign(n, 0.0);
    spectral_weights::exponentialsOfSum(n, logDensity.data(), proposalOffset.data(), -top,
                                        out.data());
    double proposal = 0;
    for (std::size_t j = 0; j < n; ++j) proposal += out[j];
    const double scale = static_cast<double>(n) / proposal;
    spectral_weights::exponentials(n, logDensity.data(), 1.0, -top, out.data());
    for (std::size_t i = 0; i < n; ++i) out[i] *= scale;
  }

  /// Every per-λ outcome 0 (a path that leaves at the surface, or pauses there, adds nothing).
  void zeroOutcomes() {
    for (std::vector<double>* v :
         {&path.exitWeight, &path.absorbedTotal, &path.absorbed, &path.absorbedInMelanosomes})
      std::fill(v->begin(), v->end(), 0.0);
  }

 private:
  /// The path's per-λ outcomes sized for n wavelengths (SpectralWalk::finish writes all of them;
  /// a path that ends or pauses before, zeroOutcomes), no split, no stays.
  void startPath(std::size_t n, bool layers, bool melanosomes) {
    path.exitWeight.resize(n);
    path.absorbedTotal.resize(n);
    path.absorbed.resize(layers ? kLayerCount * n : 0);
    path.absorbedInMelanosomes.resize(layers && melanosomes ? kLayerCount * n : 0);
    path.transmittedDirection.clear();
    path.surfaceWeight.clear();
    path.split = false;
    path.splitAtEvent = 0;
    stays.clear();
  }
};

}  // namespace hylios::skin
