// Forward scattering by melanosomes and melanosome complexes: paper Sec. 4.2.2, Algorithm 2.
//
// Algorithm 2 draws θ_m in [0, π] with density p(θ) ∝ exp(−θ/θo) sinθ (θo the "mean angle",
// 5° in the visible, falling to 0 across the near IR) by rejection from a uniform proposal; its
// acceptance rate is about 2θo/π, so it starves as θo -> 0. We sample the same density exactly by
// inverting its closed-form CDF, for every θo > 0, with a cost independent of θo:
//
//   ∫_0^θ e^{−x/θo} sin x dx = θo²/(1 + θo²) · [1 − e^{−θ/θo}(sinθ/θo + cosθ)],
//   F(θ) = [1 − e^{−θ/θo}(sinθ/θo + cosθ)] / (1 + e^{−π/θo}).
//
// The numerator is rewritten as a sum of non-negative terms,
//   1 − e^{−x}(1 + x) + e^{−x}[(θ − sinθ)/θo + 2 sin²(θ/2)],  x = θ/θo,
// each evaluated without cancellation (series for small arguments), and F(θ) = u is solved in the
// scaled variable x by bracketed Newton (skin/sampling/bracketed_newton.h); for u > 1/2 the
// complement 1 − F is solved instead, so both tails keep their relative accuracy. As θo -> 0 the
// law of θ/θo tends to a Gamma(2) law (mean 2θo). θo = 0 means no deflection: θ = 0 exactly.
#pragma once

namespace hylios::skin {

/// The largest θo accepted (radians); the density is already ∝ sinθ to 1e-6 there.
inline constexpr double kMaxExponentialMeanAngleRad = 1e6;
/// The smallest positive θo accepted (radians); below it θo/θ would leave the double range.
inline constexpr double kMinExponentialMeanAngleRad = 1e-300;

/// θ_m in [0, π] for uniform u in [0, 1). meanAngleRad = θo in {0} ∪ [1e-300, 1e6]; 0 returns 0.
/// Throws std::invalid_argument for θo outside that set or u outside [0, 1).
double sampleExponentialPolar(double meanAngleRad, double u);

/// Normalised density of θ on [0, π] (0 outside), θo in [1e-300, 1e6] (θo = 0 is a point mass
/// and throws).
double exponentialPolarDensity(double meanAngleRad, double thetaRad);

/// The closed-form CDF F(θ) above (0 below 0, 1 above π), θo as for the density.
double exponentialPolarCdf(double meanAngleRad, double thetaRad);

}  // namespace hylios::skin
