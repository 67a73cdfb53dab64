// One photon meeting a smooth interface: a Fresnel test with one uniform number decides reflection
// or transmission (paper Sec. 4: Fresnel and total internal reflection at every layer boundary).
// Shared by the generic layered slab and the HyLIoS skin walk.
#pragma once
#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/fresnel_pair.h"

namespace hylios::skin {

/// The direction after the interface and whether the photon went through it.
struct InterfaceCrossing {
  Vec3 direction;
  bool transmitted = false;
};

/// A photon travelling along unit `direction` meets a plane interface of normal +z or -z (so the
/// result depends only on direction.z, which must be nonzero), going from index nIncident into
/// nTransmitted. With probability R (Fresnel) it is mirrored (z component negated), otherwise
/// refracted (x, y scaled by n1/n2; z keeps its sign). Matched indices pass straight through and
/// total internal reflection reflects, both without drawing a random number; otherwise exactly
/// one rng.uniform() is drawn.
InterfaceCrossing crossPlaneInterfaceZ(const Vec3& direction, double nIncident, double nTransmitted,
                                       Rng& rng);

/// The same through a precomputed index pair (skin/fresnel_pair.h: one division instead of three;
/// the same law to rounding), for walks that cross fixed interfaces many times.
InterfaceCrossing crossPlaneInterfaceZ(const Vec3& direction, const FresnelPair& indices, Rng& rng);

/// The same for a plane of any unit normal (either orientation), e.g. a microfacet normal.
InterfaceCrossing crossInterface(const Vec3& direction, const Vec3& normal, double nIncident,
                                 double nTransmitted, Rng& rng);

}  // namespace hylios::skin
