// Layered-slab problems shared by the slab tests (tests/skin/layered_slab_test.cpp and
// tests/skin/layered_slab_lanes_test.cpp).
#pragma once

#include <limits>

#include "skin/layered_slab.h"

namespace hylios::test {

inline constexpr double kSemiInfinite = std::numeric_limits<double>::infinity();

/// One layer between two ambient media, lit by a beam at angleDeg.
inline skin::SlabProblem singleLayer(double nAbove, skin::SlabLayer layer, double nBelow,
                                     double angleDeg = 0) {
  skin::SlabProblem p;
  p.refractiveIndexAbove = nAbove;
  p.refractiveIndexBelow = nBelow;
  p.layers = {layer};
  p.incidenceAngleDeg = angleDeg;
  return p;
}

/// MCML manual Table 6.7 / the MCML sample input: three layers of n = 1.37 in air.
inline skin::SlabProblem mcmlThreeLayerSample() {
  skin::SlabProblem p;
  p.layers = {{1.37, 1, 100, 0.9, 0.1}, {1.37, 1, 10, 0.0, 0.1}, {1.37, 2, 10, 0.7, 0.2}};
  return p;
}

/// Layers of different index (total internal reflection inside), a lossless gap, an empty layer,
/// backward scattering, a semi-infinite last layer and an oblique beam at 75°.
inline skin::SlabProblem mismatchedSlab() {
  skin::SlabProblem p;
  p.refractiveIndexAbove = 1.0;
  p.refractiveIndexBelow = 1.33;
  p.layers = {{1.55, 0.5, 50, 0.8, 0.01},
              {1.0, 0, 0, 0, 0.02},
              {1.4, 2, 20, -0.3, 0.05},
              {1.37, 0.1, 10, 0.95, 0.0},
              {1.45, 1, 30, 0.5, kSemiInfinite}};
  p.incidenceAngleDeg = 75;
  return p;
}

}  // namespace hylios::test
