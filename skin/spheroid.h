// Prolate spheroid geometry for melanosomes (paper Sec. 4.2.2, Eq. 7–8).
//
// A prolate spheroid has semi-minor axis a and semi-major (symmetry) axis c, with 0 < a <= c.
// All lengths share one unit (the caller's); ratios come out in its inverse.
#pragma once

namespace hylios::skin {

struct ProlateSpheroid {
  double semiMinorAxis = 0;  ///< a of Eq. 7
  double semiMajorAxis = 0;  ///< c of Eq. 7 (along the symmetry axis)
};

/// Throws std::invalid_argument unless 0 < a <= c and both are finite.
void checkProlateSpheroid(const ProlateSpheroid& spheroid);

/// arcsin(b)/b for b in [0, 1]; a Taylor series near b = 0 so that b -> 0 gives 1 exactly.
double arcsinOverArgument(double b);

/// Eccentricity b = sqrt(1 - a²/c²) of Eq. 7, computed as sqrt((c-a)(c+a))/c to keep its
/// accuracy when a is close to c.
double eccentricity(const ProlateSpheroid& spheroid);

/// Surface-to-volume ratio S/V = 3/(2a) · (a/c + arcsin(b)/b)   (Eq. 7); 3/a for a sphere (a = c).
double surfaceToVolumeRatio(const ProlateSpheroid& spheroid);

/// Surface area 2πa²(1 + (c/a)·arcsin(b)/b) and volume (4/3)πa²c.
double surfaceArea(const ProlateSpheroid& spheroid);
double volume(const ProlateSpheroid& spheroid);

/// Area of the cross-section through the centre perpendicular to the major axis: πa².
/// This is what a ray travelling along the major axis sees (χ2 of Eq. 8 in our reading).
double crossSectionNormalToMajorAxis(const ProlateSpheroid& spheroid);
/// Area of the cross-section through the centre containing the major axis: πac.
/// This is what a ray travelling perpendicular to the major axis sees (χ1 of Eq. 8).
double crossSectionContainingMajorAxis(const ProlateSpheroid& spheroid);

/// Exact silhouette area seen by a ray whose direction makes angle alphaRad with the major axis:
/// π·a·sqrt(a²cos²α + c²sin²α). Equals πa² at α = 0 and πac at α = π/2.
double projectedArea(const ProlateSpheroid& spheroid, double alphaRad);

}  // namespace hylios::skin
