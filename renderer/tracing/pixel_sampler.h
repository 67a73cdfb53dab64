// The numbers a camera sample draws (issue 12, item 3). A camera path asks a SampleStream for its
// decisions in a fixed order — the camera sample (band or channel 1-D, sub-pixel position 2-D,
// lens 2-D), then at each vertex the integrator's own choices (a dielectric's 1-D coin, the light
// sample: light 1-D, triangle 1-D, position 2-D; the cosine bounce 2-D; at the first skin hit of
// a spectral path, in table mode the exit's draw 2-D (skin/exit_table_bundle.h), then the rough
// surface's first facet 2-D + 1-D (skin::FacetNumbers)) — and hands the skin walks its independent
// generator (stream.rng()): their hundreds of other decisions gain nothing from stratification.
//
// independent: every number from skin::Rng(seed, pixel, sample), drawn in the order above, with the
//   band or channel stratified over blocks of `strata` consecutive samples of the pixel, each block
//   rotated by its own stream (Cranley–Patterson).
// sobol: the first kLowDiscrepancyDimensions dimensions from Owen-scrambled Sobol' points, padded
//   (pbrt-v4's PaddedSobolSampler, Burley 2020 "Practical Hash-based Owen Scrambling"): each 1-D
//   request is Sobol' dimension 0 (van der Corput), each 2-D request dimensions 0 and 1 (a
//   (0,2)-sequence), each with its own Owen scramble of the sample index (a shuffle that maps the
//   first 2^m indices onto an aligned block of 2^m, so every power-of-two prefix is still a
//   (0,m,2)-net) and of each coordinate; the seeds are hashes of (seed, pixel, half, dimension).
//   Dimensions after the cap come from the sample's Rng.
//
// The film's two halves (renderer/image/render_noise.h) stay independent estimates, drawn from
// two independently scrambled sequences: from sample 8 on the samples of a pixel come in blocks
// of 4 that alternate between them (samples 8–11, 16–19, … are points 4–7, 8–11, … of the first;
// 12–15, 20–23, … those of the second); samples 0–7 give points 0–3 of each, the first two
// alternating (0, 2 and 1, 3), so that a render of 2 samples already has both halves. Each half is
// a randomised quasi-Monte Carlo estimate of its own, so the halves' difference is an unbiased
// noise figure (render_noise.h weighs unequal halves). At any multiple of 4 samples from 8 on,
// each half holds whole aligned blocks of 4 points of a (0,2)-sequence, every one a (0,2,2)-net:
// at 12 spp 8 points and 4, where alternating single samples (even and odd) left each half 6
// points, a net of 4 and 2 stragglers that barely helped (docs/benchmarks.md, session 18).
// (Consecutive points of one Sobol' sequence are anticorrelated — points 2k and 2k+1 fall in
// opposite halves of the pixel in x and in y — so a split within one sequence would overstate the
// noise by the difference between the pixel's halves.)
//
// Deterministic: a sample's numbers depend only on (seed, pixel, sample), never on the thread or
// the pass that draws it.
#pragma once
#include <array>
#include <cstdint>

#include "renderer/scene/sampler_kind.h"
#include "skin/core/random.h"

