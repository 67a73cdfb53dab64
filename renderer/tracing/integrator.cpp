#include "renderer/tracing/integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "renderer/scene/data_paths.h"
#include "renderer/scene/emission_spectrum.h"
#include "renderer/tracing/channel_buffer.h"
#include "renderer/tracing/surface_vectors.h"
#include "skin/core/constants.h"
#include "skin/core/vector3.h"
#include "skin/fresnel.h"
#include "skin/sampling/cosine_sampling.h"

namespace hylios {
namespace {

/// A spawned ray starts this far off its surface, times max(1, |x|, |y|, |z|) of the point: far
/// above the single-precision error of a hit there (about 6e-8 of that magnitude).
constexpr double kRelativeRayOffset = 1e-5;

double powerHeuristic(double pdfA, double pdfB) {
  const double a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0 ? a / (a + b) : 0.0;
}

/// A cosine-distributed direction about unit `normal`.
glm::dvec3 sampleCosine(const glm::dvec3& normal, SampleStream& samples) {
  const std::array<double, 2> u = samples.get2D();
  const skin::Frame frame(toSkin(normal));
  return glm::normalize(toGlm(frame.toWorld(skin::sampleCosineHemisphere(u[0], u[1]))));
}

}  // namespace

void RenderStats::add(const RenderStats& o) {
  paths += o.paths;
  skinWalks += o.skinWalks;
  skinAbsorbed += o.skinAbsorbed;
  skinSurfaceExits += o.skinSurfaceExits;
  skinSubsurfaceExits += o.skinSubsurfaceExits;
  skinEventLimited += o.skinEventLimited;
  exitFallbacks += o.exitFallbacks;
  belowSurface += o.belowSurface;
}

Integrator::Integrator(const SceneDesc& scene, const std::vector<double>& channelWavelengths)
    : scene_(scene), wavelengths_(channelWavelengths) {
  if (scene.integrator.maxDepth < 0)
    throw SceneError(scene.integrator.where, "max_depth must be >= 0");
  if (!(scene.unitCm > 0) || !std::isfinite(scene.unitCm))
    throw SceneError({scene.file.string(), 0, 0}, "unit_cm must be > 0");
  camera_ = std::make_unique<Camera>(scene.camera, scene.film.width, scene.film.height);
  geometry_ = std::make_unique<EmbreeScene>(scene);
  // Relative to the spawning point's own magnitude (spawn()): a far or huge shape elsewhere in the
  // scene must not push every ray off the surfaces near the origin (issue 13, row 2).
  rayOffset_ = kRelativeRayOffset;
  lights_ = std::make_unique<LightSet>(scene, *geometry_, channelWavelengths);
  bool anySkin = false;
  for (const auto& m : scene.materials) anySkin = anySkin || m.kind == MaterialDesc::Kind::Skin;
  std::unique_ptr<skin::SpectralDatabase> spectra;
  if (anySkin)
    spectra = std::make_unique<skin::SpectralDatabase>(skin::SpectralDatabase::load(spectraDir()));
  spectral_ = scene.integrator.estimator == skin::Estimator::Spectral;
  std::vector<std::vector<std::size_t>> bundles;  // the film's bands, as channel lists
  if (scene.integrator.estimator == skin::Estimator::Spectral) {  // walks, or tables' builds
    const Film layout(scene.film);
    for (std::size_t b = 0; b < layout.bandCount(); ++b) bundles.push_back(layout.bandChannels(b));
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    materials_.push_back(makeMaterial(scene, i, channelWavelengths, spectra.get(), bundles));
  for (const ShapeDesc& shape : scene.shapes) {
    std::size_t index = scene.materials.size();
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
      if (scene.materials[i].name == shape.material) index = i;
    if (index == scene.materials.size())
      throw SceneError(shape.where, "unknown material '" + shape.material + "'");
    materialOfShape_.push_back(index);
  }
}

Integrator::Material Integrator::makeMaterial(
    const SceneDesc& scene, std::size_t index, const std::vector<double>& channelWavelengths,
    const skin::SpectralDatabase* spectra, const std::vector<std::vector<std::size_t>>& bundles) {
  const MaterialDesc& desc = scene.materials[index];
  Material m;
  m.kind = desc.kind;
  switch (desc.kind) {
    case MaterialDesc::Kind::Diffuse:
      for (double w : channelWavelengths) {
        const double rho = evaluateEmission(desc.reflectance, w);
        if (!(rho >= 0 && rho <= 1))
          throw SceneError(desc.reflectance.where,
                           "diffuse reflectance must lie in [0, 1]; it is " + std::to_string(rho) +
                               " at " + std::to_string(w) + " nm");
        m.reflectance.push_back(rho);
      }
      break;
    case MaterialDesc::Kind::Dielectric:
      if (desc.roughness != 0)
        throw SceneError(desc.where, "only smooth dielectrics (roughness = 0) are implemented");
      if (!(desc.refractiveIndex > 0) || !std::isfinite(desc.refractiveIndex))
        throw SceneError(desc.where, "refractive index must be a positive number");
      m.refractiveIndex = desc.refractiveIndex;
      break;
    case MaterialDesc::Kind::Skin: {
      bool used = false;
      for (const auto& s : scene.shapes) used = used || s.material == desc.name;
      if (!used) break;  // only the skin that the scene shows is prepared
      const skin::Specimen specimen = loadMaterialSpecimen(desc, specimenDir());
      m.skin = std::make_unique<SkinMaterial>(
          desc, specimen, index, scene.unitCm, channelWavelengths, *spectra,
          scene.integrator.skinMode, scene.integrator.effectTolerance, bundles,
          scene.integrator.tableRaysPerBin);
      break;
    }
  }
  return m;
}

Integrator::~Integrator() = default;

std::string Integrator::effectPlanReport() const {
  std::string text;
  for (std::size_t i = 0; i < materials_.size(); ++i)
    if (materials_[i].skin)
      text += "effect plans of skin material '" + scene_.materials[i].name + "':\n" +
              materials_[i].skin->walks().explainEffectPlans();
  return text;
}

std::string Integrator::tableWalksReport() const {
  std::ostringstream text;
  for (std::size_t i = 0; i < materials_.size(); ++i) {
    const SkinTableCache* tables = materials_[i].skin ? materials_[i].skin->tables() : nullptr;
    if (!tables) continue;
    text << "  skin '" << scene_.materials[i].name << "', walks per table bin by melanin level: "
         << tables->describeRaysPerBin(materials_[i].skin->walks()) << "\n";
  }
  return text.str();
}

std::size_t Integrator::skippedDegenerateTriangles(std::string* report) const {
  std::size_t total = 0;
  std::ostringstream text;
  for (std::size_t i = 0; i < geometry_->shapeCount(); ++i) {
    const std::size_t n = geometry_->skippedDegenerate(i);
    total += n;
    if (n > 0)
      text << scene_.shapes[i].where.str() << ": mesh '" << scene_.shapes[i].meshPath.string()
           << "': skipped " << n << " degenerate triangle" << (n == 1 ? "" : "s") << "\n";
  }
  if (report) *report = text.str();
  return total;
}

Ray Integrator::spawn(const glm::dvec3& point, const glm::dvec3& sideNormal,
                      const glm::dvec3& direction, double tMax) const {
  const double scale =
      rayOffset_ * std::max({1.0, std::fabs(point.x), std::fabs(point.y), std::fabs(point.z)});
  return {point + sideNormal * (glm::dot(direction, sideNormal) >= 0 ? scale : -scale), direction,
          tMax};
}

Integrator::LightNumbers Integrator::drawLightNumbers(SampleStream& samples) {
  LightNumbers numbers{};
  numbers.select = samples.get1D();
  numbers.u0 = samples.get1D();
  numbers.u12 = samples.get2D();
  return numbers;
}

template <typename Lobe>
std::optional<Integrator::DirectSample> Integrator::directLight(const glm::dvec3& point,
                                                                const glm::dvec3& geometricNormal,
                                                                SampleStream& samples,
                                                                bool deltaOnly,
                                                                const Lobe& lobe) const {
  return directLight(point, geometricNormal, drawLightNumbers(samples), deltaOnly, lobe);
}

template <typename Lobe>
std::optional<Integrator::DirectSample> Integrator::directLight(const glm::dvec3& point,
                                                                const glm::dvec3& geometricNormal,
                                                                const LightNumbers& numbers,
                                                                bool deltaOnly,
                                                                const Lobe& lobe) const {
  const std::optional<LightSample> light =
      lights_->sampleGeometry(point, numbers.select, numbers.u0, numbers.u12[0], numbers.u12[1]);
  if (!light || (deltaOnly && !light->isDelta)) return std::nullopt;
  if (!(glm::dot(light->direction, geometricNormal) > 0)) return std::nullopt;
  const double f = lobe(light->direction);
  if (!(f > 0)) return std::nullopt;
  const Ray shadow = spawn(point, geometricNormal, light->direction, light->distance);
  if (!lights_->visible(shadow.origin, *light, glm::length(shadow.origin - point)))
    return std::nullopt;
  const double weight = light->isDelta ? 1.0 : powerHeuristic(light->pdf, f);
  return DirectSample{*light, f * weight / light->pdf};
}

void Integrator::addDirect(const std::optional<DirectSample>& direct, const PathSpectrum& spectrum,
                           const double* beta, const double* albedo, double* L) const {
  if (!direct) return;
  for (std::size_t i = 0; i < spectrum.size(); ++i) {
    const double e = lights_->emission(direct->light, spectrum[i]);
    L[i] += beta[i] * (albedo ? albedo[i] : 1.0) * e * direct->factor;
  }
}

Ray Integrator::scatterDielectric(double refractiveIndex, const Ray& ray, const SurfaceHit& hit,
                                  SampleStream& samples, double& beta) const {
  const glm::dvec3 ng = hit.geometricNormal;
  const bool backFace = glm::dot(ray.direction, ng) > 0;
  const double cosIn = std::fabs(glm::dot(ray.direction, ng));
  const double nFrom = backFace ? refractiveIndex : 1.0, nTo = backFace ? 1.0 : refractiveIndex;
  const glm::dvec3 facing = backFace ? -ng : ng;
  const skin::FresnelResult fr = skin::fresnel(cosIn, nFrom, nTo);
  glm::dvec3 direction;
  if (samples.get1D() < fr.reflectance) {
    direction = ray.direction + facing * (2 * cosIn);
  } else {
    direction = toGlm(skin::refractDirection(toSkin(ray.direction), toSkin(facing), nFrom, nTo,
                                             fr.cosTransmitted));
    beta *= (nFrom / nTo) * (nFrom / nTo);
  }
  direction = glm::normalize(direction);
  return spawn(hit.position, facing, direction, std::numeric_limits<double>::infinity());
}

void Integrator::radiance(const Ray& cameraRay, const PathSpectrum& spectrum, skin::Rng& rng,
                          RenderStats& stats, double* L) const {
  SampleStream samples(rng);
  radiance(cameraRay, spectrum, samples, stats, L);
}

void Integrator::radiance(const Ray& cameraRay, const PathSpectrum& spectrum, SampleStream& samples,
                          RenderStats& stats, double* L) const {
  ++stats.paths;
  std::fill(L, L + spectrum.size(), 0.0);
  const ChannelBuffer ones(spectrum.size(), 1.0);
  tracePath(cameraRay, 0, ones.data(), spectrum, samples, stats, L, spectrum.spectral);
}

void Integrator::tracePath(Ray ray, int firstDepth, const double* throughput,
                           const PathSpectrum& spectrum, SampleStream& samples, RenderStats& stats,
                           double* L, bool splitFirstSkinHit, double firstPdf) const {
  const std::size_t n = spectrum.size();
  const int maxDepth = scene_.integrator.maxDepth;
  ChannelBuffer betaStore(throughput, throughput + n), albedoStore(n);
  double* beta = betaStore.data();
  double* albedo = albedoStore.data();
  // Camera, dielectric or skin surface reflection (no density): emitters count fully.
  bool lastSpecular = !(firstPdf > 0);
  double lastPdf = firstPdf;  // density (sr⁻¹) of the continued direction, for MIS at emitters
  glm::dvec3 lastPoint = ray.origin;
  auto anyThroughput = [&] { return std::any_of(beta, beta + n, [](double b) { return b > 0; }); };
  ChannelBuffer control(n);  // the exit's control variate throughput (header), when useControl
  bool useControl = false;
  std::optional<FacingNormals> controlAt;  // set at a skin exit that has one: the entry's normals
  for (int depth = firstDepth;; ++depth) {
    const std::optional<SurfaceHit> hit = geometry_->intersect(ray);
    if (!hit) {
      // A camera ray (depth 0) sees the environment only when it is camera-visible.
      if (lights_->hasEnvironment() && (depth > 0 || lights_->environmentCameraVisible())) {
        const double mis = lastSpecular ? 1.0 : powerHeuristic(lastPdf, lights_->environmentPdf());
        for (std::size_t i = 0; i < n; ++i)
          L[i] += beta[i] * lights_->environmentRadiance(spectrum[i]) * mis;
      }
      break;
    }
    if (lights_->isEmitter(hit->shape)) {
      const double mis =
          lastSpecular ? 1.0 : powerHeuristic(lastPdf, lights_->emitterPdf(lastPoint, *hit));
      for (std::size_t i = 0; i < n; ++i)
        L[i] += beta[i] * lights_->emittedRadiance(*hit, -ray.direction, spectrum[i]) * mis;
    }
    if (depth >= maxDepth) break;
    const Material& material = materials_[materialOfShape_[hit->shape]];
    if (material.kind == MaterialDesc::Kind::Dielectric) {
      double scale = 1;  // the index is the same at every wavelength: the bundle stays together
      ray = scatterDielectric(material.refractiveIndex, ray, *hit, samples, scale);
      for (std::size_t i = 0; i < n; ++i) beta[i] *= scale;
      lastSpecular = true;
      continue;
    }
    // Normals on the side the ray arrives from.
    const FacingNormals facing =
        faceTheRay(ray.direction, hit->geometricNormal, hit->shadingNormal);
    glm::dvec3 ng = facing.geometric, ns = facing.shading;
    glm::dvec3 point = hit->position;
    const double* lobeAlbedo = nullptr;
    if (material.kind == MaterialDesc::Kind::Skin) {
      ++stats.skinWalks;
      // The first skin hit of a camera path splits its entry (the surface reflection scored at
      // once, the walk forced in): one coin fewer where most of the image's skin noise is made.
      const bool split = splitFirstSkinHit && spectrum.spectral;
      splitFirstSkinHit = false;
      ChannelBuffer surface(split ? n : 0), before(beta, beta + (split ? n : 0));
      // There, in table mode, the exit's draw (its table and offset cell) takes the pixel's
      // stratified pair: the channels' weights vary most with which table the exit came from.
      // And the rough surface's first facet takes three numbers of the pixel's: it decides the
      // surface branch's direction, a glossy reflection that finds the lights or not.
      std::array<double, 2> exitSample{};
      const bool stratifyExit = split && material.skin->tables();
      if (stratifyExit) exitSample = samples.get2D();
      skin::FacetNumbers facetNumbers;
      if (split) {
        facetNumbers.polar = samples.get2D();
        facetNumbers.azimuth = samples.get1D();
      }
      if (spectrum.spectral && material.skin->tables() && scene_.integrator.exitControlVariate)
        useControl = true;
      const SkinScatter s =
          scatterSkin(*material.skin, *hit, ray.direction, spectrum, samples.rng(), beta,
                      split ? surface.data() : nullptr, stratifyExit ? &exitSample : nullptr,
                      useControl ? control.data() : nullptr, split ? &facetNumbers : nullptr);
      controlAt = s.entryWeights ? std::optional<FacingNormals>(facing) : std::nullopt;
      if (s.surfaceBranch) {
        for (std::size_t i = 0; i < n; ++i) surface[i] *= before[i];
        SampleStream branch = samples.branch();
        traceSurfaceBranch(*material.skin, *hit, ray.direction, s.surfaceDirection, depth,
                           before.data(), surface.data(), spectrum, branch, stats, L);
      }
      if (s.kind == SkinScatter::Kind::Absorbed) {
        ++stats.skinAbsorbed;
        break;
      }
      if (s.kind == SkinScatter::Kind::EventLimit) {
        ++stats.skinEventLimited;
        break;
      }
      if (s.kind == SkinScatter::Kind::SurfaceReflection) {
        ++stats.skinSurfaceExits;
        const glm::dvec3 incident = ray.direction, normal = s.shadingNormal;
        addDirect(directLight(s.point, s.geometricNormal, samples, true,
                              [&](const glm::dvec3& w) {
                                return material.skin->surfaceLobeDensity(incident, normal, w);
                              }),
                  spectrum, beta, nullptr, L);
        if (!(glm::dot(s.direction, s.geometricNormal) > 0)) {
          ++stats.belowSurface;
          break;
        }
        if (!anyThroughput()) break;
        ray =
            spawn(s.point, s.geometricNormal, s.direction, std::numeric_limits<double>::infinity());
        lastSpecular = true;
        lastPoint = s.point;
        continue;
      }
      ++stats.skinSubsurfaceExits;
      if (s.exitFallback) ++stats.exitFallbacks;
      point = s.point;
      ng = s.geometricNormal;
      ns = s.shadingNormal;
    } else {  // diffuse
      for (std::size_t i = 0; i < n; ++i) albedo[i] = material.reflectance[spectrum[i]];
      lobeAlbedo = albedo;
    }
    // A Lambertian lobe: the diffuse material's, or the skin's exit lobe (albedo 1: the walk
    // already weighted the light that left).
    const auto lobe = [&](const glm::dvec3& w) { return std::max(0.0, glm::dot(w, ns)) / kPi; };
    const LightNumbers numbers = drawLightNumbers(samples);
    addDirect(directLight(point, ng, numbers, false, lobe), spectrum, beta, lobeAlbedo, L);
    if (controlAt) {  // the exit point's control variate (header): the same light at the entry
      const glm::dvec3 entryShading = controlAt->shading;
      const auto entryLobe = [&](const glm::dvec3& w) {
        return std::max(0.0, glm::dot(w, entryShading)) / kPi;
      };
      addDirect(directLight(hit->position, controlAt->geometric, numbers, false, entryLobe),
                spectrum, control.data(), nullptr, L);
      controlAt.reset();
    }
    if (lobeAlbedo)
      for (std::size_t i = 0; i < n; ++i) beta[i] *= lobeAlbedo[i];
    if (!anyThroughput()) break;
    const glm::dvec3 direction = sampleCosine(ns, samples);
    if (!(glm::dot(direction, ng) > 0)) {
      ++stats.belowSurface;
      break;
    }
    lastPdf = glm::dot(direction, ns) / kPi;
    lastSpecular = false;
    lastPoint = point;
    ray = spawn(point, ng, direction, std::numeric_limits<double>::infinity());
  }
}

double Integrator::radiance(const Ray& ray, std::size_t channel, skin::Rng& rng,
                            RenderStats& stats) const {
  const std::size_t channels[1] = {channel};
  double L = 0;
  radiance(ray, PathSpectrum{channels, 1, 0, false}, rng, stats, &L);
  return L;
}

void Integrator::traceSurfaceBranch(const SkinMaterial& skin, const SurfaceHit& hit,
                                    const glm::dvec3& incident, const glm::dvec3& direction,
                                    int depth, const double* arriving, const double* beta,
                                    const PathSpectrum& spectrum, SampleStream& samples,
                                    RenderStats& stats, double* L) const {
  ++stats.skinSurfaceExits;
  const FacingNormals facing = faceTheRay(incident, hit.geometricNormal, hit.shadingNormal);
  // The branch's lobe is F_λ(h)·p(ω), p its own sampling density (SkinMaterial::
  // surfaceBranchDensity): next-event estimation of every light with it, and the continuation
  // below, are combined by the power heuristic.
  const auto density = [&](const glm::dvec3& w) {
    return skin.surfaceBranchDensity(incident, facing.shading, w);
  };
  const std::optional<DirectSample> direct =
      directLight(hit.position, facing.geometric, samples, false, density);
  if (direct) {
    const glm::dvec3 h = glm::normalize(direct->light.direction - incident);
    const double cosFacet = -glm::dot(incident, h);
    thread_local std::vector<double> fresnel;
    fresnel.resize(spectrum.size());
    for (std::size_t i = 0; i < spectrum.size(); ++i)
      fresnel[i] = skin.surfaceFresnel(spectrum[i], cosFacet);
    addDirect(direct, spectrum, arriving, fresnel.data(), L);
  }
  if (!(glm::dot(direction, facing.geometric) > 0)) {
    ++stats.belowSurface;
    return;
  }
  tracePath(
      spawn(hit.position, facing.geometric, direction, std::numeric_limits<double>::infinity()),
      depth + 1, beta, spectrum, samples, stats, L, false, density(direction));
}

SkinScatter Integrator::scatterSkin(const SkinMaterial& skin, const SurfaceHit& hit,
                                    const glm::dvec3& direction, const PathSpectrum& spectrum,
                                    skin::Rng& rng, double* beta, double* surfaceWeights,
                                    const std::array<double, 2>* exitSample, double* controlBeta,
                                    const skin::FacetNumbers* firstFacet) const {
  if (!spectrum.spectral)
    return skin.scatter(hit, direction, spectrum[0], *geometry_, materialOfShape_, rng);
  thread_local std::vector<double> weights, entryWeights;
  weights.resize(spectrum.size());
  entryWeights.resize(spectrum.size());
  SkinScatter s = skin.scatterSpectral(
      hit, direction, spectrum.bundle, *geometry_, materialOfShape_, rng, weights.data(),
      surfaceWeights, exitSample, controlBeta ? entryWeights.data() : nullptr, firstFacet);
  // One channel (or no second stage): w = A, nothing to control.
  if (s.entryWeights)
    s.entryWeights = !std::equal(weights.begin(), weights.end(), entryWeights.begin());
  for (std::size_t i = 0; i < spectrum.size(); ++i) {
    if (s.entryWeights) controlBeta[i] = beta[i] * (entryWeights[i] - weights[i]);
    beta[i] *= weights[i];
  }
  return s;
}

}  // namespace hylios
