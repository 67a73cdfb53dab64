// HyLIoS walks prepared before rendering: one skin::SkinWalk (its SkinOptics) per film channel and
// per level of a quantised melanin multiplier, for one skin material. computeSkinOptics per hit would
// dominate the render; here it runs levels × channels times, in parallel, before the first ray —
// and only for the wavelengths the film needs and the materials the scene has.
//
// Melanin levels: the multiplier range [lo, hi] of the material (melanin map × freckles) is split
// into kMelaninLevels equally spaced levels m_k = lo + k·(hi − lo)/(K − 1) (one level when lo = hi).
// A multiplier m between m_k and m_{k+1} picks level k+1 with probability (m − m_k)/(m_{k+1} − m_k)
// and level k otherwise (stochastic rounding with one uniform number). The expected contribution
// is then the linear interpolation in m of the contributions at the two levels: no banding, and an
// error of O((hi − lo)²/K²) in the curvature of the response only.
//
// The melanin multiplier scales, in every layer, the melanosome volume fraction and the colloidal
// melanin fraction (Table 1's two melanin contents) of the specimen.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "renderer/scene.h"
#include "skin/skin_walk.h"
#include "skin/spectral_database.h"
#include "skin/specimen.h"

namespace hylios {

/// `specimen` with both melanin contents of every layer × multiplier.
skin::Specimen scaleMelanin(const skin::Specimen& specimen, double multiplier);

class SkinWalkCache {
 public:
  static constexpr int kMelaninLevels = 33;

  /// Throws SceneError at `where` when a wavelength is outside the spectral data, or when a
  /// multiplied specimen is not valid (e.g. a melanin fraction above 1).
  SkinWalkCache(const skin::Specimen& specimen, double minMultiplier, double maxMultiplier,
                const std::vector<double>& channelWavelengths, const skin::SpectralDatabase& spectra,
                const FileLocation& where);

  int levels() const { return levels_; }
  double levelMultiplier(int level) const;
  /// The level for multiplier m with stochastic rounding by uniform u in [0, 1).
  int level(double multiplier, double u) const;
  const skin::SkinWalk& walk(std::size_t channel, int level) const;
  const skin::SkinWalk& walk(std::size_t channel, double multiplier, double u) const {
    return walk(channel, level(multiplier, u));
  }

 private:
  double lo_, hi_;
  int levels_;
  std::size_t channels_;
  std::vector<std::optional<skin::SkinWalk>> walks_;  ///< [level * channels + channel]
};

}  // namespace hylios
