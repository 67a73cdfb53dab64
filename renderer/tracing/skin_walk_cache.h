// HyLIoS walks prepared before rendering: one skin::SkinWalk (its SkinOptics) per film channel and
// per level of a quantised melanin multiplier, for one skin material. computeSkinOptics per hit
// would dominate the render; here it runs levels × channels times, in parallel, before the first
// ray — and only for the wavelengths the film needs (once each, even when bands overlap) and the
// materials the scene has.
//
// Melanin levels: the multiplier range [lo, hi] of the material (melanin map × freckles) is split
// into K = kMelaninLevels levels equally spaced in √m, m_k = (√lo + k·(√hi − √lo)/(K − 1))² (one
// level when lo = hi): the skin's response bends most at low melanin, where these levels are
// closest (docs/interpretations.md, "Melanin levels in table mode"). A multiplier m between m_k and
// m_{k+1} picks level k+1 with probability (m − m_k)/(m_{k+1} − m_k) and level k otherwise
// (stochastic rounding with one uniform number). The expected contribution is then the linear
// interpolation in m of the contributions at the two levels: no banding, and an error of
// O((m_{k+1} − m_k)²) in the curvature of the response only.
//
// The melanin multiplier scales, in every layer, the melanosome volume fraction and the colloidal
// melanin fraction (Table 1's two melanin contents) of the specimen.
//
// Effect planning (skin/effect_plan.h): with a tolerance ε > 0 each channel gets one plan from
// pilots at the lowest and highest melanin level, kRenderPilotRays rays each at 0° and 60°
// incidence; a process is skipped at every level of the channel only if its bound, the largest over
// those four pilots, fits in ε. Melanin-borne processes have μ ∝ multiplier (largest at the top
// level), the others the longest paths at the lowest melanin; camera rays meet skin at all angles,
// and 0° (deepest paths) and 60° (longest paths in the top layers) bracket the usual ones. ε = 0:
// no pilot, the full model. Spectral walks (bundles) always run the full model.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "renderer/scene/scene.h"
#include "skin/effect_plan.h"
#include "skin/skin_walk.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "skin/spectral_walk.h"

namespace hylios {

/// `specimen` with both melanin contents of every layer × multiplier.
skin::Specimen scaleMelanin(const skin::Specimen& specimen, double multiplier);

class SkinWalkCache {
 public:
  static constexpr int kMelaninLevels = 33;

  /// Throws SceneError at `where` when a wavelength is outside the spectral data, or when a
  /// multiplied specimen is not valid (e.g. a melanin fraction above 1).
  /// `levels` (≥ 2) replaces kMelaninLevels when the multiplier range is not a single value.
  /// `effectTolerance` is the planner's ε in [0, 1] (0: every process simulated).
  /// `bundles` (the spectral estimator, skin/spectral_walk.h): channel lists that each get one
  /// spectral walk per level, built from the full model (no effect plan is made then).
  SkinWalkCache(const skin::Specimen& specimen, double minMultiplier, double maxMultiplier,
                const std::vector<double>& channelWavelengths,
                const skin::SpectralDatabase& spectra, const SourceLocation& where,
                int levels = kMelaninLevels, double effectTolerance = skin::kDefaultEffectTolerance,
                const std::vector<std::vector<std::size_t>>& bundles = {});

  /// Pilot rays per melanin end level and incidence of the effect planner.
  static constexpr std::uint64_t kRenderPilotRays = 500;
  /// The plan of each distinct channel wavelength, in order of first appearance (empty when ε = 0).
  const std::vector<skin::EffectPlan>& effectPlans() const { return plans_; }
  /// One summary line per plan (full tables when there are at most 4).
  std::string explainEffectPlans() const;

  int levels() const { return levels_; }
  std::size_t channels() const { return channels_; }
  double levelMultiplier(int level) const;
  /// The level for multiplier m with stochastic rounding by uniform u in [0, 1).
  int level(double multiplier, double u) const;
  const skin::SkinWalk& walk(std::size_t channel, int level) const;
  /// The spectral walk of bundle `bundle` (its channels in the order given) at `level`.
  const skin::SpectralWalk& spectralWalk(std::size_t bundle, int level) const;
  std::size_t bundles() const { return bundleCount_; }
  const skin::SkinWalk& walk(std::size_t channel, double multiplier, double u) const {
    return walk(channel, level(multiplier, u));
  }

 private:
  double lo_, hi_;
  double rootLo_, rootHi_;  ///< √lo, √hi: the levels are equally spaced between them
  int levels_;
  std::vector<double> levelMultipliers_;  ///< m_k, k = 0 … levels − 1
  std::size_t channels_;
  std::vector<std::optional<skin::SkinWalk>>
      walks_;                                   ///< [level * distinct wavelengths + distinct index]
  std::vector<std::size_t> distinctOfChannel_;  ///< channel → distinct wavelength index
  std::size_t distinctWavelengths_ = 0;
  std::vector<skin::EffectPlan> plans_;  ///< per distinct wavelength; empty when ε = 0
  std::vector<std::optional<skin::SpectralWalk>> spectralWalks_;  ///< [level * bundles + bundle]
  std::size_t bundleCount_ = 0;
};

}  // namespace hylios
