// Henyey–Greenstein phase function (used by the generic slab mode that checks the transport core
// against MCML's published numbers; not part of HyLIoS itself).
//
// Density of μ = cosθ on [−1, 1]: p(μ) = (1 − g²) / (2 (1 + g² − 2gμ)^{3/2}), mean cosine g.
// Inversion of its CDF is usually written μ = (1 + g² − ((1 − g²)/(1 − g + 2gu))²)/(2g), which
// cancels badly as g -> 0 and as |g| -> 1. Factorised, with D = 1 − g + 2gu,
//   1 − μ = 2(1 − g)²(1 − u)(1 + gu)/D²,   1 + μ = 2(1 + g)² u (1 − g + gu)/D²,
// both products of non-negative factors; the smaller one is used. g = 0 gives μ = 2u − 1 exactly.
#pragma once

namespace hylios::skin {

/// μ = cosθ in [−1, 1] for asymmetry g in (−1, 1) and uniform u in [0, 1); −1 at u = 0.
/// Throws std::invalid_argument for |g| >= 1 or NaN (a point mass has no density).
double sampleHenyeyGreensteinCos(double g, double u);

/// Density of μ on [−1, 1] (0 outside), g in (−1, 1).
double henyeyGreensteinDensity(double g, double mu);

}  // namespace hylios::skin
