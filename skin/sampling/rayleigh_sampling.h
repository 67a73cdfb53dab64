// Rayleigh phase function sampling for the connective fibres of the papillary dermis
// (paper Sec. 4.2.1, Algorithm 1).
//
// Algorithm 1 draws the polar angle θ_R with density p(θ) = (3/8)(1 + cos²θ) sinθ on [0, π] by
// rejection. We sample the same density exactly: over μ = cosθ the density is (3/8)(1 + μ²) on
// [−1, 1], whose CDF (μ³ + 3μ + 4)/8 is a cubic with one real root, inverted in closed form
// (Cardano, rewritten so that no step cancels). The azimuth is uniform and left to the caller.
#pragma once

namespace hylios::skin {

/// μ = cosθ_R for a uniform u in [0, 1); monotone in u, −1 at u = 0.
double sampleRayleighCos(double u);

/// θ_R in [0, π] for a uniform u in [0, 1): the density of Algorithm 1, sampled by inversion.
double sampleRayleighPolar(double u);

/// Density of μ = cosθ on [−1, 1]: (3/8)(1 + μ²); 0 outside.
double rayleighCosDensity(double mu);

/// Density of θ on [0, π]: (3/8)(1 + cos²θ) sinθ; 0 outside.
double rayleighPolarDensity(double thetaRad);

}  // namespace hylios::skin
