// The scene's lights at the film's wavelengths: point, spot, area (an emitting shape) and one
// environment (uniform radiance from every direction). Emission spectra come from EmissionDesc
// (renderer/scene/emission_spectrum.h) and are tabulated once per film channel.
//
// | light       | emits                                                                         |
// |-------------|-------------------------------------------------------------------------------|
// | point       | intensity I(λ) (relative W·sr⁻¹·nm⁻¹) equally in all directions               |
// | spot        | I(λ) inside inner_angle, 0 outside outer_angle, smoothstep in cosθ between     |
// | area        | radiance L(λ) from the front side of its shape only (the geometric normal:     |
// |             | winding for meshes and planes, outward for spheres)                            |
// | environment | radiance L(λ) arriving from every direction (at infinity)                     |
//
// Next-event estimation picks one light with a probability by its estimated share of the light
// that reaches the scene (renderer/tracing/light_selection.h), then a point on it:
// area lights uniformly in area (pdf converted to solid angle, d²/|cosθ_light|), the environment
// uniformly over the sphere of directions (1/4π sr⁻¹). Point and spot lights are delta lights:
// only next-event estimation reaches them.
#pragma once
#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"
#include "renderer/tracing/embree_scene.h"

namespace hylios {

/// A light sample as seen from a shading point.
struct LightSample {
  glm::dvec3 direction;  ///< unit, from the shading point towards the light
  double distance = 0;   ///< to the sampled point; infinite for the environment
  /// Area/environment: radiance arriving along -direction. Delta lights: irradiance on a surface
  /// facing the light, I/d² (so contribution = lobe density × value / pdf in both cases).
  double value = 0;
  double pdf = 0;  ///< selection × solid-angle density (delta lights: selection only)
  bool isDelta = false;
  /// Area lights: the emitting shape, and whether it is convex or flat (a sphere or a plane), so
  /// that nothing of it can hide the sampled point (a mesh may shadow itself).
  int shape = -1;
  bool convexShape = false;
  std::size_t light = 0;  ///< which light was sampled
  double geometry = 1;    ///< the channel-free factor of value: falloff/d² (delta lights), else 1
};

class LightSet {
 public:
  LightSet(const SceneDesc& scene, const EmbreeScene& geometry,
           const std::vector<double>& channelWavelengths);
  /// Whether nothing blocks the light sample as seen from `origin` (an offset shading point).
  /// Area lights: the first surface along the ray must be the light's own shape, at the sampled
  /// point (meshes) or anywhere (convex/flat shapes: a float ray grazing a sphere's silhouette
  /// may meet it slightly early, which must not count as a shadow).
  bool visible(const glm::dvec3& origin, const LightSample& sample, double offset) const;

  std::size_t count() const { return lights_.size(); }
  /// The probability with which sampleGeometry() picks light `light` (light_selection.h).
  double selectionProbability(std::size_t light) const { return selection_.at(light); }
  /// A log line with every light's probability (its kind, and an area light's shape name from
  /// `scene`, the scene this set was built from); empty for fewer than two lights.
  std::string selectionReport(const SceneDesc& scene) const;

  /// One light sample for a shading point, without a channel (the light's choice and point do not
  /// depend on it): value = geometry; emission(sample, c) gives the value at channel c. nullopt
  /// when the chosen light sends nothing there.
  std::optional<LightSample> sampleGeometry(const glm::dvec3& point, double uSelect, double u0,
                                            double u1, double u2) const;
  /// value of `sample` at channel `channel`.
  double emission(const LightSample& sample, std::size_t channel) const;

  bool hasEnvironment() const { return environment_ >= 0; }
  /// Whether camera rays that miss every shape see the environment (LightDesc::cameraVisible).
  bool environmentCameraVisible() const { return environmentCameraVisible_; }
  double environmentRadiance(std::size_t channel) const;
  /// Selection × solid-angle density with which sampleGeometry() yields a given environment
  /// direction.
  double environmentPdf() const;

  /// Whether a shape emits, and its radiance towards `towardViewer` (unit, from the surface to the
  /// viewer) at a hit: 0 from the back side.
  bool isEmitter(std::size_t shape) const {
    return shape < lightOfShape_.size() && lightOfShape_[shape] >= 0;
  }
  double emittedRadiance(const SurfaceHit& hit, const glm::dvec3& towardViewer,
                         std::size_t channel) const;
  /// Selection × solid-angle density with which sampleGeometry() from `from` yields the point `hit`
  /// on an emitting shape.
  double emitterPdf(const glm::dvec3& from, const SurfaceHit& hit) const;

 private:
  struct Light {
    LightDesc::Kind kind;
    glm::dvec3 position{0};
    glm::dvec3 axis{0, 0, -1};
    double cosInner = 1, cosOuter = 1;
    std::size_t shape = 0;
    std::vector<double> emission;  ///< per channel
  };
  double spotFalloff(const Light& light, const glm::dvec3& towardPoint) const;
  void chooseSelectionProbabilities();  ///< fills selection_ and selectionCdf_

  const EmbreeScene& geometry_;
  std::vector<Light> lights_;
  std::vector<double> selection_, selectionCdf_;  ///< per light: p_i, and its running sum
  std::vector<int> lightOfShape_;
  std::vector<bool> convexShape_;
  int environment_ = -1;
  bool environmentCameraVisible_ = true;
};

}  // namespace hylios