namespace hylios {

/// Sobol' points in 32-bit fixed point (value / 2^32 in [0, 1)) and their scrambles.
namespace sobol {
/// Dimension 0: the base-2 radical inverse (van der Corput) of `index`.
std::uint32_t dimension0(std::uint32_t index);
/// Dimension 1: primitive polynomial x + 1, direction numbers v_1 = 1/2, v_k = v_(k-1) ⊕ v_(k-1)/2
/// (the upper-triangular Pascal matrix mod 2); with dimension 0 a (0,2)-sequence.
std::uint32_t dimension1(std::uint32_t index);
/// A nested uniform (Owen) scramble of the binary digits of `value`, most significant first: digit
/// k is flipped or not by a hash of `seed` and the k digits above it. Bijective; maps every aligned
/// block of 2^m values onto an aligned block of 2^m, so it keeps (t,m,s)-nets nets.
std::uint32_t owenScramble(std::uint32_t value, std::uint32_t seed);
/// owenScramble(dimension0(owenScramble(i, shuffleSeed)), seed) for reversedIndex =
/// dimension0(i): point i of a shuffled, scrambled van der Corput sequence.
std::uint32_t scrambledRadicalInverse(std::uint32_t reversedIndex, std::uint32_t shuffleSeed,
                                      std::uint32_t seed);
/// The same for dimensions 0 and 1 with one shuffle: owenScramble(dimension0(j), seedX) and
/// owenScramble(dimension1(j), seedY) for j = owenScramble(i, shuffleSeed).
std::array<std::uint32_t, 2> scrambledSobol2D(std::uint32_t reversedIndex,
                                              std::uint32_t shuffleSeed, std::uint32_t seedX,
                                              std::uint32_t seedY);
}  // namespace sobol

/// The film's halves (above): whether sample s of a pixel belongs to the second half, and which
/// point of its half's sequence it is.
constexpr std::uint64_t kFilmHalfBlock = 4;
constexpr bool inSecondFilmHalf(std::uint64_t sample) {
  if (sample < 4) return sample % 2 == 1;
  if (sample < 8) return sample >= 6;
  return sample / kFilmHalfBlock % 2 == 1;
}
constexpr std::uint64_t filmHalfPoint(std::uint64_t sample) {
  if (sample < 4) return sample / 2;
  if (sample < 8) return 2 + sample % 2;
  return sample / (2 * kFilmHalfBlock) * kFilmHalfBlock + sample % kFilmHalfBlock;
}

/// Low-discrepancy dimensions per camera path (sobol): the camera sample (5), at the first skin hit
/// a table-mode exit's draw (2) and the entry's first facet (3), and the light sample and bounce of
/// the first vertices (6 each); the rest comes from the sample's Rng.
constexpr std::uint32_t kLowDiscrepancyDimensions = 22;

/// The numbers of one camera path (see above). Cheap to copy; holds a pointer to the sample's Rng.
class SampleStream {
 public:
  /// The independent sampler: every number from `rng`.
  explicit SampleStream(skin::Rng& rng) : rng_(&rng) {}
  /// Point `index` of the scrambled Sobol' sequence whose scrambles derive from `scrambleSeed`;
  /// dimensions past kLowDiscrepancyDimensions from `rng`.
  SampleStream(skin::Rng& rng, std::uint64_t scrambleSeed, std::uint32_t index)
      : rng_(&rng),
        scrambleSeed_(scrambleSeed),
        reversedIndex_(sobol::dimension0(index)),
        sobol_(true) {}

  /// One number in [0, 1).
  double get1D();
  /// Two numbers in [0, 1) (stratified jointly by sobol).
  std::array<double, 2> get2D();
  /// The sample's independent generator (the skin walks; every number of an independent stream).
  skin::Rng& rng() const { return *rng_; }
  /// The stream of a branch traced before the path goes on (the surface reflection split off at a
  /// skin entry): its own dimensions (sobol), so the path's later decisions keep theirs whatever
  /// the branch draws; the same Rng (independent: the numbers follow on as before).
  SampleStream branch() const;
  bool lowDiscrepancy() const { return sobol_; }
  /// Dimensions drawn so far.
  std::uint32_t dimension() const { return dimension_; }

 private:
  skin::Rng* rng_;
  std::uint64_t scrambleSeed_ = 0;
  std::uint32_t index() const { return sobol::dimension0(reversedIndex_); }
  std::uint32_t reversedIndex_ = 0;  ///< the point's index, bit-reversed (the scrambles use it)
  std::uint32_t dimension_ = 0;
  bool sobol_ = false;
};

/// What a camera sample needs before its path starts.
struct CameraSample {
  double band = 0;              ///< u in [0, 1) for Film::sampleBand or Film::sampleChannel
  double filmX = 0, filmY = 0;  ///< offsets in the pixel, [0, 1)
  double lensU = 0, lensV = 0;  ///< Camera::generateRay's lens sample
};

class PixelSampler {
 public:
  /// `strata`: the film's bands (spectral) or channels (per wavelength), for the independent
  /// sampler's rotated blocks; at least 1.
  PixelSampler(SamplerKind kind, std::uint64_t seed, std::uint64_t strata);

  SamplerKind kind() const { return kind_; }
  /// The stream of sample `sample` of pixel `pixel` (p = y·width + x); `rng` must be
  /// skin::Rng(seed, pixel, sample) and outlive the stream. Throws std::invalid_argument for a
  /// sample index of 2^33 or more (sobol: 2^32 points per half).
  SampleStream stream(std::uint64_t pixel, std::uint64_t sample, skin::Rng& rng) const;
  /// The camera sample, the first numbers of `stream` (that of (pixel, sample)).
  CameraSample cameraSample(std::uint64_t pixel, std::uint64_t sample, SampleStream& stream) const;

 private:
  SamplerKind kind_;
  std::uint64_t seed_;
  std::uint64_t strata_;
};

}  // namespace hylios
