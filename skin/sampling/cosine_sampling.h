// Cosine-weighted (diffuse) perturbation: the polar density 2 cosθ sinθ on [0, π/2) used for the
// internal bounces in a melanosome (Sec. 4.2.2) and for the reflection at the dermis/hypodermis
// boundary (Sec. 4.3). Inversion: F(θ) = sin²θ, so sinθ = √u and cosθ = √(1 − u); θ = 0 at u = 0
// and θ < π/2 for every u < 1.
#pragma once
#include "skin/core/vector3.h"

namespace hylios::skin {

/// θ in [0, π/2) with density 2 cosθ sinθ, for uniform u in [0, 1).
double sampleCosinePolar(double u);

/// Density of θ: 2 cosθ sinθ on [0, π/2); 0 outside.
double cosinePolarDensity(double thetaRad);

/// A unit direction about +z with density cosθ/π per steradian (z > 0): u1 sets sin²θ, u2 the
/// azimuth 2πu2. Turn it into a direction about a normal n with Frame(n).toWorld(...).
Vec3 sampleCosineHemisphere(double u1, double u2);

}  // namespace hylios::skin
