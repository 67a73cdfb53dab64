// Runs many HyLIoS walks for one specimen and wavelength, in parallel and deterministically:
// ray i of wavelength λ uses Rng(seed, wavelengthStream(λ), i); rays are grouped in fixed-size
// chunks whose tallies are merged in chunk order, so results are identical at any thread count.
#pragma once
#include <cstdint>

#include "skin/skin_optics.h"
#include "skin/skin_tally.h"
#include "skin/skin_walk.h"

namespace hylios::skin {

struct WalkRunOptions {
  double incidenceDeg = 0;  ///< polar angle of the incident ray from the surface normal, [0, 90)
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  WalkOptions walk;
  TallyOptions tally;
};

/// The random stream of a wavelength: depends on the wavelength's value only, so a wavelength
/// gives the same result alone or within any list.
std::uint64_t wavelengthStream(double wavelengthNm);

/// The incident direction for a polar angle in degrees (travelling into the skin, in the x–z
/// plane).
Vec3 incidentDirection(double incidenceDeg);

/// Traces options.rays rays through the skin of `optics`. Throws std::invalid_argument for an
/// incidence outside [0°, 90°) or zero rays.
SkinTally simulateSkin(const SkinOptics& optics, const WalkRunOptions& options);

}  // namespace hylios::skin
