// A skin exit for every wavelength of a band at once from the band's exit tables (issue 12, items 1
// and 2: hero wavelengths and expected-value skin in table mode). One draw serves the whole band:
// no wavelength of a camera path goes without a sample, and no absorbed/escaped outcome is drawn.
//
// Sampling, in two stages with a one-sample MIS over the bundle each (Wilkie et al. 2014; the
// balance heuristic, as in skin/spectral_walk.h):
//   1. the surface crossing from air is SpectralWalk::enter: hero j uniform over the bundle, the
//      rough surface crossed with j's law; a reflection is scored there exactly as the walk scores
//      it. A transmission along t gives, per λ, the entry's target density p_λ(e) and hero-λ
//      proposal density q_λ(e);
//   2. the cosine bin k from t.z, drawn as every member table draws it (ExitTable::chooseBin; the
//      probabilities depend on t only);
//   3. a second hero h uniform over the M tables with subsurface exits in bin k; from h's table an
//      offset cell c (radius × offset azimuth) with h's conditional probability π_h(c) among
//      subsurface exits, a radius r within c by the cell's law u_h(r | c) (the same for every table
//      except the overflow cell, uniform up to each table's own largest radius), the offset azimuth
//      and its sign uniform within c. The exit is always subsurface.
// Wavelength λ's exit weight is the product of the two stages' ratios,
//   w_λ = [p_λ(e) / ((1/N) Σ_j q_j(e))] · [S_λ(k) π_λ(c) u_λ(r|c) / ((1/M) Σ_h π_h(c) u_h(r|c))],
// S_λ(k) the subsurface exits' share of the bin's outcome weights in λ's table (its P(subsurface
// exit), absorption included, as ExitTable::sample draws it). The stages are drawn independently,
// so E[w_λ] = E_λ[S_λ(k)], λ's own table's subsurface reflectance, with exit offsets distributed as
// λ's table: exact in expectation for every λ against ExitTable::sample, and the second ratio is at
// most M · S_λ(k). Transmitted and event-limited outcomes, which a render scores 0, are not drawn.
// The exit direction is not drawn either (exitDirection is the outward normal): its law would add a
// ratio to every weight, and the renderer gives subsurface exits a lobe of its own
// (renderer/tracing/skin_material.h).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/exit_table.h"
#include "skin/spectral_walk.h"

namespace hylios::skin {

class ExitTableBundle {
 public:
  /// `entryWalk` crosses the surface; tables[i] is the exit table of its i-th wavelength. All
  /// tables must share their settings. Throws std::invalid_argument when the counts differ, a
  /// table is null or the settings differ. Both must outlive the bundle.
  ExitTableBundle(const SpectralWalk& entryWalk, std::vector<const ExitTable*> tables);

  std::size_t size() const { return tables_.size(); }

  /// One ray arriving from air along `incident` (z > 0). `path` gets end SurfaceReflection (the
  /// walk's weights) or SubsurfaceReflection with the shared exit offset and the weight w_λ of
  /// every λ in exitWeight, and in exitEntryWeight the first stage's part (entry ratio × S_λ):
  /// exitWeight − exitEntryWeight has expectation 0 given the entry; Absorbed (every weight 0)
  /// when no table of the bundle has a subsurface exit in the bin. With `splitEntryReflection` the
  /// entry split of WalkOptions::splitEntryReflection (SpectralPath::surfaceWeight). Absorption
  /// fields stay 0. `stratified` (may be null): two uniform numbers in [0, 1) for the second hero
  /// and its offset cell, e.g. a pixel's stratified or low-discrepancy sample
  /// (renderer/tracing/pixel_sampler.h), instead of two from `rng`; any uniform pair keeps the
  /// weights exact in expectation. `firstFacet` (may be null): the entry's first facet numbers
  /// (SpectralWalk::enter).
  void sample(const Vec3& incident, Rng& rng, SpectralPath& path, bool splitEntryReflection,
              const std::array<double, 2>* stratified = nullptr,
              const FacetNumbers* firstFacet = nullptr) const;

 private:
  /// A member with subsurface exits in a bin, with what sample() reads of it there.
  struct ExitingMember {
    std::size_t member;
    double subsurfaceShare;  ///< subsurface weight / the bin's total outcome weight
  };
  /// Per bin: the members with exits there, and their offset cells' probabilities π_j(c) cell by
  /// cell ([c · members + j]), so that a sample reads one contiguous run instead of one cache
  /// line in every member's table.
  struct ExitingInBin {
    std::vector<ExitingMember> members;
    std::vector<double> cellProbability;
  };
  const SpectralWalk& entryWalk_;
  std::vector<const ExitTable*> tables_;
  std::vector<ExitingInBin> exitingByBin_;
};

}  // namespace hylios::skin
