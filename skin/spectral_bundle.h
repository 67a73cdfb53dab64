// Which wavelengths share a spectral path (issue 11's bundle rule, docs/interpretations.md).
//
// Any wavelengths of one specimen may share a path exactly (skin/spectral_walk.h), but the
// variance of a wavelength's weight grows with how differently the other members would have
// sampled the path. Two laws change across the spectrum enough to matter, so they bound a bundle:
//
// | law                                | bound within a bundle                                      |
// |------------------------------------|------------------------------------------------------------|
// | Algorithm 2's θo (780–1400 nm)     | θo = 0 and θo > 0 never mix; ln(θo_max/θo_min) ≤ maxLogAngleSpread; |
// |                                    | a run of one θo > 0 (the plateau below 780 nm) takes no other θo |
// | Rayleigh, optical depth τ = μR·d   | min(ln(τ_max/τ_min), τ_max − τ_min) ≤ maxRayleighSpread    |
// |  of the papillary dermis           |  (a ratio bound where the layer is thick, a difference     |
// |                                    |  bound where Rayleigh is rare)                             |
// | a smooth surface (no roughness)    | one surface index per bundle (a delta refraction)          |
//
// Wavelengths are taken in increasing order, except that those Algorithm 2 does not deflect
// (θo = 0, from 1400 nm) follow in increasing absorption depth (absorptionDepth), and a bundle is
// closed when the next one would break a bound or the bundle holds maxWavelengths. Members absorbed
// alike die together: the walk's roulette follows the least absorbed member, so a bundle of the
// water bands' strongly absorbed members ends its paths early instead of carrying them along the
// long paths of 1700 or 2200 nm (S1 curve, 1400–2500 nm: 0.87× the time, session 26).
//
// The bounds set the variance at a bundle's edges, where a member's law has neighbours on one side
// only (docs/benchmarks.md, "The spectral estimator"): on the S1 curve (10⁵ rays) the spreads 0.3
// and 1.0 gave a largest standard error of 0.0023 at 890 nm, where 17 plateau members at θo = 5°
// outweighed the ramp's; 0.15 with the plateau rule leaves 0.0016 at 690 nm, the edge of a
// Rayleigh spread of 1.0, and the commands' 0.8 (commandSpectralRun) gives 0.0014, with 33
// bundles instead of 22. Render tables keep 1.0 (one bundle fewer in the visible band). Since the
// commands' tallies subtract the MIS ratio's fluctuation (skin/core/controlled_means.h), their
// curves took a θo spread of 0.3: 24 bundles, the largest standard error 0.0014 (session 21);
// with heroes in shares by law (skin/hero_shares.h) they take 0.6 and a Rayleigh spread of 1.2:
// 16 bundles, the same largest standard error (session 24). With the roulette at 0.3 they take a
// Rayleigh spread of 2.6: two plateau bundles instead of four, 13 in all (session 27).
#pragma once
#include <cstddef>
#include <vector>

#include "skin/skin_optics.h"
#include "skin/skin_walk.h"

namespace hylios::skin {

struct BundleRule {
  std::size_t maxWavelengths = 64;
  double maxLogAngleSpread = 0.15;  ///< the commands' curves use 0.6 (commandSpectralRun)
  double maxRayleighSpread = 1.0;   ///< the commands' curves use 2.6 (commandSpectralRun)
};

/// The Rayleigh optical depth τ of the walked stack at normal incidence (what one pass sees; 0
/// when the walk has no Rayleigh): one of the laws that bound a bundle and set its hero shares.
double rayleighDepth(const SkinOptics& optics, const WalkOptions& walk);

/// The absorption optical depth of the walked stack at normal incidence, Σ μa·thickness over its
/// layers (melanosomes' interiors left out): the order in which undeflected members are grouped.
double absorptionDepth(const SkinOptics& optics, const WalkOptions& walk);

/// Groups of indices into `optics` (each group in increasing wavelength; every index once).
std::vector<std::vector<std::size_t>> groupIntoBundles(const std::vector<SkinOptics>& optics,
                                                       const WalkOptions& walk = {},
                                                       const BundleRule& rule = {});

}  // namespace hylios::skin
