// Which light next-event estimation picks (LightSet::sampleGeometry): light i with probability
//
//   p_i = (1 − δ)·e_i / Σ_j e_j + δ/N,   δ = kDefensiveLightShare = 0.1, N lights,
//
// e_i the light's estimated contribution to the scene: its mean emission over the film's channels
// times the irradiance factor it gives the receivers (the shapes that do not emit), averaged over
// kReceiverPoints points drawn uniformly in area over them, each taken as facing the light:
//
// | light       | irradiance factor at a receiver point x                                       |
// |-------------|-------------------------------------------------------------------------------|
// | point, spot | falloff(x) / d²                                                               |
// | area        | its solid angle from x, Σ_k max(0, cosθ_k) / (d_k² pdfArea) over kLightPoints |
// |             | points on it, at most π (the projected solid angle of a whole hemisphere)     |
// | environment | π (a whole hemisphere of radiance 1)                                          |
//
// Any p_i > 0 keeps next-event estimation unbiased (the MIS densities use the same p_i:
// LightSet::environmentPdf and emitterPdf); δ keeps a light the estimate misjudges (one that
// shines where the receivers' sample points are not) at p_i ≥ δ/N. Every e_i zero, or no
// receiver: uniform, 1/N. The points come from a fixed stream: the same scene, the same p_i.
// Why: with uniform choice the paper's scenes (a key light of radiance 8 and an environment of
// 0.15) spent half their light samples on a fifth of the light (docs/benchmarks.md, session 16).
#pragma once
#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

#include "renderer/tracing/embree_scene.h"

namespace hylios {

constexpr double kDefensiveLightShare = 0.1;
constexpr int kReceiverPoints = 256;
constexpr int kLightPoints = 8;  ///< per receiver point, for an area light's solid angle

/// p_i from the contributions e_i ≥ 0 (the mixture above); uniform when they sum to 0.
std::vector<double> lightSelectionProbabilities(const std::vector<double>& contribution);

/// kReceiverPoints points uniform in area over `shapes` of `geometry` (a shape chosen with
/// probability ∝ its area), from a fixed stream; empty when `shapes` is empty or has no area.
std::vector<glm::dvec3> receiverPoints(const EmbreeScene& geometry,
                                       const std::vector<std::size_t>& shapes);

/// An area light's solid angle from `receiver`, estimated from kLightPoints points on `shape`
/// (its front side only), at most π.
double areaLightSolidAngle(const EmbreeScene& geometry, std::size_t shape,
                           const glm::dvec3& receiver, std::size_t receiverIndex);

}  // namespace hylios
