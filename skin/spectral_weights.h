// The per-wavelength loops of the spectral walk (skin/spectral_walk.h) as kernels over contiguous
// arrays, one wavelength per element, so that the compiler vectorises them: the exponentials of a
// path's stays and of its MIS ratios were most of the walk's time (docs/benchmarks.md, "The
// spectral estimator", speed).
//
// | kernel            | computes, for every wavelength i < n                                     |
// |-------------------|--------------------------------------------------------------------------|
// | stayLosses        | the transmittance after each stay and the weight each stay absorbed, by  |
// |                   | layer and the part taken by melanin (as SpectralWalk::finish books it)   |
// | pathDepths        | the optical depth of the whole path (no per-stay booking)                |
// | exponentials      | exp of an array (skin/core/vector_math.h)                                |
// | reflectances      | the Fresnel reflectance of the air–skin interface at one angle (fresnel) |
// | addLogReflectances| its log, added to the log densities (a reflection at a facet)           |
// | addRefraction-    | the log density of a rough-surface refraction for each λ's index: the    |
// |  Densities        | generalised half vector's facet density, Fresnel and Jacobian (Walter et |
// |                   | al. 2007), as SpectralWalk::crossFacet adds it                           |
//
// On x86-64 with GCC each kernel is also compiled for AVX-512 and AVX2 and chosen at load time
// (skin/core/vector_clones.h); skin/CMakeLists.txt compiles this file with -ffp-contract=off so
// that no clone fuses a multiply and an add: every clone computes the same bits, and results stay
// the same on every machine.
#pragma once
#include <cstddef>

#include "skin/core/vector3.h"
#include "skin/spectral_walk.h"

namespace hylios::skin::spectral_weights {

/// An absorption coefficient per λ in both precisions (melanin's inside melanosomes, or a slab's)
/// and its largest value.
struct AbsorptionCoefficients {
  const double* muA_perCm;       ///< n values
  const float* muA_perCmSingle;  ///< the same rounded to float (the series' depths; stayLosses)
  double largestMuA_perCm;       ///< max of muA_perCm (bounds a stay's depth: stayLosses' series)
};
using MelaninAbsorption = AbsorptionCoefficients;

/// What stayLosses reads of the walk per slab: its coefficients and its layer.
struct SlabAbsorption : AbsorptionCoefficients {
  std::size_t layer;  ///< index(layer) < kLayerCount
};

/// Walks the stays in order. On return transmitted[i] = exp(−depth_i) of the whole path (as the
/// product of the stays' transmittances), and for every layer ℓ: absorbed[ℓ·n + i] = Σ over the
/// stays in ℓ of roulette·(T_before − T_after)·ratio[i], inMelanin[ℓ·n + i] = the same shares
/// weighted by melanin depth / stay depth (both overwritten); absorbed and inMelanin hold
/// kLayerCount·n values, and inMelanin may be null (melanin's share not booked). Each stay's
/// absorbed fraction 1 − e^{−d} is its series in single precision (relative error below 1e−6)
/// where the bound largestMuA_perCm·cm + melanin.largestMuA_perCm·melaninCm on every λ's d is at
/// most 1/2 (and no coefficient exceeds 1e30 /cm), else 1 − exp(−d) in double; the transmittances
/// and losses accumulate in double.
/// work: 2n floats of scratch.
void stayLosses(std::size_t n, const SpectralPath::Stay* stays, std::size_t stayCount,
                const SlabAbsorption* slabs, const MelaninAbsorption& melanin, const double* ratio,
                double* transmitted, double* absorbed, double* inMelanin, float* work);

/// depth[i] = Σ_k slabs[k].muA_perCm[i]·pathCm[k] + melaninMuA_perCm[i]·melaninCm[k].
void pathDepths(std::size_t n, std::size_t slabCount, const SlabAbsorption* slabs,
                const double* pathCm, const double* melaninCm, const double* melaninMuA_perCm,
                double* depth);

/// out[i] = exp(scale·x[i] + offset) (vectorExp: 0 below −708).
void exponentials(std::size_t n, const double* x, double scale, double offset, double* out);
/// out[i] = exp(x[i] + y[i] + offset).
void exponentialsOfSum(std::size_t n, const double* x, const double* y, double offset, double* out);

/// out[i] = fresnel(cosI, n1, n2).reflectance with (n1, n2) = (index[i], 1) from inside the skin,
/// (1, index[i]) from the air (the same bits as fresnel()).
void reflectances(std::size_t n, double cosI, const double* index, bool fromInside, double* out);
/// logDensity[i] += log of reflectances' out[i].
void addLogReflectances(std::size_t n, double cosI, const double* index, bool fromInside,
                        double* logDensity);
/// For a ray d refracted into t by a rough facet (macro normal `macro`, facet density
/// ∝ (aspect²·cos² + sin²)⁻²): per λ the facet h that refracts d into t with λ's indices; where it
/// exists (facing, Fresnel < 1), logDensity[i] += log of its facet density, 1 − F, n2²|cos t| and
/// the Jacobian 1/(n1 cos d − n2 cos t)², and proposalOffset[i] −= log(1 − F) when `forced`
/// (a transmission proposed without its Fresnel factor); elsewhere logDensity[i] = −∞.
/// inverseIndex[i] = 1/index[i] (the Fresnel ratio from the air without a division).
void addRefractionDensities(std::size_t n, const Vec3& d, const Vec3& t, const Vec3& macro,
                            const double* index, const double* inverseIndex, bool fromInside,
                            double aspectSquared, bool forced, double* logDensity,
                            double* proposalOffset);

}  // namespace hylios::skin::spectral_weights
