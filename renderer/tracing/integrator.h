// The spectral path tracer. Spectral estimator (the default in walk mode): a camera path carries
// every channel of one band (Film::sampleBand, stratified over the pixel's samples) with a
// throughput per channel — hero wavelengths in the manner of pbrt-v4's SampledWavelengths; nothing
// here is dispersive (dielectrics have one index), so a bundle never splits, and skin hits run the
// band's spectral walk (skin_material.h). Per-wavelength estimator (and table mode): one wavelength
// per camera path (a film channel drawn by Film::sampleChannel). Next-event estimation with
// multiple importance sampling (power heuristic, β = 2) for area and environment lights, delta
// point/spot lights by next-event estimation only.
//
// Materials (MaterialDesc):
//   diffuse    — Lambertian, reflectance spectrum ρ(λ) in [0, 1]; cosine-sampled continuation;
//                two-sided.
//   dielectric — smooth interface of index n (air outside): Fresnel reflection or refraction chosen
//                in proportion; refraction scales radiance by (n_i/n_t)² (pbrt's radiance mode).
//   skin       — the HyLIoS walk (renderer/tracing/skin_material.h, where the estimator is
//   documented).
// Exit point control variate (table mode, spectral): a band's exit weights are w_λ = A_λ·r_λ, A_λ
// fixed by the entry and r_λ = π_λ(c)/mean_h π_h(c) the second stage's ratio for the exit cell c
// (skin/exit_table_bundle.h), with E[r_λ | entry] = 1. The exit's next-event estimate N(x_c) is
// scored as A_λ·N(x_0) + w_λ·(N(x_c) − N(x_0)): the subtracted (w_λ − A_λ)·N(x_0) has expectation 0
// because N(x_0), the same light sample taken at the entry point x_0 with the exit lobe about the
// entry's normal, does not depend on c. Where the light varies little between entry and exit,
// r_λ's spread (the band's colour noise) leaves the direct light. One shadow ray more per skin hit.
// max_depth counts scattering vertices (a skin walk is one): max_depth = 1 is direct lighting.
// No Russian roulette: paths end at max_depth, by absorption, or by leaving the scene.
//
// Sample streams (renderer/tracing/pixel_sampler.h, [integrator] sampler): sample s of pixel p
// (p = y·width + x) takes its camera sample and the integrator's decisions from a SampleStream —
// independent: every number from skin::Rng(seed, p, s); sobol: the first dimensions from
// Owen-scrambled Sobol' points of the pixel — and the skin walks from skin::Rng(seed, p, s).
// Determinism: a sample's numbers depend only on (seed, p, s), and the pixels are split into 16×16
// tiles, each written by one task; the image is identical for any thread count
// (tbb::global_control chooses it).
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/image/render_noise.h"
#include "renderer/scene/scene.h"
#include "renderer/tracing/camera.h"
#include "renderer/tracing/embree_scene.h"
#include "renderer/tracing/lights.h"
#include "renderer/tracing/pixel_sampler.h"
#include "renderer/tracing/render_progress.h"
#include "renderer/tracing/skin_material.h"
#include "skin/core/random.h"

