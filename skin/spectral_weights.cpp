#include "skin/spectral_weights.h"

#include <cmath>

#include "skin/core/vector_clones.h"
#include "skin/core/vector_math.h"

namespace hylios::skin::spectral_weights {
namespace {
/// fresnel(cosThetaIncident, n1, n2).reflectance (skin/fresnel.cpp), the same operations with
/// selects for its branches (so that a loop of it vectorises); cosT as fresnel's cosTransmitted.
inline double fresnelReflectance(double cosThetaIncident, double n1, double n2, double& cosT) {
  const double absCos = std::fabs(cosThetaIncident);
  const double cosI = absCos < 1.0 ? absCos : 1.0;  // fmin(1, |cos|), NaN → 1 as fmin
  const double ratio = n1 / n2;
  const double cosTSquared = (1.0 - ratio) * (1.0 + ratio) + ratio * ratio * cosI * cosI;
  const bool total = cosTSquared <= 0.0;  // total internal reflection
  const double root = std::sqrt(total ? 0.0 : cosTSquared);
  const double n1cosI = n1 * cosI, n2cosT = n2 * root;
  const double n2cosI = n2 * cosI, n1cosT = n1 * root;
  const double rs = (n1cosI - n2cosT) / (n1cosI + n2cosT);
  const double rp = (n1cosT - n2cosI) / (n1cosT + n2cosI);
  const double reflectance = 0.5 * (rs * rs + rp * rp);
  const bool same = n1 == n2;
  cosT = same ? cosI : root;
  return same ? 0.0 : (total ? 1.0 : reflectance);
}

/// fresnelReflectance's reflectance with the ratio n1/n2 given and the s and p terms over one
/// division (FresnelPair's form, skin/fresnel_pair.h): the same law to rounding, for the
/// refraction densities, where divisions were a large part of the kernel's cost.
inline double refractionReflectance(double cosThetaIncident, double n1, double n2, double ratio) {
  const double absCos = std::fabs(cosThetaIncident);
  const double cosI = absCos < 1.0 ? absCos : 1.0;
  const double cosTSquared = (1.0 - ratio) * (1.0 + ratio) + ratio * ratio * cosI * cosI;
  const bool total = cosTSquared <= 0.0;  // total internal reflection
  const double root = std::sqrt(total ? 0.0 : cosTSquared);
  const double sNumerator = n1 * cosI - n2 * root, sDenominator = n1 * cosI + n2 * root;
  const double pNumerator = n1 * root - n2 * cosI, pDenominator = n1 * root + n2 * cosI;
  const double sN2 = sNumerator * sNumerator, sD2 = sDenominator * sDenominator;
  const double pN2 = pNumerator * pNumerator, pD2 = pDenominator * pDenominator;
  const double reflectance = 0.5 * (sN2 * pD2 + pN2 * sD2) / (sD2 * pD2);
  return n1 == n2 ? 0.0 : (total ? 1.0 : reflectance);
}

/// The air–skin reflectance at index ni: (n1, n2) = (ni, 1) from inside, (1, ni) from the air,
/// chosen by arithmetic (inside = 1 or 0, outside = 1 − inside; exact: 0 or 1 factors), since a
/// select on the flag stops a loop vectorising.
inline double surfaceReflectance(double cosI, double ni, double inside, double outside) {
  double cosT;
  return fresnelReflectance(cosI, inside * ni + outside, outside * ni + inside, cosT);
}

/// Facet densities within [1e-30, 1e30] (aspect² there) keep the whole refraction density within
/// the double range: one log of the product instead of two.
constexpr double kOneLogAspectSquaredBound = 1e30;

template <bool kForced, bool kOneLog>
__attribute__((always_inline)) inline void refractionDensities(
    std::size_t n, const Vec3& d, const Vec3& t, const Vec3& macro, const double* index,
    const double* inverseIndex, bool fromInside, double aspectSquared,
    double* __restrict logDensity, double* __restrict proposalOffset) {
  // (n1, n2) = (index, 1) or (1, index) by arithmetic: a select on the flag stops vectorising.
  const double inside = fromInside ? 1.0 : 0.0, outside = 1.0 - inside;
  const double dx = d.x, dy = d.y, dz = d.z, tx = t.x, ty = t.y, tz = t.z;
  const double mx = macro.x, my = macro.y, mz = macro.z;
  for (std::size_t i = 0; i < n; ++i) {
    const double ni = index[i];
    const double n1 = inside * ni + outside, n2 = outside * ni + inside;  // exact: 0 or 1 factors
    // The facet that refracts d into t for these indices: the generalised half vector n1·d − n2·t.
    double hx = dx * n1 - tx * n2, hy = dy * n1 - ty * n2, hz = dz * n1 - tz * n2;
    const double length = std::sqrt(hx * hx + hy * hy + hz * hz);
    const bool hasLength = length > 0;
    const double inverse = 1.0 / (hasLength ? length : 1.0);
    hx = hx * inverse, hy = hy * inverse, hz = hz * inverse;
    const bool flip = dx * hx + dy * hy + dz * hz > 0;
    hx = flip ? hx * -1.0 : hx, hy = flip ? hy * -1.0 : hy, hz = flip ? hz * -1.0 : hz;
    const double cosD = dx * hx + dy * hy + dz * hz, cosT = tx * hx + ty * hy + tz * hz;
    const double cosFacet = hx * mx + hy * my + hz * mz;  // the facet's polar angle about macro
    const double ratio = inside * ni + outside * inverseIndex[i];  // n1/n2, exact: 0 or 1 factors
    const double reflectance = refractionReflectance(cosD, n1, n2, ratio);
    // Where that facet exists: facing, with some transmission (the conditions as 0/1 doubles:
    // GCC 12 does not vectorise this loop with a conjunction of bools).
    const double okLength = hasLength ? 1.0 : 0.0, okT = cosT < 0 ? 1.0 : 0.0;
    const double okFacet = cosFacet > 0 ? 1.0 : 0.0, okF = reflectance < 1.0 ? 1.0 : 0.0;
    const bool valid = okLength * okT * okFacet * okF > 0.5;
    const double sin2 = (1.0 - cosFacet) * (1.0 + cosFacet);
    const double facetDensity = aspectSquared * cosFacet * cosFacet + sin2;  // D ∝ this⁻²
    const double jacobianDenominator = n1 * cosD - n2 * cosT;
    // (1 − F)·n2²|cos t| / (n1 cos d − n2 cos t)² in one log: each factor is bounded (the
    // denominator is ≥ |n1 − n2|·|cos t| for a refraction); the facet density, which an extreme
    // aspect ratio makes extreme, in the same log unless kOneLog is false (its own log).
    const double transmitted = 1.0 - reflectance;
    const double logTransmitted = kForced ? vectorLog(transmitted) : 0.0;
    const double numerator = transmitted * (n2 * n2 * std::fabs(cosT));
    const double jacobianSquared = jacobianDenominator * jacobianDenominator;
    const double logDensityHere =
        kOneLog ? vectorLog(numerator / (jacobianSquared * (facetDensity * facetDensity)))
                : vectorLog(numerator / jacobianSquared) - 2.0 * vectorLog(facetDensity);
    logDensity[i] = valid ? logDensity[i] + logDensityHere : -HUGE_VAL;
    // A forced transmission was proposed without the Fresnel factor: hero i's proposal density
    // lacks its (1 − F), which the MIS denominator must not hold either.
    if (kForced) proposalOffset[i] -= valid ? logTransmitted : 0.0;
  }
}

/// (−1)^{j+1}/j!, the coefficients of 1 − e^{−d} = Σ_{j ≥ 1} (−1)^{j+1} d^j/j!.
constexpr int kSeriesTerms = 10;
/// Coefficients above it stay in double: the series' float form needs them and every depth
/// μa·cm within float's range (a larger coefficient sends its stays to the double form).
constexpr double kLargestSingleMuA_perCm = 1e30;
struct Expm1Series {
  double coefficient[kSeriesTerms] = {};
  constexpr Expm1Series() {
    double inverseFactorial = 1.0;
    for (int j = 1; j < kSeriesTerms; ++j) {
      inverseFactorial /= j;
      coefficient[j] = j % 2 == 1 ? inverseFactorial : -inverseFactorial;
    }
  }
};
constexpr Expm1Series kExpm1Series;

/// (1 − e^{−d})/d by its series Σ_{1 ≤ j ≤ kTerms} (−1)^{j+1} d^{j−1}/j! (Horner), in single
/// precision (16 lanes of AVX-512 where double has 8): the loss per unit depth, which splits a
/// stay's loss among its absorbers without a division. Its truncation stays below 1e−9 relative
/// for d ≤ 1/64 (4 terms), 1/8 (6) and 1/2 (9), under float's rounding (6e−8).
template <int kTerms>
__attribute__((always_inline)) inline float absorbedFractionPerDepthSingle(float d) {
  static_assert(kTerms > 0 && kTerms < kSeriesTerms);
  float p = static_cast<float>(kExpm1Series.coefficient[kTerms]);
  for (int j = kTerms - 1; j >= 1; --j) p = p * d + static_cast<float>(kExpm1Series.coefficient[j]);
  return p;
}

/// One stay of stayLosses: the path's transmittance per λ updated, the stay's loss (without the
/// MIS ratio) added to its layer's sums.
struct StayBooking {
  std::size_t n;
  const AbsorptionCoefficients& slab;
  const AbsorptionCoefficients& melanin;
  double cm, melaninCm, roulette;
  double* transmitted;
  double* lost;
  double* lostInMelanin;
  float* fraction;           ///< n: the stay's absorbed fraction per λ (series forms)
  float* fractionInMelanin;  ///< n: melanin's part of it
};

/// The series forms (kTerms > 0) in two passes: the absorbed fraction per λ in single precision
/// (relative error below 1e-6: the series' truncation below 1e-8 and a rounding per term), then
/// the transmittance and the losses updated in double from it. A stay's fraction is small, so
/// its relative error moves the transmittance by less than 1e-6 of the stay's loss.
/// kMelanin: the stay crossed melanosomes (their depth adds to the stay's); kBookMelanin: their
/// share of the loss is booked as well.
template <int kTerms, bool kMelanin, bool kBookMelanin>
__attribute__((always_inline)) inline void bookSeriesStay(const StayBooking& b) {
  const float* __restrict muA = b.slab.muA_perCmSingle;
  const float* __restrict melaninMuA = b.melanin.muA_perCmSingle;
  float* __restrict fraction = b.fraction;
  float* __restrict fractionInMelanin = b.fractionInMelanin;
  const float cm = static_cast<float>(b.cm), melaninCm = static_cast<float>(b.melaninCm);
  for (std::size_t i = 0; i < b.n; ++i) {
    const float melaninDepth = kMelanin ? melaninMuA[i] * melaninCm : 0.0f;
    const float d = muA[i] * cm + melaninDepth;
    const float perDepth = absorbedFractionPerDepthSingle<kTerms>(d);
    fraction[i] = perDepth * d;  // melanin's part: its depth × the loss per unit depth
    if (kBookMelanin) fractionInMelanin[i] = perDepth * melaninDepth;
  }
  double* __restrict transmitted = b.transmitted;
  double* __restrict lost = b.lost;
  double* __restrict lostInMelanin = b.lostInMelanin;
  const double roulette = b.roulette;
  for (std::size_t i = 0; i < b.n; ++i) {
    const double before = transmitted[i];
    const double loss = before * static_cast<double>(fraction[i]);
    lost[i] += roulette * loss;
    if (kBookMelanin)
      lostInMelanin[i] += roulette * (before * static_cast<double>(fractionInMelanin[i]));
    transmitted[i] = before - loss;
  }
}

/// A stay too deep for the series (some λ's depth above 1/2): 1 − e^{−d} in double.
template <bool kMelanin, bool kBookMelanin>
__attribute__((always_inline)) inline void bookDeepStay(const StayBooking& b) {
  const double* __restrict muA = b.slab.muA_perCm;
  const double* __restrict melaninMuA = b.melanin.muA_perCm;
  double* __restrict transmitted = b.transmitted;
  double* __restrict lost = b.lost;
  double* __restrict lostInMelanin = b.lostInMelanin;
  const double cm = b.cm, melaninCm = b.melaninCm, roulette = b.roulette;
  for (std::size_t i = 0; i < b.n; ++i) {
    const double melaninDepth = kMelanin ? melaninMuA[i] * melaninCm : 0.0;
    const double d = muA[i] * cm + melaninDepth;
    const double before = transmitted[i];
    const double fraction = 1.0 - vectorExp(-d);  // d > 1/2: no cancellation to speak of
    // The share of melanin (0 when the stay absorbed nothing; the division is then not used).
    const double share = d > 0 ? melaninDepth / (d > 0 ? d : 1.0) : 0.0;
    if (kBookMelanin) lostInMelanin[i] += roulette * (before * fraction) * share;
    lost[i] += roulette * (before * fraction);
    transmitted[i] = before - before * fraction;
  }
}

/// One stay booked in its form (kTerms series terms, or 0: the exponential) with the stay's
/// melanin flags (melanosomes crossed, their share booked).
template <int kTerms>
__attribute__((always_inline)) inline void bookStay(const StayBooking& b, bool melanin,
                                                    bool bookMelanin) {
  if constexpr (kTerms > 0) {
    if (!melanin)
      bookSeriesStay<kTerms, false, false>(b);
    else if (bookMelanin)
      bookSeriesStay<kTerms, true, true>(b);
    else
      bookSeriesStay<kTerms, true, false>(b);
  } else {
    if (!melanin)
      bookDeepStay<false, false>(b);
    else if (bookMelanin)
      bookDeepStay<true, true>(b);
    else
      bookDeepStay<true, false>(b);
  }
}
}  // namespace

HYLIOS_VECTOR_CLONES
void stayLosses(std::size_t n, const SpectralPath::Stay* stays, std::size_t stayCount,
                const SlabAbsorption* slabs, const MelaninAbsorption& melanin, const double* ratio,
                double* __restrict transmitted, double* __restrict absorbed,
                double* __restrict inMelanin, float* work) {
  const bool bookMelanin = inMelanin != nullptr;
  for (std::size_t i = 0; i < n; ++i) transmitted[i] = 1.0;
  for (std::size_t j = 0; j < kLayerCount * n; ++j) absorbed[j] = 0.0;
  if (bookMelanin)
    for (std::size_t j = 0; j < kLayerCount * n; ++j) inMelanin[j] = 0.0;
  for (std::size_t k = 0; k < stayCount; ++k) {  // in the order the path made them
    const SpectralPath::Stay& stay = stays[k];
    const SlabAbsorption& slab = slabs[stay.slab];
    const StayBooking booking{n,
                              slab,
                              melanin,
                              stay.cm,
                              stay.melaninCm,
                              stay.roulette,
                              transmitted,
                              absorbed + slab.layer * n,
                              bookMelanin ? inMelanin + slab.layer * n : nullptr,
                              work,
                              work + n};
    // The cheapest form of the absorbed fraction, chosen by a bound on every λ's depth.
    const double largest =
        slab.largestMuA_perCm * stay.cm + melanin.largestMuA_perCm * stay.melaninCm;
    const bool crossedMelanin = stay.melaninCm > 0;
    const bool single = slab.largestMuA_perCm <= kLargestSingleMuA_perCm &&
                        melanin.largestMuA_perCm <= kLargestSingleMuA_perCm;
    if (!single || largest > 0.5)
      bookStay<0>(booking, crossedMelanin, bookMelanin);
    else if (largest <= 1.0 / 64)
      bookStay<4>(booking, crossedMelanin, bookMelanin);
    else if (largest <= 1.0 / 8)
      bookStay<6>(booking, crossedMelanin, bookMelanin);
    else
      bookStay<9>(booking, crossedMelanin, bookMelanin);
  }
  // The MIS ratio is the same for every stay of the path: it multiplies the layers' sums once.
  for (std::size_t layer = 0; layer < kLayerCount; ++layer) {
    double* __restrict lost = absorbed + layer * n;
    for (std::size_t i = 0; i < n; ++i) lost[i] *= ratio[i];
    if (!bookMelanin) continue;
    double* __restrict lostInMelanin = inMelanin + layer * n;
    for (std::size_t i = 0; i < n; ++i) lostInMelanin[i] *= ratio[i];
  }
}

HYLIOS_VECTOR_CLONES
void pathDepths(std::size_t n, std::size_t slabCount, const SlabAbsorption* slabs,
                const double* pathCm, const double* melaninCm, const double* melaninMuA_perCm,
                double* __restrict depth) {
  for (std::size_t i = 0; i < n; ++i) depth[i] = 0.0;
  for (std::size_t k = 0; k < slabCount; ++k) {
    const double* __restrict muA = slabs[k].muA_perCm;
    const double cm = pathCm[k], inMelanin = melaninCm[k];
    for (std::size_t i = 0; i < n; ++i) depth[i] += muA[i] * cm + melaninMuA_perCm[i] * inMelanin;
  }
}

HYLIOS_VECTOR_CLONES
void exponentials(std::size_t n, const double* x, double scale, double offset,
                  double* __restrict out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = vectorExp(scale * x[i] + offset);
}

HYLIOS_VECTOR_CLONES
void exponentialsOfSum(std::size_t n, const double* x, const double* y, double offset,
                       double* __restrict out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = vectorExp(x[i] + y[i] + offset);
}

HYLIOS_VECTOR_CLONES
void reflectances(std::size_t n, double cosI, const double* index, bool fromInside,
                  double* __restrict out) {
  const double inside = fromInside ? 1.0 : 0.0, outside = 1.0 - inside;
  for (std::size_t i = 0; i < n; ++i) out[i] = surfaceReflectance(cosI, index[i], inside, outside);
}

HYLIOS_VECTOR_CLONES
void addLogReflectances(std::size_t n, double cosI, const double* index, bool fromInside,
                        double* __restrict logDensity) {
  const double inside = fromInside ? 1.0 : 0.0, outside = 1.0 - inside;
  for (std::size_t i = 0; i < n; ++i)
    logDensity[i] += vectorLog(surfaceReflectance(cosI, index[i], inside, outside));
}

HYLIOS_VECTOR_CLONES
void addRefractionDensities(std::size_t n, const Vec3& d, const Vec3& t, const Vec3& macro,
                            const double* index, const double* inverseIndex, bool fromInside,
                            double aspectSquared, bool forced, double* __restrict logDensity,
                            double* __restrict proposalOffset) {
  const bool oneLog = aspectSquared >= 1.0 / kOneLogAspectSquaredBound &&
                      aspectSquared <= kOneLogAspectSquaredBound;
  if (forced && oneLog)
    refractionDensities<true, true>(n, d, t, macro, index, inverseIndex, fromInside, aspectSquared,
                                    logDensity, proposalOffset);
  else if (forced)
    refractionDensities<true, false>(n, d, t, macro, index, inverseIndex, fromInside, aspectSquared,
                                     logDensity, proposalOffset);
  else if (oneLog)
    refractionDensities<false, true>(n, d, t, macro, index, inverseIndex, fromInside, aspectSquared,
                                     logDensity, proposalOffset);
  else
    refractionDensities<false, false>(n, d, t, macro, index, inverseIndex, fromInside,
                                      aspectSquared, logDensity, proposalOffset);
}

}  // namespace hylios::skin::spectral_weights
