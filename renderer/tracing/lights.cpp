#include "renderer/tracing/lights.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

#include "renderer/scene/emission_spectrum.h"
#include "renderer/tracing/light_selection.h"
#include "skin/core/constants.h"

namespace hylios {

LightSet::LightSet(const SceneDesc& scene, const EmbreeScene& geometry,
                   const std::vector<double>& channelWavelengths)
    : geometry_(geometry),
      lightOfShape_(scene.shapes.size(), -1),
      convexShape_(scene.shapes.size(), false) {
  for (const LightDesc& desc : scene.lights) {
    Light light;
    light.kind = desc.kind;
    for (double wavelength : channelWavelengths) {
      const double value = evaluateEmission(desc.emission, wavelength);
      if (!(value >= 0) || !std::isfinite(value))
        throw SceneError(desc.emission.where, "emission must be finite and >= 0 at " +
                                                  std::to_string(wavelength) + " nm");
      light.emission.push_back(value);
    }
    switch (desc.kind) {
      case LightDesc::Kind::Point:
        light.position = desc.position;
        break;
      case LightDesc::Kind::Spot:
        light.position = desc.position;
        if (!(glm::length(desc.direction) > 0))
          throw SceneError(desc.where, "spot light direction is zero");
        light.axis = glm::normalize(desc.direction);
        light.cosOuter = std::cos(desc.spotOuterDeg * kPi / 180);
        light.cosInner = std::cos(std::min(desc.spotInnerDeg, desc.spotOuterDeg) * kPi / 180);
        break;
      case LightDesc::Kind::Area: {
        std::size_t shape = scene.shapes.size();
        for (std::size_t i = 0; i < scene.shapes.size(); ++i)
          if (scene.shapes[i].name == desc.shape) shape = i;
        if (shape == scene.shapes.size())
          throw SceneError(desc.where, "unknown shape '" + desc.shape + "'");
        if (lightOfShape_[shape] >= 0)
          throw SceneError(desc.where, "shape '" + desc.shape + "' already emits");
        light.shape = shape;
        convexShape_[shape] = scene.shapes[shape].kind != ShapeDesc::Kind::Mesh;
        lightOfShape_[shape] = static_cast<int>(lights_.size());
        break;
      }
      case LightDesc::Kind::Environment:
        if (environment_ >= 0)
          throw SceneError(desc.where, "only one environment light is allowed");
        environment_ = static_cast<int>(lights_.size());
        environmentCameraVisible_ = desc.cameraVisible;
        break;
    }
    lights_.push_back(std::move(light));
  }
  chooseSelectionProbabilities();
}

void LightSet::chooseSelectionProbabilities() {
  std::vector<std::size_t> receivers;
  for (std::size_t shape = 0; shape < lightOfShape_.size(); ++shape)
    if (lightOfShape_[shape] < 0) receivers.push_back(shape);
  const std::vector<glm::dvec3> points = receiverPoints(geometry_, receivers);
  std::vector<double> contribution(lights_.size(), 0.0);
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = lights_[i];
    double irradiance = 0;  // the factor of light_selection.h's table, summed over the points
    for (std::size_t j = 0; j < points.size(); ++j) {
      const glm::dvec3 toPoint = points[j] - light.position;
      const double d2 = glm::dot(toPoint, toPoint);
      switch (light.kind) {
        case LightDesc::Kind::Point:
        case LightDesc::Kind::Spot:
          if (d2 > 0) irradiance += spotFalloff(light, toPoint / std::sqrt(d2)) / d2;
          break;
        case LightDesc::Kind::Area:
          irradiance += areaLightSolidAngle(geometry_, light.shape, points[j], j);
          break;
        case LightDesc::Kind::Environment:
          irradiance += kPi;
          break;
      }
    }
    const double meanEmission =
        light.emission.empty()
            ? 0.0
            : std::accumulate(light.emission.begin(), light.emission.end(), 0.0) /
                  static_cast<double>(light.emission.size());
    contribution[i] = meanEmission * irradiance;
  }
  selection_ = lightSelectionProbabilities(contribution);
  selectionCdf_.resize(selection_.size());
  std::partial_sum(selection_.begin(), selection_.end(), selectionCdf_.begin());
}

std::string LightSet::selectionReport(const SceneDesc& scene) const {
  if (lights_.size() < 2) return "";
  std::ostringstream out;
  out << "  next-event light choice:";
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    switch (lights_[i].kind) {
      case LightDesc::Kind::Point:
        out << " point";
        break;
      case LightDesc::Kind::Spot:
        out << " spot";
        break;
      case LightDesc::Kind::Area:
        out << " area '" << scene.shapes[lights_[i].shape].name << "'";
        break;
      case LightDesc::Kind::Environment:
        out << " environment";
        break;
    }
    out << " " << std::setprecision(3) << selection_[i] << (i + 1 < lights_.size() ? "," : "\n");
  }
  return out.str();
}