namespace hylios {

/// Counters of a render (sums over all paths; order-independent, so deterministic).
struct RenderStats {
  std::uint64_t paths = 0;
  std::uint64_t skinWalks = 0;
  std::uint64_t skinAbsorbed = 0;
  std::uint64_t skinSurfaceExits = 0;
  std::uint64_t skinSubsurfaceExits = 0;
  std::uint64_t skinEventLimited = 0;  ///< walks stopped at SkinWalk::kMaxEvents (path ended)
  std::uint64_t exitFallbacks = 0;     ///< subsurface exits not projected onto the surface
  std::uint64_t belowSurface = 0;      ///< continuations below the geometric surface (path ended)
  void add(const RenderStats& o);
  // Set by Integrator::render (not counters): the last noise estimate when a target was given.
  std::vector<GroupNoise> noise;
  bool noiseTargetReached = false;
};

/// Work division for several processes on one render (app/mpi_render.h; nothing here knows of
/// MPI): only the tiles t with t % parts == part are rendered by this part, every part renders the
/// same samples of its pixels, and the film's other pixels stay empty. A pixel's sums are those of
/// the undivided render (its samples in order), so adding the parts' films, where each slot is
/// filled by one part only, gives the undivided film bit for bit.
struct RenderDivision {
  std::size_t part = 0, parts = 1;
  /// With a noise target: the noise of the whole film, given this part's film; every part calls it
  /// at the same sample counts and must get the same figures (the MPI layer sums the films on rank
  /// 0, estimates there and broadcasts). Empty: filmNoise(film).
  std::function<std::vector<GroupNoise>(const Film& film)> wholeFilmNoise;
  /// Called by renderScene after the render: makes `film` and `stats` those of the whole render on
  /// the part that writes the outputs (the MPI layer sums them onto rank 0). Empty: nothing to do.
  std::function<void(Film& film, RenderStats& stats)> gather;
  bool divided() const { return parts > 1; }
};

/// Sample passes: render() adds samples to every pixel pass by pass (samples [a, b) of every
/// pixel, then [b, c), ...), so it can stop between passes with the same number of samples in
/// every pixel; a pixel's samples are always added in the order 0, 1, 2, ..., so the film's sums
/// are bit-identical however the samples are split into passes (and whether a render was stopped
/// and continued).
struct RenderOptions {
  RenderProgressFactory progress;  ///< empty: no progress display
  std::string label = "render";
  /// Samples per pixel per pass; 0: adaptive — 1 at first, then after every pass shorter than
  /// kAdaptivePassSeconds multiplied by round(kAdaptivePassSeconds / its duration), at most 8-fold,
  /// so passes settle near kAdaptivePassSeconds (the latency of a stop request).
  int samplesPerPass = 0;
  /// Asked before each pass; true stops the render (film.samplesPerPixelDone() tells how far it
  /// got).
  std::function<bool()> stopRequested;
  /// Called after each completed pass with the samples per pixel done and the pass's duration.
  std::function<void(int samplesDone, double passSeconds)> onPassDone;
  /// Stop once the film's own noise estimate (renderer/image/film_output.h's filmNoise: every
  /// band, R, G, B and chromaticity) is at most this, checked after each pass from
  /// kMinNoiseSamples samples per pixel on; the film's spp is then the cap.
  std::optional<double> noiseTarget;
  /// This process's share of the tiles (all of them by default).
  RenderDivision division;
};
constexpr int kMinNoiseSamples = 8;
/// Noise checks after the first fall on multiples of 4 samples per pixel (kFilmHalfBlock): each
/// of the film's two halves then holds whole blocks of 4 points of its sobol sequence, each block
/// a net (pixel_sampler.h). A count between leaves a half with points that are not balanced: at
/// 512², Figure 1's 1100 nm band measured 7.0 % noise at 14 spp against 5.9 % at 12 (session 15,
/// docs/benchmarks.md). It is also the least step, so that a render ends in few passes.
constexpr int kNoiseCheckGranule = 4;
constexpr double kAdaptivePassSeconds = 2.0;

/// Options for a render without a progress bar (tests, batch use).
inline RenderOptions quietRenderOptions(std::string label) {
  RenderOptions options;
  options.label = std::move(label);
  return options;
}

class Integrator {
 public:
  /// Prepares geometry, lights, materials and the skin walks for the given channel wavelengths.
  /// Throws SceneError for anything wrong in the scene or the files it refers to.
  Integrator(const SceneDesc& scene, const std::vector<double>& channelWavelengths);
  ~Integrator();

