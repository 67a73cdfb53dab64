// The law of a ray's total path length inside one melanosome, tabulated (issue 5's fast path).
//
// Inside a melanosome the ray's path — chords between Fresnel wall bounces, in units of the
// semi-minor axis a — does not depend on the interior absorption; absorption only truncates it
// (Eq. 1 along each chord). So one melanosome absorbs with probability p1(κ) = 1 − E[exp(−κL)],
// κ = μa·a, L the total internal path length (0 when the ray is reflected at entry). L's law
// depends only on the aspect γ = c/a and the index ratio ρ = n_melanin/n_layer, and ρ does not
// depend on the wavelength (every index is dispersed by the same factor,
// skin/layer_refractive_index.h). N samples of L (traced by skin/melanosome_internal_walk.h with
// the exact interaction's geometry, from one fixed random stream) serve a whole spectrum.
//
// | quantity            | meaning                                                 |
// |---------------------|---------------------------------------------------------|
// | aspect γ            | c/a ≥ 1 of the prolate spheroid                         |
// | indexRatio ρ        | n_melanin / n_layer                                     |
// | κ (muA_perMinorAxis)| interior absorption coefficient × a                     |
// | q = E[exp(−κL)]     | probability that a ray meeting the melanosome survives  |
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "skin/core/statistics.h"

namespace hylios::skin {

class MelanosomePathLengths {
 public:
  static constexpr std::size_t kDefaultSampleCount = std::size_t{1} << 16;

  /// Samples `sampleCount` path lengths. Throws std::invalid_argument for an aspect outside
  /// [1, 1e6], a non-positive or non-finite index ratio, or fewer than 2 samples.
  MelanosomePathLengths(double aspect, double indexRatio,
                        std::size_t sampleCount = kDefaultSampleCount);

  double aspect() const { return aspect_; }
  double indexRatio() const { return indexRatio_; }
  std::size_t sampleCount() const { return lengths_.size(); }
  /// The sampled total internal path lengths L (units of a; 0 for rays reflected at entry).
  const std::vector<double>& pathLengths() const { return lengths_; }
  /// The same lengths in single precision (relative rounding 6e-8), half the memory: the spectral
  /// walk draws from it at random, where the table's size in the cache sets the speed.
  const std::vector<float>& pathLengthsSingle() const { return singleLengths_; }

  /// q(κ) = mean of exp(−κL): the probability that a ray crosses one melanosome unabsorbed.
  /// Throws std::invalid_argument for κ negative or not finite.
  double survivalProbability(double muA_perMinorAxis) const;
  /// p1(κ) = 1 − q(κ), summed as mean of −expm1(−κL) (accurate at small κ).
  double absorptionProbability(double muA_perMinorAxis) const;
  /// 1 − q(κ)^count for `count` melanosomes met in turn (0 for count 0).
  double absorptionProbability(double muA_perMinorAxis, unsigned count) const;
  /// 1 − (1 − p1)^count from one melanosome's absorption p1 in [0, 1] (0 for count 0), without
  /// cancellation at small p1.
  static double absorptionByCount(double oneMelanosome, unsigned count);
  /// Mean of L (units of a) with its standard error.
  Estimate meanPathLength() const;
  /// Fraction of the samples reflected at entry (L = 0 exactly), the limit of q as κ → ∞.
  double reflectedAtEntryFraction() const;

  /// The process-wide table for (γ, ρ, N), built on first use (thread-safe; keyed by the exact
  /// values given). The same key always gives the same table (one fixed random stream).
  static std::shared_ptr<const MelanosomePathLengths> shared(
      double aspect, double indexRatio, std::size_t sampleCount = kDefaultSampleCount);

 private:
  double aspect_, indexRatio_;
  std::vector<double> lengths_;
  std::vector<float> singleLengths_;
  std::size_t reflectedAtEntry_ = 0;
};

/// x rounded to 12 significant digits (x > 0): the key of the shared tables, so that indices
/// dispersed by the same factor give one table despite last-bit differences in their ratio.
double melanosomeTableKey(double x);

}  // namespace hylios::skin