double LightSet::spotFalloff(const Light& light, const glm::dvec3& towardPoint) const {
  if (light.kind != LightDesc::Kind::Spot) return 1;
  const double c = glm::dot(light.axis, towardPoint);
  if (c >= light.cosInner) return 1;
  if (c <= light.cosOuter) return 0;
  const double t = (c - light.cosOuter) / (light.cosInner - light.cosOuter);
  return t * t * (3 - 2 * t);
}

double LightSet::emission(const LightSample& sample, std::size_t channel) const {
  return lights_[sample.light].emission[channel] * sample.geometry;
}

std::optional<LightSample> LightSet::sampleGeometry(const glm::dvec3& point, double uSelect,
                                                    double u0, double u1, double u2) const {
  if (lights_.empty()) return std::nullopt;
  const std::size_t index = std::min<std::size_t>(
      static_cast<std::size_t>(
          std::upper_bound(selectionCdf_.begin(), selectionCdf_.end(), uSelect) -
          selectionCdf_.begin()),
      lights_.size() - 1);
  const Light& light = lights_[index];
  const double select = selection_[index];
  LightSample s;
  s.light = index;
  switch (light.kind) {
    case LightDesc::Kind::Point:
    case LightDesc::Kind::Spot: {
      const glm::dvec3 toLight = light.position - point;
      const double d2 = glm::dot(toLight, toLight);
      if (!(d2 > 0)) return std::nullopt;
      s.distance = std::sqrt(d2);
      s.direction = toLight / s.distance;
      s.geometry = spotFalloff(light, -s.direction) / d2;
      s.pdf = select;
      s.isDelta = true;
      break;
    }
    case LightDesc::Kind::Area: {
      const AreaSample a = geometry_.sampleArea(light.shape, u0, u1, u2);
      const glm::dvec3 toLight = a.position - point;
      const double d2 = glm::dot(toLight, toLight);
      if (!(d2 > 0)) return std::nullopt;
      s.distance = std::sqrt(d2);
      s.direction = toLight / s.distance;
      const double cosLight = -glm::dot(a.normal, s.direction);
      if (!(cosLight > 0)) return std::nullopt;  // the back side does not emit
      s.pdf = select * a.pdfArea * d2 / cosLight;
      s.shape = static_cast<int>(light.shape);
      s.convexShape = convexShape_[light.shape];
      break;
    }
    case LightDesc::Kind::Environment: {
      const double z = 1 - 2 * u0, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u1;
      s.direction = {r * std::cos(phi), r * std::sin(phi), z};
      s.distance = std::numeric_limits<double>::infinity();
      s.pdf = select / (4 * kPi);
      break;
    }
  }
  if (!(s.geometry > 0)) return std::nullopt;
  s.value = s.geometry;
  return s;
}

bool LightSet::visible(const glm::dvec3& origin, const LightSample& sample, double offset) const {
  if (sample.shape < 0) {
    const double tMax = std::isfinite(sample.distance) ? sample.distance * (1 - 1e-7) - 2 * offset
                                                       : sample.distance;
    return !geometry_.occluded({origin, sample.direction, tMax});
  }
  const double slack = 1e-3 * sample.distance + 2 * offset;
  const std::optional<SurfaceHit> hit =
      geometry_.intersect({origin, sample.direction, sample.distance + slack});
  if (!hit || hit->shape != static_cast<std::size_t>(sample.shape)) return false;
  return sample.convexShape || hit->t >= sample.distance - slack;
}

double LightSet::environmentRadiance(std::size_t channel) const {
  return environment_ >= 0 ? lights_[static_cast<std::size_t>(environment_)].emission[channel]
                           : 0.0;
}

double LightSet::environmentPdf() const {
  return environment_ >= 0 ? selection_[static_cast<std::size_t>(environment_)] / (4 * kPi) : 0.0;
}

double LightSet::emittedRadiance(const SurfaceHit& hit, const glm::dvec3& towardViewer,
                                 std::size_t channel) const {
  if (!isEmitter(hit.shape) || !(glm::dot(hit.geometricNormal, towardViewer) > 0)) return 0;
  return lights_[static_cast<std::size_t>(lightOfShape_[hit.shape])].emission[channel];
}

double LightSet::emitterPdf(const glm::dvec3& from, const SurfaceHit& hit) const {
  if (!isEmitter(hit.shape)) return 0;
  const glm::dvec3 toLight = hit.position - from;
  const double d2 = glm::dot(toLight, toLight);
  const double cosLight = -glm::dot(hit.geometricNormal, toLight) / std::sqrt(d2);
  if (!(cosLight > 0)) return 0;
  const double select = selection_[static_cast<std::size_t>(lightOfShape_[hit.shape])];
  return select * d2 / (cosLight * geometry_.shapeArea(hit.shape));
}

}  // namespace hylios