  /// Renders samples film.samplesPerPixelDone() .. film.desc().samplesPerPixel − 1 of every pixel
  /// into `film` (whose channels must be the wavelengths given to the constructor), in passes, and
  /// updates film.samplesPerPixelDone() after each; returns the counters of the samples it drew.
  /// A film continued from a saved state gets exactly the sums of an uninterrupted render.
  RenderStats render(Film& film, const RenderOptions& options = {}) const;

  /// The film channels one camera path carries: one channel (per-wavelength estimator) or every
  /// channel of band `bundle` (spectral estimator: the skin runs that band's spectral walk).
  struct PathSpectrum {
    const std::size_t* channels;
    std::size_t count;
    std::size_t bundle;
    bool spectral;
    std::size_t size() const { return count; }
    std::size_t operator[](std::size_t i) const { return channels[i]; }
  };
  /// Radiance along `ray` at each channel of `spectrum` (one path), into L[0 .. size).
  void radiance(const Ray& ray, const PathSpectrum& spectrum, skin::Rng& rng, RenderStats& stats,
                double* L) const;
  /// The same with the path's numbers from `samples` (a pixel sampler's stream).
  void radiance(const Ray& ray, const PathSpectrum& spectrum, SampleStream& samples,
                RenderStats& stats, double* L) const;
  /// Radiance along `ray` at channel `channel` (one path, per-wavelength estimator).
  double radiance(const Ray& ray, std::size_t channel, skin::Rng& rng, RenderStats& stats) const;
  skin::Estimator estimator() const {
    return spectral_ ? skin::Estimator::Spectral : skin::Estimator::PerWavelength;
  }

  const Camera& camera() const { return *camera_; }
  const EmbreeScene& geometry() const { return *geometry_; }
  const LightSet& lights() const { return *lights_; }
  /// Degenerate triangles skipped over all meshes, with a line per mesh in `report`.
  std::size_t skippedDegenerateTriangles(std::string* report = nullptr) const;
  /// The skin materials' effect plans (skin_walk_cache.h), for --explain.
  std::string effectPlanReport() const;
  /// Table mode: per skin material, the walks per table bin at each melanin level ("" otherwise).
  std::string tableWalksReport() const;

