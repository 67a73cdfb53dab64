// Ray / spheroid geometry for the melanosome interaction (paper Sec. 4.2.2): where a ray enters a
// melanosome ("the hitting point ... among the set of points facing the ray") and where it leaves.
//
// The spheroid has semi-axes (a, a, c) — a = semiMinorAxis, c = semiMajorAxis of ProlateSpheroid —
// centred at the origin, its symmetry axis along the unit vector `axis` (world). Positions are
// relative to the centre, in the spheroid's length unit.
//
// Entry sampling: lines parallel to the ray direction d meet the spheroid where they cross its
// silhouette, the ellipse seen along d (semi-axes a and sqrt(a²cos²α + c²sin²α), α the angle
// between d and the axis). A hit point uniform over that silhouette's area is drawn by mapping the
// spheroid to the unit sphere with the linear map diag(1/a, 1/a, 1/c) in the body frame: parallel
// lines stay parallel, area on any transversal plane scales by a constant, so a point uniform over
// the unit disk normal to the mapped direction maps back to a point uniform over the silhouette.
// The entry point is the first crossing of that line, and the outward normal there is the
// gradient (x/a², y/a², z/c²) normalised. a = c (a sphere) and large c/a need no special case.
#pragma once
#include "skin/core/vector3.h"
#include "skin/spheroid.h"

namespace hylios::skin {

/// A point on the spheroid's surface (relative to its centre) and the outward unit normal there.
struct SpheroidSurfacePoint {
  Vec3 position;
  Vec3 outwardNormal;
};

/// Where a ray inside the spheroid leaves it: path length to the exit (same unit as the axes),
/// the exit point (relative to the centre) and the outward unit normal there.
struct SpheroidExit {
  double distance = 0;
  Vec3 position;
  Vec3 outwardNormal;
};

/// Area of the silhouette seen by a ray travelling along `direction` (unit):
/// π a sqrt(a²cos²α + c²sin²α), cosα = direction·axis.
double spheroidSilhouetteArea(const ProlateSpheroid& spheroid, const Vec3& axis,
                              const Vec3& direction);

/// An entry point uniform over the silhouette seen along `direction` (unit) for uniform u1 (radius²
/// in the unit disk) and u2 (angle 2πu2), both in [0, 1). The normal satisfies normal·direction <
/// 0.
SpheroidSurfacePoint sampleSilhouetteEntry(const ProlateSpheroid& spheroid, const Vec3& axis,
                                           const Vec3& direction, double u1, double u2);

/// Outward unit normal at a point on (or near) the surface.
Vec3 spheroidOutwardNormal(const ProlateSpheroid& spheroid, const Vec3& axis,
                           const Vec3& surfacePoint);

/// Distance along `direction` (unit) from `pointInside` to the surface, with the exit point and
/// its outward normal. A point on the surface (within 1e-6 in the normalised radius) counts as
/// inside: one heading outward gets distance 0. Throws std::invalid_argument for a point farther
/// out or a non-unit direction.
SpheroidExit distanceToSpheroidExit(const ProlateSpheroid& spheroid, const Vec3& axis,
                                    const Vec3& pointInside, const Vec3& direction);

}  // namespace hylios::skin
