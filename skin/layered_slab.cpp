#include "skin/layered_slab.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/core/vector3.h"
#include "skin/fresnel.h"
#include "skin/interface_crossing.h"
#include "skin/layered_slab_lanes.h"
#include "skin/sampling/henyey_greenstein.h"

namespace hylios::skin {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Photons per parallel task, and tasks per in-order reduction batch (bounds the memory held).
constexpr std::uint64_t kPhotonsPerChunk = 4096;
constexpr std::uint64_t kChunksPerBatch = 256;

// Uniform azimuth as (cos phi, sin phi) without trigonometry: a uniform point in the unit disk at
// angle a gives the doubled angle 2a, uniform on the circle.
void sampleAzimuth(Rng& rng, double& cosPhi, double& sinPhi) {
  double x, y, r2;
  do {
    x = 2.0 * rng.uniform() - 1.0;
    y = 2.0 * rng.uniform() - 1.0;
    r2 = x * x + y * y;
  } while (r2 > 1.0 || r2 == 0.0);
  cosPhi = (x * x - y * y) / r2;
  sinPhi = 2.0 * x * y / r2;
}

Vec3 scatterHenyeyGreenstein(const Vec3& direction, double g, Rng& rng) {
  const double cosTheta = sampleHenyeyGreensteinCos(g, rng.uniform());
  const double sinTheta = std::sqrt(std::fmax(0.0, 1.0 - cosTheta * cosTheta));
  double cosPhi, sinPhi;
  sampleAzimuth(rng, cosPhi, sinPhi);
  return Frame(direction).toWorld({sinTheta * cosPhi, sinTheta * sinPhi, cosTheta});
}

// Hemispherical specular reflectance 2 * integral_0^1 R(mu) mu dmu by composite Simpson's rule,
// split at the critical cosine where R has a kink (light from a denser ambient).
double hemisphericalReflectance(double nIncident, double nTransmitted) {
  auto integrand = [&](double mu) {
    return 2.0 * mu * fresnelReflectance(mu, nIncident, nTransmitted);
  };
  auto simpson = [&](double a, double b) {
    constexpr int kIntervals = 1 << 14;  // even
    const double h = (b - a) / kIntervals;
    double sum = integrand(a) + integrand(b);
    for (int i = 1; i < kIntervals; ++i) sum += integrand(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    return sum * h / 3.0;
  };
  if (nIncident <= nTransmitted) return simpson(0.0, 1.0);
  const double sinCritical = nTransmitted / nIncident;
  const double muCritical = std::sqrt(1.0 - sinCritical * sinCritical);
  return muCritical * muCritical + simpson(muCritical, 1.0);  // R = 1 below muCritical
}

std::string layerLabel(std::size_t i) { return "layer " + std::to_string(i + 1); }

void requireFiniteNonNegative(double value, const std::string& where, const char* name) {
  if (!std::isfinite(value) || value < 0.0)
    throw std::invalid_argument(where + ": " + name + " must be finite and >= 0, got " +
                                fmt::format("{:g}", value));
}

void requireIndex(double n, const std::string& where) {
  if (!std::isfinite(n) || n <= 0.0)
    throw std::invalid_argument(where + ": refractive index must be finite and > 0, got " +
                                fmt::format("{:g}", n));
}

}  // namespace

void validateSlabProblem(const SlabProblem& problem) {
  requireIndex(problem.refractiveIndexAbove, "ambient above");
  requireIndex(problem.refractiveIndexBelow, "ambient below");
  if (problem.layers.empty()) throw std::invalid_argument("slab: at least one layer is needed");
  const double angle = problem.incidenceAngleDeg;
  if (!(angle >= 0.0 && angle < 90.0))
    throw std::invalid_argument("slab: incidence angle must be in [0, 90) degrees, got " +
                                fmt::format("{:g}", angle));
  for (std::size_t i = 0; i < problem.layers.size(); ++i) {
    const SlabLayer& layer = problem.layers[i];
    const std::string where = layerLabel(i);
    requireIndex(layer.refractiveIndex, where);
    requireFiniteNonNegative(layer.muA_perCm, where, "mua");
    requireFiniteNonNegative(layer.muS_perCm, where, "mus");
    if (!(layer.anisotropyG > -1.0 && layer.anisotropyG < 1.0))
      throw std::invalid_argument(where + ": g must be in (-1, 1), got " +
                                  fmt::format("{:g}", layer.anisotropyG));
    const bool last = i + 1 == problem.layers.size();
    if (std::isinf(layer.thicknessCm) && layer.thicknessCm > 0) {
      if (!last)
        throw std::invalid_argument(where + ": only the last layer may be semi-infinite (d = inf)");
      if (layer.muA_perCm + layer.muS_perCm <= 0.0)
        throw std::invalid_argument(where + ": a semi-infinite layer needs mua + mus > 0");
    } else {
      requireFiniteNonNegative(layer.thicknessCm, where, "d (thickness in cm)");
    }
  }
}

SlabWalker::SlabWalker(const SlabProblem& problem, AbsorptionScheme scheme,
                       std::uint32_t eventLimit)
    : scheme_(scheme), eventLimit_(eventLimit) {
  validateSlabProblem(problem);
  if (eventLimit < 1) throw std::invalid_argument("slab: the event limit must be at least 1");
  double z = 0.0;
  const std::size_t count = problem.layers.size();
  for (std::size_t i = 0; i < count; ++i) {
    const SlabLayer& in = problem.layers[i];
    LayerData out{};
    out.zTopCm = z;
    z += in.thicknessCm;
    out.zBottomCm = z;
    out.muT_perCm = in.muA_perCm + in.muS_perCm;
    out.absorptionProbability = out.muT_perCm > 0.0 ? in.muA_perCm / out.muT_perCm : 0.0;
    out.g = in.anisotropyG;
    out.n = in.refractiveIndex;
    out.nAbove = i == 0 ? problem.refractiveIndexAbove : problem.layers[i - 1].refractiveIndex;
    out.nBelow =
        i + 1 == count ? problem.refractiveIndexBelow : problem.layers[i + 1].refractiveIndex;
    layers_.push_back(out);
  }
  diffuseIncidence_ = problem.diffuseIncidence;
  nAmbientAbove_ = problem.refractiveIndexAbove;
  if (diffuseIncidence_) {
    specularReflectance_ = hemisphericalReflectance(nAmbientAbove_, layers_[0].n);
    launchWeight_ = 1.0 - specularReflectance_;
    if (!(launchWeight_ > 0.0))
      throw std::invalid_argument("slab: diffuse light cannot enter layer 1 (all reflected)");
    return;
  }
  const double theta = problem.incidenceAngleDeg * kPi / 180.0;
  const double cosIncident = std::cos(theta);
  const FresnelResult f = fresnel(cosIncident, problem.refractiveIndexAbove, layers_[0].n);
  specularReflectance_ = f.reflectance;  // < 1: going into layer 1, below 90 deg
  launchWeight_ = 1.0 - f.reflectance;
  launchCosTheta_ = f.cosTransmitted;
  launchSinTheta_ = std::sin(theta) * problem.refractiveIndexAbove / layers_[0].n;  // Snell
}

double SlabWalker::sampleDiffuseEntryCos(Rng& rng) const {
  // Cosine-weighted proposal mu = sqrt(u), accepted with the entering fraction 1 - R(mu) <= 1.
  for (;;) {
    const double mu = std::sqrt(rng.uniform());
    if (rng.uniform() >= fresnelReflectance(mu, nAmbientAbove_, layers_[0].n)) return mu;
  }
}

Vec3 SlabWalker::launchDirection(Rng& rng) const {
  if (!diffuseIncidence_) return {launchSinTheta_, 0.0, launchCosTheta_};
  // Azimuth is irrelevant in a plane-parallel stack: the walk sees only u.z and the layers.
  const double muAmbient = sampleDiffuseEntryCos(rng);
  const FresnelResult f = fresnel(muAmbient, nAmbientAbove_, layers_[0].n);
  const double sinAmbient = std::sqrt(std::fmax(0.0, 1.0 - muAmbient * muAmbient));
  return {sinAmbient * nAmbientAbove_ / layers_[0].n, 0.0, f.cosTransmitted};
}

void SlabWalker::trace(Rng& rng, PhotonScores& scores) const {
  scores.diffuseReflectance = scores.transmittance = scores.unscatteredTransmittance = 0.0;
  scores.eventLimited = 0.0;
  scores.layerAbsorptance.assign(layers_.size(), 0.0);
  const std::size_t lastLayer = layers_.size() - 1;
  const bool analog = scheme_ == AbsorptionScheme::Analog;
  double weight = launchWeight_;
  Vec3 u = launchDirection(rng);
  double z = 0.0;
  std::size_t k = 0;
  bool scattered = false;
  // Events counted as the lane walk counts its steps: each boundary meeting and each interaction,
  // checked before it happens.
  std::uint32_t events = 0;
  for (;;) {
    // Optical depth to the next interaction, Exp(1) (equivalent to the paper's Eq. 1 minimum over
    // processes). 1 - uniform() is in (0, 1], so the log is finite.
    double opticalDepth = -std::log(1.0 - rng.uniform());
    // Move, crossing boundaries until the interaction falls inside a layer; the optical depth not
    // used up in one layer is carried into the next (MCML's partial-step logic).
    for (;;) {
      const LayerData& layer = layers_[k];
      const double distanceToBoundary = u.z > 0.0   ? (layer.zBottomCm - z) / u.z
                                        : u.z < 0.0 ? (layer.zTopCm - z) / u.z
                                                    : kInfinity;
      if (layer.muT_perCm > 0.0 && opticalDepth < layer.muT_perCm * distanceToBoundary) {
        z += u.z * (opticalDepth / layer.muT_perCm);
        break;
      }
      if (distanceToBoundary == kInfinity)  // unreachable: validation and Snell forbid it
        throw std::logic_error("slab walk: photon travels forever in a lossless layer");
      if (++events > eventLimit_) {  // the boundary meeting
        scores.eventLimited = weight;
        return;
      }
      opticalDepth -= layer.muT_perCm * distanceToBoundary;
      const bool down = u.z > 0.0;
      z = down ? layer.zBottomCm : layer.zTopCm;
      const InterfaceCrossing crossing =
          crossPlaneInterfaceZ(u, layer.n, down ? layer.nBelow : layer.nAbove, rng);
      u = crossing.direction;
      if (!crossing.transmitted) continue;
      if (down) {
        if (k == lastLayer) {
          scores.transmittance = weight;
          if (!scattered) scores.unscatteredTransmittance = weight;
          return;
        }
        ++k;
      } else {
        if (k == 0) {
          scores.diffuseReflectance = weight;
          return;
        }
        --k;
      }
    }
    if (++events > eventLimit_) {  // the interaction
      scores.eventLimited = weight;
      return;
    }
    const LayerData& layer = layers_[k];
    if (analog) {
      if (rng.uniform() < layer.absorptionProbability) {
        scores.layerAbsorptance[k] = weight;
        return;
      }
    } else {
      const double deposited = weight * layer.absorptionProbability;
      scores.layerAbsorptance[k] += deposited;
      weight -= deposited;
      if (weight < kSlabRouletteThreshold) {
        if (weight == 0.0 || rng.uniform() >= kSlabRouletteSurvival)
          return;                               // weight lost to roulette
        weight *= 1.0 / kSlabRouletteSurvival;  // 1/0.1 rounds to 10 exactly
      }
    }
    u = scatterHenyeyGreenstein(u, layer.g, rng);
    scattered = true;
  }
}

namespace {

// Per-chunk accumulators: [0] Rd, [1] Tt, [2] unscattered Tt, [3] diffuse Tt, [4] total A,
// [5] event-limited, [6 + l] A of layer l.
using Tally = std::vector<RunningStatistic>;
constexpr std::size_t kEventLimitedTally = 5, kFirstLayerTally = 6;

void addPacket(Tally& tally, double diffuseReflectance, double transmittance,
               double unscatteredTransmittance, double eventLimited, const double* layerAbsorptance,
               std::size_t layers) {
  tally[0].add(diffuseReflectance);
  tally[1].add(transmittance);
  tally[2].add(unscatteredTransmittance);
  tally[3].add(transmittance - unscatteredTransmittance);
  tally[kEventLimitedTally].add(eventLimited);
  double absorbed = 0.0;
  for (std::size_t l = 0; l < layers; ++l) {
    absorbed += layerAbsorptance[l];
    tally[kFirstLayerTally + l].add(layerAbsorptance[l]);
  }
  tally[4].add(absorbed);
}

void traceChunk(const SlabWalker& walker, std::uint64_t seed, std::uint64_t first,
                std::uint64_t last, Tally& tally) {
  PhotonScores scores;
  for (std::uint64_t i = first; i < last; ++i) {
    Rng rng(seed, 0, i);
    walker.trace(rng, scores);
    addPacket(tally, scores.diffuseReflectance, scores.transmittance,
              scores.unscatteredTransmittance, scores.eventLimited, scores.layerAbsorptance.data(),
              scores.layerAbsorptance.size());
  }
}

// The lane walk writes each packet's row; the rows are summed in packet order.
void traceChunkInLanes(const SlabLaneWalker& lanes, std::uint64_t seed, std::uint64_t first,
                       std::uint64_t last, Tally& tally) {
  const std::size_t stride = lanes.scoresPerPacket();
  std::vector<double> rows((last - first) * stride);
  lanes.trace(seed, first, last, rows.data());
  for (std::size_t i = 0; i < last - first; ++i) {
    const double* row = rows.data() + i * stride;
    addPacket(tally, row[SlabLaneWalker::kDiffuseReflectance], row[SlabLaneWalker::kTransmittance],
              row[SlabLaneWalker::kUnscatteredTransmittance], row[SlabLaneWalker::kEventLimited],
              row + SlabLaneWalker::kFirstLayerAbsorptance,
              stride - SlabLaneWalker::kFirstLayerAbsorptance);
  }
}

}  // namespace

SlabResult simulateLayeredSlab(const SlabProblem& problem, const SlabRunOptions& options) {
  const SlabWalker walker(problem, options.scheme, options.eventLimit);
  const bool inLanes = options.laneWalk && options.scheme == AbsorptionScheme::WeightWithRoulette &&
                       SlabLaneWalker::represents(walker);
  const std::optional<SlabLaneWalker> lanes =
      inLanes ? std::optional<SlabLaneWalker>(std::in_place, walker) : std::nullopt;
  const std::size_t quantities = kFirstLayerTally + walker.layerCount();
  Tally total(quantities);
  const std::uint64_t chunks = (options.photons + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
  std::vector<Tally> batch;
  for (std::uint64_t firstChunk = 0; firstChunk < chunks; firstChunk += kChunksPerBatch) {
    const std::uint64_t batchChunks = std::min(kChunksPerBatch, chunks - firstChunk);
    batch.assign(batchChunks, Tally(quantities));
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, batchChunks, 1),
                      [&](const tbb::blocked_range<std::uint64_t>& range) {
                        for (std::uint64_t c = range.begin(); c != range.end(); ++c) {
                          const std::uint64_t first = (firstChunk + c) * kPhotonsPerChunk;
                          const std::uint64_t last =
                              std::min(options.photons, first + kPhotonsPerChunk);
                          if (lanes)
                            traceChunkInLanes(*lanes, options.seed, first, last, batch[c]);
                          else
                            traceChunk(walker, options.seed, first, last, batch[c]);
                        }
                      });
    for (const Tally& chunk : batch)  // in chunk order: the sums do not depend on the threads
      for (std::size_t q = 0; q < quantities; ++q) total[q].merge(chunk[q]);
  }
  SlabResult result;
  result.specularReflectance = walker.specularReflectance();
  result.diffuseReflectance = total[0].estimate();
  result.transmittance = total[1].estimate();
  result.unscatteredTransmittance = total[2].estimate();
  result.diffuseTransmittance = total[3].estimate();
  result.absorptance = total[4].estimate();
  result.eventLimited = total[kEventLimitedTally].estimate();
  for (std::size_t l = 0; l < walker.layerCount(); ++l)
    result.layerAbsorptance.push_back(total[kFirstLayerTally + l].estimate());
  result.photons = options.photons;
  return result;
}

}  // namespace hylios::skin