 private:
  struct Material {
    MaterialDesc::Kind kind;
    std::vector<double> reflectance;  ///< diffuse, per channel
    double refractiveIndex = 1.5;     ///< dielectric
    std::unique_ptr<SkinMaterial> skin;
  };
  /// A light sample that reached the shading point: contribution = factor × emission(light, λ).
  struct DirectSample {
    LightSample light;
    double factor;  ///< lobe density × MIS weight / pdf
  };
  /// The numbers of one next-event sample: the light (1-D), triangle or environment height (1-D),
  /// point on the triangle or environment azimuth (2-D).
  struct LightNumbers {
    double select, u0;
    std::array<double, 2> u12;
  };
  static LightNumbers drawLightNumbers(SampleStream& samples);
  /// Next-event estimate at `point` for a lobe density `lobe(ω)` (per sr, cos included);
  /// deltaOnly: only point/spot lights. nullopt when nothing arrives.
  template <typename Lobe>
  std::optional<DirectSample> directLight(const glm::dvec3& point,
                                          const glm::dvec3& geometricNormal, SampleStream& samples,
                                          bool deltaOnly, const Lobe& lobe) const;
  /// The same with given numbers (the exit point's control variate reuses the exit's).
  template <typename Lobe>
  std::optional<DirectSample> directLight(const glm::dvec3& point,
                                          const glm::dvec3& geometricNormal,
                                          const LightNumbers& numbers, bool deltaOnly,
                                          const Lobe& lobe) const;
  /// L[i] += beta[i] · albedo[i] (1 when null) · the direct sample at channel spectrum[i].
  void addDirect(const std::optional<DirectSample>& direct, const PathSpectrum& spectrum,
                 const double* beta, const double* albedo, double* L) const;
  /// The skin walk at a hit for the path's spectrum; multiplies beta by the exit weights
  /// (spectral). surfaceWeights (spectral only, may be null): the entry split's surface weights.
  /// controlBeta (spectral, may be null): where the exit has a second stage
  /// (SkinScatter::entryWeights), the control variate's throughput β_before · (A_λ − w_λ).
  /// exitSample, firstFacet (may be null): the pixel's numbers for the exit's draw and the entry's
  /// first facet (SkinMaterial::scatterSpectral).
  SkinScatter scatterSkin(const SkinMaterial& skin, const SurfaceHit& hit,
                          const glm::dvec3& direction, const PathSpectrum& spectrum, skin::Rng& rng,
                          double* beta, double* surfaceWeights = nullptr,
                          const std::array<double, 2>* exitSample = nullptr,
                          double* controlBeta = nullptr,
                          const skin::FacetNumbers* firstFacet = nullptr) const;
  /// The rest of a path from `ray` (its vertex count so far `firstDepth`) with throughput
  /// `throughput`, adding into L; splitFirstSkinHit: the first skin hit splits its entry;
  /// firstPdf > 0: the density (sr⁻¹) with which `ray`'s direction was sampled, for MIS with
  /// next-event estimation at an emitter it meets (0: a specular direction, counted fully).
  void tracePath(Ray ray, int firstDepth, const double* throughput, const PathSpectrum& spectrum,
                 SampleStream& samples, RenderStats& stats, double* L, bool splitFirstSkinHit,
                 double firstPdf = 0) const;
  /// The surface reflection scored at a split skin entry (throughput `arriving` before the skin,
  /// `beta` after the branch's Fresnel weight): next-event estimation of every light with the
  /// branch's exact lobe, then the reflected ray as a path of its own (no further split), the two
  /// combined by MIS.
  void traceSurfaceBranch(const SkinMaterial& skin, const SurfaceHit& hit,
                          const glm::dvec3& incident, const glm::dvec3& direction, int depth,
                          const double* arriving, const double* beta, const PathSpectrum& spectrum,
                          SampleStream& samples, RenderStats& stats, double* L) const;
  /// Marks the pixels whose centre ray sees a shape that does not emit (the noise mask).
  void setCoverage(Film& film) const;
  /// Samples [firstSample, endSample) of every pixel of `film` (sample passes, see RenderOptions).
  /// Returns false when `abandon` (checked before each tile) asked to stop: the film then holds
  /// part of the pass and must not be written.
  bool renderPass(Film& film, int firstSample, int endSample, const RenderDivision& division,
                  RenderStats& total, RenderProgress* progress,
                  const std::function<bool()>& abandon = {}) const;
  Ray spawn(const glm::dvec3& point, const glm::dvec3& sideNormal, const glm::dvec3& direction,
            double tMax) const;
  /// A smooth dielectric of index `refractiveIndex` at `hit`: Fresnel-chosen mirror reflection or
  /// refraction (beta takes the radiance scaling (n_from/n_to)²); the continued ray.
  Ray scatterDielectric(double refractiveIndex, const Ray& ray, const SurfaceHit& hit,
                        SampleStream& samples, double& beta) const;
  /// The material `index` of `scene` prepared for the channel wavelengths (skin: its walks or
  /// tables, only when a shape shows it). `spectra` may be null when the scene has no skin.
  static Material makeMaterial(const SceneDesc& scene, std::size_t index,
                               const std::vector<double>& channelWavelengths,
                               const skin::SpectralDatabase* spectra,
                               const std::vector<std::vector<std::size_t>>& bundles);

  SceneDesc scene_;
  std::vector<double> wavelengths_;
  std::unique_ptr<EmbreeScene> geometry_;
  std::unique_ptr<LightSet> lights_;
  std::unique_ptr<Camera> camera_;
  std::vector<Material> materials_;
  std::vector<std::size_t> materialOfShape_;
  double rayOffset_ = 1e-5;
  bool spectral_ = true;  ///< the spectral estimator (bands per path) in walk mode
};

}  // namespace hylios
