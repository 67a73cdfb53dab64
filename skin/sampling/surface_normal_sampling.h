// Polar angle of the perturbed skin-surface normal (paper Sec. 4.3).
//
// The paper draws θs in [0, π/2) from P_s(θs) ∝ s⁴ sinθs / (s² cos²θs + sin²θs)², a
// Trowbridge–Reitz-type density without the cosθs factor of a projected microfacet density;
// the azimuth is uniform (left to the caller). By the formula, small s concentrates θs near 0
// (nearly specular: tanθs ~ s) and s = 1 gives cosθs uniform.
//
// Normalisation (derived here; μ = cosθs, B = s² − 1, Φ(z) = atan(√z)/√z, atanh(√−z)/√−z for
// z < 0, 1 at z = 0):
//   ∫_0^{π/2} s⁴ sinθ dθ/(s²cos²θ + sin²θ)² = ∫_0^1 s⁴ dμ/(1 + Bμ²)² = (s⁴/2)·[1/s² + Φ(B)].
// CDF, with the same factor s⁴/2 taken out of both parts:
//   C(θ) = (1 − μ)(1 − Bμ)/(s²(s²μ² + sin²θ)) + w·Φ(B w²),  w = (1 − μ)/((1 − μ) + s²μ),
//   tail T(θ) = μ/(s²μ² + sin²θ) + μ·Φ(Bμ²),   F(θ) = C/(1/s² + Φ(B)) = 1 − T/(1/s² + Φ(B)).
// (w·Φ(Bw²) is ∫_μ^1 dν/(1 + Bν²) written via the atan/atanh addition formulas, which removes the
// cancellation.) F has no closed-form inverse (it mixes a rational and an arctangent term), so
// F(θ) = u is solved by bracketed Newton from the GGX-style guess tanθ = s·sqrt(u/(1 − u)). Below
// s = 1e-20 that guess is the exact law to double precision (its relative error is O(tan²θ) <
// 1e-24 for every u < 1) and is returned directly.
#pragma once

namespace hylios::skin {

/// Range of the aspect ratio s accepted by the sampler and density.
inline constexpr double kMinSurfaceAspectRatio = 1e-100;
inline constexpr double kMaxSurfaceAspectRatio = 1e10;

/// θs in [0, π/2) for uniform u in [0, 1) and aspect ratio s in [1e-100, 1e10] (Table 1's
/// "surface fold aspect ratio"). Throws std::invalid_argument otherwise.
double sampleSurfaceNormalPolar(double aspectRatio, double u);

/// Normalised density of θs on [0, π/2) (0 outside).
double surfaceNormalPolarDensity(double aspectRatio, double thetaRad);

/// The CDF F(θs) above (0 below 0, 1 from π/2 on).
double surfaceNormalPolarCdf(double aspectRatio, double thetaRad);

}  // namespace hylios::skin
