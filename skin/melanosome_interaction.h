// A ray meeting a melanosome or a melanosome complex (paper Sec. 4.2.2).
//
// Dispersed melanosomes: one prolate spheroid. Complexes: up to m melanosomes are met in turn
// (m = complex diameter / minor axis; a fractional m is rounded up with probability equal to its
// fractional part, so the mean number met is m). For each melanosome: an orientation from Eq. 8,
// a hit point uniform over the silhouette facing the ray, a Fresnel test on entry (epidermis →
// melanin), then inside: an absorption test over the chord (Eq. 1 with the melanosome's melanin
// coefficient); at the far wall a Fresnel test (melanin → epidermis, with total internal
// reflection); a reflected ray is perturbed diffusely (cosine lobe about the inward normal) and
// goes on inside. A ray that is not absorbed leaves with its direction turned by Algorithm 2
// (polar angle about the incoming direction, mean angle θo, uniform azimuth).
#pragma once
#include "skin/layer.h"
#include "skin/random.h"
#include "skin/skin_optics.h"
#include "skin/vector3.h"

namespace hylios::skin {

struct MelanosomeEvent {
  bool absorbed = false;
  Vec3 direction;               ///< the outgoing direction when not absorbed
  unsigned melanosomesMet = 0;  ///< melanosomes tested for absorption
};

/// Bound on internal wall bounces in one melanosome; past it the ray is let out through the wall
/// (with 1.7/1.4 and cosine-perturbed bounces the chance of reaching it is below 1e-300).
inline constexpr int kMaxMelanosomeBounces = 10000;

MelanosomeEvent interactWithMelanosomes(const Vec3& direction, const SkinOptics& optics, Layer layer,
                                        Rng& rng);

/// One melanosome (semi-axes a ≤ c in cm): returns true if the ray is absorbed inside it.
bool absorbedInMelanosome(const Vec3& direction, double semiMinorCm, double semiMajorCm,
                          double interiorMuA_perCm, double nLayer, double nMelanin, Rng& rng);

}  // namespace hylios::skin
