// Effect planning (issue 5): which processes of the HyLIoS walk a (specimen, wavelength) needs.
//
// Each process p of the walk acts through events in one layer k: absorption by one absorber,
// melanosome / complex interactions, Rayleigh scattering (papillary dermis); surface roughness acts
// at every crossing of the skin surface. A short pilot run of the full walk measures the mean
// distance a ray travels in each layer, E[ℓ_k]; the expected number of events of p per ray is then
// its optical depth along the light's path, τ_p = μ_p · E[ℓ_k] (for melanosomes with θo = 0 only
// the absorbing interactions change the ray, so τ counts those). A walk without p can be coupled
// to the full walk so that both agree until the first p-event (superposed Poisson processes), so
// dropping p changes any exit statistic (R, A, a histogram bin) by at most P(a p-event) ≤ τ_p, and
// dropping a set S by at most Σ_{p∈S} τ_p. The planner drops processes in increasing order of the
// upper confidence bound τ⁺_p (pilot mean + 3 s.e.) while Σ τ⁺ ≤ ε, so |ΔR| ≤ ε.
// With ε = 0 only processes with τ = 0 exactly (zero coefficients) are dropped, which changes
// nothing. kDefaultEffectTolerance is below the standard error of R at 10⁵ rays (≈ 0.0015).
//
// | parameter        | meaning                                                              |
// |------------------|----------------------------------------------------------------------|
// | epsilon          | bound on the change of any exit probability, [0, 1]                  |
// | pilotRays        | rays of the pilot run that estimates E[ℓ_k]                          |
// | incidenceDeg     | the pilot's incidence (spectra); renders plan at 0° and 60°          |
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "skin/absorber.h"
#include "skin/layer.h"
#include "skin/skin_optics.h"
#include "skin/skin_walk.h"

namespace hylios::skin {

inline constexpr double kDefaultEffectTolerance = 1e-3;

enum class Process : std::uint8_t { Absorption, Melanosomes, Rayleigh, SurfaceRoughness };

struct PlannedEffect {
  Process process = Process::Absorption;
  Layer layer = Layer::StratumCorneum;    ///< unused for SurfaceRoughness
  Absorber absorber = Absorber::Water;    ///< Process::Absorption only
  double opticalDepth = 0;                ///< τ_p, pilot estimate (expected events per ray)
  double opticalDepthUpper = 0;           ///< τ⁺_p = τ_p + 3 s.e.
  bool kept = true;
  std::string name() const;               ///< e.g. "absorption: water", "melanosomes", "Rayleigh"
};

struct PlanOptions {
  double incidenceDeg = 0;
  std::uint64_t pilotRays = 2000;
  std::uint64_t seed = 1;
  WalkOptions walk;                       ///< the walk the plan starts from (all processes on)
};

struct EffectPlan {
  double epsilon = kDefaultEffectTolerance;
  double wavelengthNm = 0;
  std::vector<PlannedEffect> effects;     ///< every process with a nonzero coefficient somewhere
  SkinOptics optics;                      ///< the input optics with dropped processes zeroed
  WalkOptions walk;                       ///< the input walk options with dropped switches off
  double droppedDepthBound = 0;           ///< Σ τ⁺ of dropped processes: the bound on |ΔR|

  /// A table: process, layer, optical depth, kept/skipped, and the bound.
  std::string explain() const;
};

/// Plans the walk for `optics` with tolerance epsilon in [0, 1] (std::invalid_argument otherwise).
/// Deterministic for a given seed.
EffectPlan planEffects(const SkinOptics& optics, double epsilon, const PlanOptions& options = {});

}  // namespace hylios::skin
