// Orientation of a melanosome (prolate spheroid) relative to the ray that hits it: paper Eq. 8.
//
// Eq. 8 gives P_m(α, β) = ( [χ1(1 − |cosα|) + χ2|cosα|] / (χ1 + χ2), 1/(2π) ), α the angle between
// the ray direction and the spheroid's major axis, β the azimuth of the axis about the ray.
// Reading: the first component is the density of μ = cosα over [−1, 1] (it integrates to exactly 1
// there), i.e. over α it is that value times sinα. It weights isotropically oriented spheroids by
// the area they present to the ray — a ray meets a body in proportion to its silhouette — with the
// exact silhouette π·a·sqrt(a²μ² + c²(1 − μ²)) linearised in |μ| between its two extremes:
//   χ1 = π a c  (cross-section containing the major axis; seen when the ray is perpendicular to it,
//                μ = 0), and
//   χ2 = π a²   (cross-section normal to the major axis; seen looking along it, |μ| = 1).
// (The paper names χ1, χ2 after the "minor" and "major" axes; these are the only assignments for
// which Eq. 8 is a projected-area weighting.) β is uniform on [0, 2π).
//
// Sampling is exact: the sign of μ takes one half of u1's range, and |μ| = m inverts the linear
// density χ1 + (χ2 − χ1)m on [0, 1] through the root of a quadratic written without cancellation.
#pragma once
#include "skin/core/vector3.h"
#include "skin/spheroid.h"

namespace hylios::skin {

/// Density of μ = cos α in [−1, 1] (Eq. 8): (c(1 − |μ|) + a|μ|)/(c + a); 0 outside.
double melanosomeAxisCosDensity(const ProlateSpheroid& spheroid, double mu);

/// μ = cos α in [−1, 1] for uniform u in [0, 1) (−1 at u = 0).
double sampleMelanosomeAxisCos(const ProlateSpheroid& spheroid, double u);

/// The major-axis direction (unit) in the ray's frame, where the ray travels along +z:
/// (sinα cosβ, sinα sinβ, cosα), μ = cosα from u1 and β = 2πu2.
Vec3 sampleMelanosomeAxisInRayFrame(const ProlateSpheroid& spheroid, double u1, double u2);

/// The major-axis direction (unit) in the world, for a ray travelling along `rayDirection` (unit).
Vec3 sampleMelanosomeAxis(const ProlateSpheroid& spheroid, const Vec3& rayDirection, double u1,
                          double u2);

}  // namespace hylios::skin
