// Effect planning (issue 5): which processes of the HyLIoS walk a (specimen, wavelength) needs.
//
// Each process p of the walk acts through events in one layer k: absorption by one absorber,
// melanosome / complex interactions, Rayleigh scattering (papillary dermis); surface roughness acts
// at every crossing of the skin surface. A short pilot run of the full walk measures the mean
// distance a ray travels in each layer, E[ℓ_k]; the expected number of events of p per ray is then
// its optical depth along the light's path, τ_p = μ_p · E[ℓ_k] (for melanosomes with θo = 0 only
// the absorbing interactions change the ray, so τ counts those: τ = μ_mel · E[ℓ_k] · p_abs, p_abs
// the absorption probability of one interaction). A walk without p can be coupled to the full walk
// so that both agree until the first p-event (superposed Poisson processes), so dropping p changes
// any exit statistic (R, A, a histogram bin) by at most P(a p-event) ≤ min(τ_p, P(ray enters k)),
// and dropping a set S by at most Σ_{p∈S} of those. The planner drops processes while Σ τ⁺ ≤ ε, so
// |ΔR| ≤ ε (at the pilot's ~3σ confidence): first those whose events cost time (melanosomes,
// Rayleigh), then absorbers (dropping one saves no time), each group in increasing τ⁺; one that
// does not fit is passed over for smaller ones.
//
// τ⁺_p, the bound on P(a p-event) (explain()'s "bound" column, may be below τ_p):
// τ⁺_p = min(τ_p + 3 s.e., r⁺_k), r⁺_k the Wilson upper bound (z = 3) of the fraction of pilot rays
// that entered layer k; when fewer than kMinPilotRaysInLayer pilot rays entered k, the s.e. is not
// trusted and τ⁺_p = r⁺_k (≈ 9/N when none did, so unvisited layers are kept unless ε ≥ 9/N).
// Rayleigh acts only on the first scattering of a pass, so μ_R·E[ℓ] over-estimates its τ (safe).
// Surface roughness is never dropped: a rough crossing's law (a continuous facet distribution) and
// the smooth one (two directions) differ in total variation by 1, every ray meets the surface at
// least once, so its bound is ≥ 1 ≥ ε; its row shows the expected crossings' lower bound
// 1 + P(subsurface exit) as τ and +∞ as τ⁺. For θo = 0, p_abs comes from the melanosome
// path-length table (skin/melanosome_path_lengths.h, shared with the tabulated walk), its
// upper value (3 s.e. of the table's mean) in τ⁺.
// With ε = 0 nothing that has a nonzero coefficient is dropped, which changes nothing.
// kDefaultEffectTolerance = 1e-3 is below the standard error of R at 10⁵ rays (≈ 0.0015).
//
// | parameter        | meaning                                                              |
// |------------------|----------------------------------------------------------------------|
// | epsilon          | bound on the change of any exit probability, [0, 1]                  |
// | pilotRays        | rays of the pilot run per (optics, incidence) that estimate E[ℓ_k]  |
// | incidenceDeg     | the pilot's incidences; τ⁺ of a process is the largest over them     |
// | seed             | the pilot's random seed (streams differ from the main run's)         |
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
/// Pilot rays that must enter a layer before τ + 3 s.e. is trusted there.
inline constexpr std::uint64_t kMinPilotRaysInLayer = 30;

enum class Process : std::uint8_t { Absorption, Melanosomes, Rayleigh, SurfaceRoughness };

struct PlannedEffect {
  Process process = Process::Absorption;
  Layer layer = Layer::StratumCorneum;  ///< unused for SurfaceRoughness
  Absorber absorber = Absorber::Water;  ///< Process::Absorption only
  double opticalDepth = 0;              ///< τ_p, pilot estimate (expected events per ray)
  double opticalDepthUpper = 0;  ///< τ⁺_p ≥ P(a p-event) (see above); +∞ for SurfaceRoughness
  bool kept = true;
  std::string name() const;  ///< e.g. "absorption: water", "melanosomes", "Rayleigh"
};

struct PlanOptions {
  std::vector<double> incidenceDeg{0.0};  ///< each in [0, 90); pilotRays rays at each
  std::uint64_t pilotRays = 2000;
  std::uint64_t seed = 1;
  WalkOptions walk;  ///< the walk the plan starts from
};

struct EffectPlan {
  double epsilon = kDefaultEffectTolerance;
  double wavelengthNm = 0;
  std::vector<PlannedEffect> effects;  ///< every process with a nonzero coefficient somewhere
  SkinOptics optics;                   ///< the (first) input optics with dropped processes zeroed
  WalkOptions walk;                    ///< the input walk options with dropped switches off
  double droppedDepthBound = 0;        ///< Σ τ⁺ of dropped processes: the bound on |ΔR|
  std::uint64_t pilotRaysTraced = 0;   ///< the pilot's cost: rays traced in all
  std::vector<double> pilotIncidenceDeg;  ///< for explain()

  std::size_t droppedCount() const;
  /// `other` (e.g. another melanin level at the same wavelength) with this plan's dropped
  /// processes zeroed; layers where nothing is dropped are copied bit for bit.
  SkinOptics apply(const SkinOptics& other) const;
  /// A table: process, layer, optical depth, τ⁺, kept/skipped, then ε and the bound.
  std::string explain() const;
  /// One line: wavelength, processes kept, the skipped ones, the bound.
  std::string summary() const;
};

/// Plans the walk for `optics` with tolerance epsilon in [0, 1] (std::invalid_argument otherwise,
/// and for an incidence outside [0, 90) or zero pilot rays). Deterministic for a given seed.
EffectPlan planEffects(const SkinOptics& optics, double epsilon, const PlanOptions& options = {});

/// One plan shared by several optics at the same wavelength (e.g. the lowest and highest melanin
/// level of a render channel): a process is listed if any of them has it, and its τ, τ⁺ are the
/// largest over the optics and incidences, so the bound holds for each of them.
EffectPlan planEffects(const std::vector<SkinOptics>& optics, double epsilon,
                       const PlanOptions& options = {});

}  // namespace hylios::skin
