// A ray meeting a melanosome or a melanosome complex (paper Sec. 4.2.2).
//
// Dispersed melanosomes: one prolate spheroid. Complexes: up to m melanosomes are met in turn
// (m = the whole part of complex diameter / minor axis, MelanosomeOptics; the walk stops at the
// first that absorbs the ray). For each melanosome: an orientation from Eq. 8,
// a hit point uniform over the silhouette facing the ray, a Fresnel test on entry (epidermis →
// melanin), then inside: an absorption test over the chord (Eq. 1 with the melanosome's melanin
// coefficient); at the far wall a Fresnel test (melanin → epidermis, with total internal
// reflection); a reflected ray is perturbed diffusely (cosine lobe about the inward normal) and
// goes on inside. A ray that is not absorbed leaves with its direction turned by Algorithm 2
// (polar angle about the incoming direction, mean angle θo, uniform azimuth).
//
// Speed (docs/interpretations.md): whether a melanosome absorbs does not depend on the ray's
// direction. Eq. 8 draws the axis relative to the ray (angle α, uniform azimuth β), the spheroid
// is symmetric about its axis and under reflection through its equator, and the silhouette point
// and the diffuse bounces are drawn by rotation-equivariant laws; so the whole internal walk is
// traced in the spheroid's body frame (axis = z, unit a = 1) with the ray in the x–z plane at
// angle α to the axis, and β and the sign of cosα need not be drawn. The outgoing direction only
// depends on Algorithm 2. MelanosomeLayer holds a layer's constants for one wavelength.
//
// Tabulated mode (issue 5, MelanosomeAbsorption::Tabulated): the `count` melanosomes of an
// interaction absorb the ray with probability 1 − q^count, q from the layer's path-length table
// (skin/melanosome_path_lengths.h), drawn with one uniform instead of tracing each melanosome.
#pragma once
#include "skin/core/random.h"
#include "skin/core/vector3.h"
#include "skin/fresnel_pair.h"
#include "skin/layer.h"
#include "skin/melanosome_internal_walk.h"
#include "skin/skin_optics.h"

namespace hylios::skin {

struct MelanosomeEvent {
  bool absorbed = false;
  Vec3 direction;               ///< the outgoing direction when not absorbed
  unsigned melanosomesMet = 0;  ///< melanosomes tested for absorption
};

/// How an interaction decides absorption: each melanosome traced (exact, the default) or the
/// tabulated probability of the melanosomes met (skin/melanosome_path_lengths.h).
enum class MelanosomeAbsorption { Traced, Tabulated };

/// The constants of one layer's melanosomes at one wavelength, checked once.
class MelanosomeLayer {
 public:
  MelanosomeLayer() = default;
  /// Throws std::invalid_argument for a layer without a valid spheroid (0 < a <= c) or with a
  /// negative interior coefficient, non-positive indices or an invalid θo.
  MelanosomeLayer(const SkinOptics& optics, Layer layer,
                  MelanosomeAbsorption absorption = MelanosomeAbsorption::Traced);
  /// One melanosome (a ≤ c in any one unit, interior coefficient in the inverse of that unit).
  MelanosomeLayer(double semiMinor, double semiMajor, double interiorMuA, double nLayer,
                  double nMelanin);

  /// One interaction: a dispersed melanosome or a complex, then Algorithm 2 if not absorbed.
  MelanosomeEvent interact(const Vec3& direction, Rng& rng) const;
  /// One melanosome met by a ray: true if the ray is absorbed inside it (always traced).
  bool absorbedInOne(Rng& rng) const;
  /// Tabulated mode: the probability that an interaction's melanosomes absorb, 1 − q^count
  /// (count = m in complexes, 1 when dispersed): the traced mode's law. Throws std::logic_error
  /// in the traced mode.
  double tabulatedAbsorption() const;
  /// Melanosomes an interaction meets unless one absorbs the ray: m in complexes, else 1.
  unsigned melanosomesPerInteraction() const { return count_; }
  bool tabulated() const { return tabulated_; }

 private:
  void tabulate(double nLayer, double nMelanin);
  MelanosomeGeometry geometry_;  // γ = c/a, 1/γ, epidermis → melanin and back
  double muA_perMinorAxis_ = 0;  // interior coefficient × a (chords are in units of a)
  unsigned count_ = 1;           // melanosomes per interaction: m in complexes, 1 dispersed
  double meanAngleRad_ = 0;      // θo of Algorithm 2
  bool tabulated_ = false;
  double absorbedByCount_ = 0;  // tabulated: 1 − q^count
};

/// One melanosome (semi-axes a ≤ c in cm): returns true if the ray is absorbed inside it. The
/// direction (unit) does not change the law (see above).
bool absorbedInMelanosome(const Vec3& direction, double semiMinorCm, double semiMajorCm,
                          double interiorMuA_perCm, double nLayer, double nMelanin, Rng& rng);

}  // namespace hylios::skin
