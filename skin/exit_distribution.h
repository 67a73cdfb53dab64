// Where and in which direction light leaves the skin, as densities: the direction histograms of
// SkinTally turned into fractions of incident rays per steradian (= BRDF·cos θr for reflection,
// paper Fig. 11; BTDF·cos θt for the transmission of Fig. 8), into BRDF values, and into an
// in-plane cut (the plane of incidence); the radial histogram turned into R(r) per unit area
// (the radial part of the BSSRDF). Standard errors come along everywhere.
//
// | quantity                 | definition                                                      |
// |--------------------------|-----------------------------------------------------------------|
// | fraction per sr          | F_bin / Ω_bin, Ω_bin = (cos θ1 − cos θ2)·Δφ                     |
// | BRDF                     | F_bin / Ω⊥_bin, Ω⊥_bin = ½(sin²θ2 − sin²θ1)·Δφ (projected)       |
// |                          | (the cosine-weighted mean of f_r over the bin, exactly)         |
// | R(r)  [cm⁻²]             | F_annulus / π(r2² − r1²)                                        |
//
// F is the fraction of incident rays that left through the bin. Polar angles are measured from
// the outward normal on the side the light leaves (SkinTally::directionBin); azimuth φ = 0 is the
// forward (specular) side of the incident ray, φ = ±180° the side it came from.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skin/core/statistics.h"
#include "skin/skin_tally.h"

namespace hylios::skin {

/// The polar × azimuth bins of SkinTally's direction histograms (TallyOptions).
class DirectionBins {
 public:
  /// Throws std::invalid_argument for zero bins.
  DirectionBins(std::size_t polarBins, std::size_t azimuthBins);
  std::size_t polarBins() const { return polarBins_; }
  std::size_t azimuthBins() const { return azimuthBins_; }
  std::size_t count() const { return polarBins_ * azimuthBins_; }
  /// Index into the flattened histogram (polar-major, as SkinTally::directionBin).
  std::size_t flatIndex(std::size_t polarBin, std::size_t azimuthBin) const;

  double polarLowerRad(std::size_t polarBin) const;
  double polarUpperRad(std::size_t polarBin) const;
  double polarCentreRad(std::size_t polarBin) const;
  double azimuthWidthRad() const;
  double azimuthLowerRad(std::size_t azimuthBin) const;
  double azimuthCentreRad(std::size_t azimuthBin) const;
  /// Ω of one bin of polar ring `polarBin` (all azimuth bins of a ring are equal) [sr].
  double solidAngleSr(std::size_t polarBin) const;
  /// ∫ cos θ dω over one bin of the ring [sr].
  double projectedSolidAngleSr(std::size_t polarBin) const;
  /// The azimuth bins whose centre lies less than one bin width from `azimuthRad` (circularly):
  /// the two bins either side when a bin edge falls on it, the one centred on it otherwise.
  std::vector<std::size_t> azimuthBinsNear(double azimuthRad) const;

 private:
  std::size_t polarBins_, azimuthBins_;
};

/// Σ of estimates of disjoint quantities from the same `packets` packets, where each packet
/// scores in at most one of them (analog 0/1 tallies of where a ray left): the exact mean and
/// standard error of the sum (per-packet second moments are recovered from each estimate).
Estimate sumOfExclusive(const std::vector<Estimate>& parts, std::uint64_t packets);
/// a / b for two disjoint quantities of the same packets (as sumOfExclusive), with the
/// first-order standard error including their covariance −a·b/(packets − 1). Throws
/// std::domain_error when b.mean is 0.
Estimate ratioOfExclusive(const Estimate& a, const Estimate& b, std::uint64_t packets);
/// a / b for independent estimates, with the first-order standard error √(σa² + r²σb²)/|b| (an
/// upper bound for disjoint tallies of the same packets, whose covariance is negative). Throws
/// std::domain_error when b.mean is 0.
Estimate ratioOfIndependent(const Estimate& a, const Estimate& b);
/// The mean of independent estimates (e.g. of separate wavelengths): σ = √(Σσᵢ²)/k.
Estimate meanOfIndependent(const std::vector<Estimate>& estimates);
/// factor · e (mean and error).
Estimate scaled(const Estimate& e, double factor);

/// One value per exit-direction bin (flattened like DirectionBins) for surface, subsurface and
/// total (= surface + subsurface) reflection.
struct ReflectedDirections {
  std::vector<Estimate> surface, subsurface, total;
};

/// The in-plane cut of a directional quantity: signed θr from −90° (back toward the source,
/// φ = 180°) to +90° (specular side, φ = 0°), one point per polar bin and side.
struct InPlaneCut {
  std::vector<double> signedPolarDeg;
  std::vector<Estimate> surface, subsurface, total;
};

/// Everything `hylios brdf` reports for one wavelength or an average of wavelengths.
struct ReflectionDistribution {
  ReflectedDirections perSteradian;  ///< fraction of incident rays per sr = BRDF·cos θr [sr⁻¹]
  ReflectedDirections brdf;          ///< BRDF [sr⁻¹]
  InPlaneCut inPlanePerSteradian;    ///< perSteradian averaged over the in-plane azimuth bins
  Estimate surfaceReflectance, subsurfaceReflectance, totalReflectance;  ///< hemispherical
};

/// Reads a tally kept with direction histograms (TallyOptions::polarBins > 0; throws
/// std::invalid_argument otherwise).
ReflectionDistribution reflectionDistribution(const SkinTally& tally);
/// The per-bin mean over wavelengths (independent runs), e.g. the visible band of paper Fig. 10.
/// Throws std::invalid_argument for an empty list or differing bins.
ReflectionDistribution meanOverWavelengths(
    const std::vector<ReflectionDistribution>& distributions);

/// The transmitted light of a truncated stack (Fig. 8): per polar bin (azimuth bins merged),
/// fraction per sr from the inward normal and the same normalised to the first bin (θ ≈ 0°).
struct TransmissionProfile {
  std::vector<double> polarLowerDeg, polarUpperDeg;
  std::vector<double> solidAngleSr;  ///< of the whole ring
  std::vector<Estimate> perSteradian;
  std::vector<Estimate> relativeToNormal;  ///< perSteradian / perSteradian[0]
  Estimate transmittance;
};
/// Throws std::invalid_argument without direction histograms, std::domain_error when nothing was
/// transmitted into the first polar bin (no normalisation possible).
TransmissionProfile transmissionProfile(const SkinTally& tally);

/// π(r2² − r1²) [cm²] for 0 ≤ r1 ≤ r2.
double annulusAreaCm2(double innerCm, double outerCm);

/// Subsurface exits per unit area around the entry point (radially symmetric part of the BSSRDF).
struct RadialProfile {
  std::vector<double> innerCm, outerCm;
  std::vector<Estimate> perCm2;    ///< fraction of incident rays per cm² of the annulus
  std::vector<Estimate> fraction;  ///< fraction of incident rays in the annulus
  Estimate beyondMaxRadius;        ///< subsurface exits at r ≥ maxRadiusCm (not in any bin)
  Estimate subsurfaceReflectance;  ///< = Σ fraction + beyondMaxRadius
};
/// Throws std::invalid_argument when the tally kept no radial histogram.
RadialProfile radialProfile(const SkinTally& tally);

}  // namespace hylios::skin
