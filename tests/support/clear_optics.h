// Test optics: every layer clear (nothing absorbing or scattering), with one refractive index.
#pragma once
#include "skin/skin_optics.h"

namespace hylios::test {

/// Every layer clear with index n, each `thicknessCm` thick (500 nm, s = 0.1, melanin index 1.7).
inline skin::SkinOptics clearOptics(double n, double thicknessCm = 0.01) {
  skin::SkinOptics optics;
  optics.wavelengthNm = 500;
  optics.surfaceAspectRatio = 0.1;
  optics.melaninRefractiveIndex = 1.7;
  for (auto& layer : optics.layers) {
    layer.thicknessCm = thicknessCm;
    layer.refractiveIndex = n;
  }
  return optics;
}

}  // namespace hylios::test
