#include "skin/exit_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skin/core/constants.h"
#include "skin/core/content_hash.h"
#include "skin/exit_table_rays.h"
#include "skin/sampling/discrete_sampling.h"

namespace hylios::skin {
namespace {

constexpr std::uint64_t kChunkRays = 2048;
// Outcomes: subsurface, transmitted, event limit, absorbed by layer outside and inside melanosomes.
constexpr std::size_t kOutcomes = 3 + 2 * kLayerCount;
constexpr std::size_t kOutcomeAbsorbed = 3, kOutcomeMelanosome = 3 + kLayerCount;

void checkRange(const char* name, std::uint64_t value, std::uint64_t lo, std::uint64_t hi) {
  if (value < lo || value > hi)
    throw std::invalid_argument(std::string("exit table: ") + name + " = " + std::to_string(value) +
                                " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                "]");
}

void validateSettings(const ExitTableSettings& s) {
  auto nonNegative = [](int v) { return static_cast<std::uint64_t>(std::max(v, 0)); };
  checkRange("cosine bins", nonNegative(s.cosineBins), 1, 4096);
  checkRange("radial bins", nonNegative(s.radialBins), 1, 4096);
  checkRange("offset azimuth bins", nonNegative(s.offsetAzimuthBins), 1, 4096);
  checkRange("polar bins", nonNegative(s.polarBins), 1, 4096);
  checkRange("rays per bin", s.raysPerBin, 2, std::uint64_t{1} << 32);
}

std::vector<double> fractions(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) total += w;
  std::vector<double> f;
  for (double w : weights) f.push_back(total > 0 ? w / total : 0.0);
  return f;
}

/// Mean and standard error of a per-path score from its sum and sum of squares over `rays` paths.
Estimate meanOfScores(double sum, double squares, std::uint64_t rays) {
  const double n = static_cast<double>(rays), mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1))};
}

void hashOptics(ContentHash& h, const SkinOptics& o) {
  h.addDouble(o.wavelengthNm);
  for (const LayerOptics& l : o.layers) {
    h.addDouble(l.thicknessCm).addDouble(l.refractiveIndex);
    for (double mu : l.muA_perCm) h.addDouble(mu);
    h.addDouble(l.muATotal_perCm).addDouble(l.muRayleigh_perCm);
    const MelanosomeOptics& m = l.melanosome;
    h.addDouble(m.semiMinorAxisCm)
        .addDouble(m.semiMajorAxisCm)
        .addBool(m.inComplexes)
        .addDouble(m.complexRadiusCm);
    h.addDouble(static_cast<double>(m.melanosomesPerComplex)).addDouble(m.mu_perCm);
  }
  h.addDouble(o.melanosomeInteriorMuA_perCm).addDouble(o.melaninRefractiveIndex);
  h.addDouble(o.meanScatteringAngleRad).addDouble(o.surfaceAspectRatio);
}

void hashWalkAndSettings(ContentHash& h, const WalkOptions& walk, const ExitTableSettings& s) {
  h.addBool(walk.melanosomes).addBool(walk.rayleigh).addBool(walk.roughSurface);
  h.addU64(static_cast<std::uint64_t>(index(walk.deepestLayer)))
      .addDouble(walk.belowRefractiveIndex);
  h.addBool(walk.tabulatedMelanosomes);
  h.addU64(static_cast<std::uint64_t>(s.cosineBins)).addU64(s.raysPerBin).addU64(s.seed);
  h.addU64(static_cast<std::uint64_t>(s.radialBins))
      .addU64(static_cast<std::uint64_t>(s.offsetAzimuthBins));
  h.addU64(static_cast<std::uint64_t>(s.polarBins)).addBool(s.tabulatedMelanosomes);
  h.addDouble(ExitTable::kMinRadiusCm).addDouble(ExitTable::kMaxRadiusCm);
  if (s.raysByUse)  // (absent for uniform bins, so their keys are those of before the rule)
    h.addString("rays by use")
        .addDouble(kFullUse)
        .addDouble(kLeastRaysFraction)
        .addU64(static_cast<std::uint64_t>(kUseAngles))
        .addU64(static_cast<std::uint64_t>(kUseEntriesPerAngle));
}

/// Polar bin of a cosine in [0, 1] (uniform bins; cosine 1 goes to the last).
std::size_t polarBin(double cosine, int bins) {
  return static_cast<std::size_t>(std::clamp(static_cast<int>(cosine * bins), 0, bins - 1));
}

/// The build's walk options: the walk's own, with tabulated melanosomes when the settings ask.
WalkOptions buildOptions(const WalkOptions& walk, const ExitTableSettings& settings) {
  WalkOptions options = walk;
  options.tabulatedMelanosomes = options.tabulatedMelanosomes || settings.tabulatedMelanosomes;
  return options;
}

/// Whether two walks' options give the same exit tables (the options traceEntered reads).
bool sameWalkPhysics(const WalkOptions& a, const WalkOptions& b) {
  return a.melanosomes == b.melanosomes && a.rayleigh == b.rayleigh &&
         a.roughSurface == b.roughSurface && a.deepestLayer == b.deepestLayer &&
         a.belowRefractiveIndex == b.belowRefractiveIndex &&
         a.tabulatedMelanosomes == b.tabulatedMelanosomes;
}

std::uint64_t chunksOf(std::uint64_t rays) { return (rays + kChunkRays - 1) / kChunkRays; }

}  // namespace

std::uint64_t ExitTable::key(const SkinOptics& optics, const WalkOptions& walk,
                             const ExitTableSettings& settings) {
  ContentHash h;
  h.addString("hylios exit table").addU64(kExitTableFormatVersion);
  hashOptics(h, optics);
  hashWalkAndSettings(h, walk, settings);
  return h.value();
}

std::uint64_t ExitTable::bundleKey(const std::vector<const SkinWalk*>& bundle, std::size_t member,
                                   const ExitTableSettings& settings) {
  if (bundle.size() == 1) return key(bundle[0]->optics(), bundle[0]->options(), settings);
  ContentHash h;
  h.addString("hylios spectral exit table").addU64(kExitTableFormatVersion);
  h.addU64(bundle.size()).addU64(member);
  for (const SkinWalk* walk : bundle) hashOptics(h, walk->optics());
  hashWalkAndSettings(h, bundle.at(member)->options(), settings);
  return h.value();
}

ExitTable::ExitTable(const SkinWalk& walk, const ExitTableSettings& settings, std::uint64_t key,
                     std::size_t bundleSize)
    : walk_(walk), settings_(settings), key_(key), bundleSize_(bundleSize) {
  validateSettings(settings);
}

ExitTable::Bin& ExitTable::newBin() { return bins_.emplace_back(emptyBin()); }

ExitTable::Bin ExitTable::emptyBin() const {
  Bin b;
  b.offsetWeights.assign(
      static_cast<std::size_t>(settings_.radialBins + 2) * settings_.offsetAzimuthBins, 0);
  b.exitPolarWeights.assign(static_cast<std::size_t>(settings_.polarBins), 0);
  b.transmittedPolarWeights.assign(static_cast<std::size_t>(settings_.polarBins), 0);
  return b;
}

void ExitTable::Bin::merge(const Bin& o) {
  rays += o.rays;
  subsurface += o.subsurface;
  transmitted += o.transmitted;
  eventLimited += o.eventLimited;
  subsurfaceSquares += o.subsurfaceSquares;
  transmittedSquares += o.transmittedSquares;
  eventLimitedSquares += o.eventLimitedSquares;
  absorbedSquares += o.absorbedSquares;
  for (std::size_t l = 0; l < kLayerCount; ++l) {
    absorbed[l] += o.absorbed[l];
    absorbedInMelanosome[l] += o.absorbedInMelanosome[l];
    absorbedSquaresByLayer[l] += o.absorbedSquaresByLayer[l];
  }
  for (std::size_t i = 0; i < offsetWeights.size(); ++i) offsetWeights[i] += o.offsetWeights[i];
  for (std::size_t i = 0; i < exitPolarWeights.size(); ++i)
    exitPolarWeights[i] += o.exitPolarWeights[i];
  for (std::size_t i = 0; i < transmittedPolarWeights.size(); ++i)
    transmittedPolarWeights[i] += o.transmittedPolarWeights[i];
  largestRadiusCm = std::max(largestRadiusCm, o.largestRadiusCm);
  radiusSumCm += o.radiusSumCm;
  radiusSquaresSumCm2 += o.radiusSquaresSumCm2;
}

void ExitTable::Bin::addSubsurface(double weight, double radiusCm, std::size_t cell,
                                   std::size_t exitPolar) {
  subsurface += weight;
  subsurfaceSquares += weight * weight;
  offsetWeights[cell] += weight;
  exitPolarWeights[exitPolar] += weight;
  largestRadiusCm = std::max(largestRadiusCm, radiusCm);
  radiusSumCm += weight * radiusCm;
  radiusSquaresSumCm2 += weight * radiusCm * radiusCm;
}

void ExitTable::Bin::addTransmitted(double weight, std::size_t polar) {
  transmitted += weight;
  transmittedSquares += weight * weight;
  transmittedPolarWeights[polar] += weight;
}

int ExitTable::radialCell(double radiusCm) const {
  if (radiusCm < kMinRadiusCm) return 0;
  if (radiusCm >= kMaxRadiusCm) return settings_.radialBins + 1;
  const double x = std::log(radiusCm / kMinRadiusCm) / std::log(kMaxRadiusCm / kMinRadiusCm) *
                   settings_.radialBins;
  return 1 + std::clamp(static_cast<int>(x), 0, settings_.radialBins - 1);  // rounding at edges
}

ExitTable::PathCells ExitTable::subsurfaceCells(double offsetXCm, double offsetYCm,
                                                const Vec3& exitDirection) const {
  PathCells cells;
  const double r = std::hypot(offsetXCm, offsetYCm);
  cells.radiusCm = r;
  // Entry direction has azimuth 0 (x axis): the offset's azimuth from it, folded to [0, π].
  const double phi = r > 0 ? std::atan2(std::fabs(offsetYCm), offsetXCm) : 0.0;
  const int a = std::clamp(static_cast<int>(phi / kPi * settings_.offsetAzimuthBins), 0,
                           settings_.offsetAzimuthBins - 1);
  cells.offset = static_cast<std::size_t>(radialCell(r)) * settings_.offsetAzimuthBins +
                 static_cast<std::size_t>(a);
  cells.polar = polarBin(-exitDirection.z, settings_.polarBins);
  return cells;
}

double ExitTable::radialCellLowerCm(int cell) const {
  if (cell == 0) return 0;
  if (cell > settings_.radialBins) return kMaxRadiusCm;
  return kMinRadiusCm * std::pow(kMaxRadiusCm / kMinRadiusCm,
                                 static_cast<double>(cell - 1) / settings_.radialBins);
}

double ExitTable::radialCellUpperCm(int bin, int cell) const {
  if (cell == 0) return kMinRadiusCm;
  if (cell > settings_.radialBins) return bins_[static_cast<std::size_t>(bin)].largestRadiusCm;
  return kMinRadiusCm *
         std::pow(kMaxRadiusCm / kMinRadiusCm, static_cast<double>(cell) / settings_.radialBins);
}

void ExitTable::tally(Bin& bin, const SkinPath& path) const {
  ++bin.rays;
  switch (path.end) {
    case PathEnd::SubsurfaceReflection: {
      const PathCells cells =
          subsurfaceCells(path.exitOffsetXCm, path.exitOffsetYCm, path.exitDirection);
      bin.addSubsurface(1, cells.radiusCm, cells.offset, cells.polar);
      break;
    }
    case PathEnd::Transmitted:
      bin.addTransmitted(1, polarBin(path.exitDirection.z, settings_.polarBins));
      break;
    case PathEnd::Absorbed: {
      const std::size_t l = index(path.layer);
      bin.absorbed[l] += 1;
      bin.absorbedSquaresByLayer[l] += 1;
      bin.absorbedSquares += 1;
      if (path.absorbedInMelanosome) bin.absorbedInMelanosome[l] += 1;
      break;
    }
    case PathEnd::EventLimit:
    case PathEnd::SurfaceReflection:  // traceEntered never reflects at the surface: a limit
      bin.eventLimited += 1;
      bin.eventLimitedSquares += 1;
      break;
  }
}

ExitTable::PathCells ExitTable::cellsOf(const SpectralPath& path) const {
  if (path.end == PathEnd::SubsurfaceReflection)
    return subsurfaceCells(path.exitOffsetXCm, path.exitOffsetYCm, path.exitDirection);
  PathCells cells;
  if (path.end == PathEnd::Transmitted && path.transmittedDirection.empty()) {
    cells.polar = polarBin(path.exitDirection.z, settings_.polarBins);
  }
  return cells;
}

void ExitTable::tally(Bin& bin, const SpectralPath& path, std::size_t member,
                      const PathCells& cells) const {
  if (path.split)  // one exit per path here (WalkOptions::splitFirstRayleigh is for curves)
    throw std::logic_error("ExitTable: a spectral path split at a Rayleigh event");
  ++bin.rays;
  const double exit = path.exitWeight[member];
  switch (path.end) {
    case PathEnd::SubsurfaceReflection:
      bin.addSubsurface(exit, cells.radiusCm, cells.offset, cells.polar);
      break;
    case PathEnd::Transmitted: {  // per-λ directions where the bottom refracts each λ elsewhere
      const std::size_t polar =
          path.transmittedDirection.empty()
              ? cells.polar
              : polarBin(path.transmittedDirection[member].z, settings_.polarBins);
      bin.addTransmitted(exit, polar);
      break;
    }
    case PathEnd::EventLimit:
    case PathEnd::SurfaceReflection:
      bin.eventLimited += exit;
      bin.eventLimitedSquares += exit * exit;
      break;
    case PathEnd::Absorbed:  // ended by Russian roulette: its weight was booked on the way
      break;
  }
  double absorbedHere = 0;
  const std::size_t members = path.exitWeight.size();
  for (std::size_t l = 0; l < kLayerCount; ++l) {
    const double a = path.absorbed[l * members + member];
    bin.absorbed[l] += a;
    bin.absorbedSquaresByLayer[l] += a * a;
    bin.absorbedInMelanosome[l] += path.absorbedInMelanosomes[l * members + member];
    absorbedHere += a;
  }
  bin.absorbedSquares += absorbedHere * absorbedHere;
}

std::vector<std::uint64_t> ExitTable::raysOfBins(const SkinWalk& walk,
                                                 const ExitTableSettings& settings) {
  validateSettings(settings);
  const auto bins = static_cast<std::size_t>(settings.cosineBins);
  if (!settings.raysByUse) return std::vector<std::uint64_t>(bins, settings.raysPerBin);
  return raysByUse(worstCaseBinUse(walk, settings.cosineBins, settings.seed), settings.raysPerBin);
}

ExitTable ExitTable::build(const SkinWalk& walk, const ExitTableSettings& settings) {
  ExitTable table(walk, settings, key(walk.optics(), walk.options(), settings), 1);
  const SkinWalk buildWalk(walk.optics(), buildOptions(walk.options(), settings));
  const std::vector<std::uint64_t> rays = raysOfBins(walk, settings);
  struct Task {
    std::size_t bin;
    std::uint64_t first, last;
  };
  std::vector<Task> tasks;  // fixed chunks of every bin, in bin order
  for (std::size_t k = 0; k < rays.size(); ++k)
    for (std::uint64_t first = 0; first < rays[k]; first += kChunkRays)
      tasks.push_back({k, first, std::min(first + kChunkRays, rays[k])});
  std::vector<Bin> partials(tasks.size(), table.emptyBin());  // per-chunk partial bins
  tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t t) {
    const Task& task = tasks[t];
    const double mu = table.binCosine(static_cast<int>(task.bin));
    const Vec3 direction{std::sqrt(1 - mu * mu), 0, mu};
    for (std::uint64_t i = task.first; i < task.last; ++i) {
      Rng rng(settings.seed, task.bin, i);
      table.tally(partials[t], buildWalk.traceEntered(direction, rng));
    }
  });
  for (std::size_t k = 0, t = 0; k < rays.size(); ++k) {
    Bin& b = table.newBin();
    for (; t < tasks.size() && tasks[t].bin == k; ++t) b.merge(partials[t]);
  }
  table.prepareSampling();
  return table;
}

std::vector<ExitTable> ExitTable::buildBundle(const std::vector<const SkinWalk*>& bundle,
                                              const ExitTableSettings& settings) {
  if (bundle.empty()) throw std::invalid_argument("exit table: a bundle needs a wavelength");
  if (bundle.size() == 1) return {build(*bundle[0], settings)};
  std::vector<SkinOptics> optics;
  for (const SkinWalk* walk : bundle) {
    if (!sameWalkPhysics(walk->options(), bundle[0]->options()))
      throw std::invalid_argument("exit table: the walks of a bundle must share their options");
    optics.push_back(walk->optics());
  }
  WalkOptions options = buildOptions(bundle[0]->options(), settings);
  options.layerAbsorption = true;
  options.melanosomeAbsorption = true;  // the tables' melanosome outcomes
  options.splitEntryReflection = false;
  const SpectralWalk spectral(optics, options);
  const std::size_t members = bundle.size();
  std::vector<ExitTable> tables;
  for (std::size_t m = 0; m < members; ++m)
    tables.push_back(ExitTable(*bundle[m], settings, bundleKey(bundle, m, settings), members));
  // Bin by bin (partials for one bin's chunks × members at a time), chunks in parallel.
  const std::vector<std::uint64_t> rays = raysOfBins(*bundle[0], settings);
  for (int k = 0; k < settings.cosineBins; ++k) {
    const double mu = tables[0].binCosine(k);
    const Vec3 direction{std::sqrt(1 - mu * mu), 0, mu};
    const std::uint64_t binRays = rays[static_cast<std::size_t>(k)], chunks = chunksOf(binRays);
    std::vector<Bin> partials(chunks * members, tables[0].emptyBin());  // [chunk][member]
    tbb::parallel_for(std::uint64_t{0}, chunks, [&](std::uint64_t c) {
      SpectralPath path;
      const std::uint64_t last = std::min((c + 1) * kChunkRays, binRays);
      for (std::uint64_t i = c * kChunkRays; i < last; ++i) {
        Rng rng(settings.seed, static_cast<std::uint64_t>(k), i);
        spectral.traceEntered(direction, rng, path);
        const PathCells cells = tables[0].cellsOf(path);  // the members share their settings
        for (std::size_t m = 0; m < members; ++m)
          tables[m].tally(partials[c * members + m], path, m, cells);
      }
    });
    for (std::size_t m = 0; m < members; ++m) {
      Bin& b = tables[m].newBin();
      for (std::uint64_t c = 0; c < chunks; ++c) b.merge(partials[c * members + m]);
    }
  }
  for (ExitTable& table : tables) table.prepareSampling();
  return tables;
}

void ExitTable::prepareSampling() {
  for (Bin& b : bins_) {
    std::vector<double> outcomes(kOutcomes, 0);
    outcomes[0] = b.subsurface;
    outcomes[1] = b.transmitted;
    outcomes[2] = b.eventLimited;
    for (std::size_t l = 0; l < kLayerCount; ++l) {
      outcomes[kOutcomeAbsorbed + l] = std::max(0.0, b.absorbed[l] - b.absorbedInMelanosome[l]);
      outcomes[kOutcomeMelanosome + l] = b.absorbedInMelanosome[l];
    }
    b.outcomeCdf = cumulativeWeights(outcomes);
    b.offsetCdf = cumulativeWeights(b.offsetWeights);
    b.exitPolarCdf = cumulativeWeights(b.exitPolarWeights);
    b.transmittedPolarCdf = cumulativeWeights(b.transmittedPolarWeights);
  }
}

SkinPath ExitTable::sample(const Vec3& incident, Rng& rng) const {
  const InterfaceCrossing entry = walk_.enterFromAir(incident, rng);
  if (entry.transmitted) return sampleEntered(entry.direction, rng);
  SkinPath path;
  path.events = 1;
  path.end = PathEnd::SurfaceReflection;
  path.exitDirection = entry.direction;
  return path;
}

SkinPath ExitTable::sampleEntered(const Vec3& transmitted, Rng& rng) const {
  return sampleBin(bins_[static_cast<std::size_t>(chooseBin(transmitted.z, rng.uniform()))],
                   transmitted, rng);
}

int ExitTable::chooseBin(double transmittedCosine, double u) const {
  const int bins = settings_.cosineBins;
  const double x = std::clamp(transmittedCosine, 0.0, 1.0) * bins - 1;  // centres at (k + 1)/K
  if (x >= bins - 1) return bins - 1;
  if (!(x > 0)) return 0;
  const int k = static_cast<int>(x);
  return u < x - k ? k + 1 : k;  // linear interpolation between the centres k and k + 1
}

double ExitTable::radiusInCell(int bin, int radial, double v) const {
  const double lo = radialCellLowerCm(radial), hi = radialCellUpperCm(bin, radial);
  if (radial == 0) return hi * std::sqrt(v);                     // uniform in area
  if (radial > settings_.radialBins) return lo + v * (hi - lo);  // overflow: uniform
  return lo * std::pow(hi / lo, v);                              // log-uniform
}

SkinPath ExitTable::sampleBin(const Bin& bin, const Vec3& transmitted, Rng& rng) const {
  SkinPath path;
  path.events = 1;
  const std::size_t outcome = pickCumulative(bin.outcomeCdf, rng.uniform());
  auto polarDirection = [&](const std::vector<double>& cdf, double zSign) {
    const double cosine =
        (static_cast<double>(pickCumulative(cdf, rng.uniform())) + rng.uniform()) /
        settings_.polarBins;
    const double sine = std::sqrt(std::max(0.0, 1 - cosine * cosine));
    const double phi = 2 * kPi * rng.uniform();
    return Vec3{sine * std::cos(phi), sine * std::sin(phi), zSign * cosine};
  };
  if (outcome >= kOutcomeAbsorbed) {
    path.end = PathEnd::Absorbed;
    path.absorbedInMelanosome = outcome >= kOutcomeMelanosome;
    path.layer = kAllLayers[(outcome - kOutcomeAbsorbed) % kLayerCount];
    return path;
  }
  if (outcome == 2) {
    path.end = PathEnd::EventLimit;
    return path;
  }
  if (outcome == 1) {
    path.end = PathEnd::Transmitted;
    path.exitDirection = polarDirection(bin.transmittedPolarCdf, 1);
    return path;
  }
  path.end = PathEnd::SubsurfaceReflection;
  const std::size_t A = static_cast<std::size_t>(settings_.offsetAzimuthBins);
  const std::size_t cell = pickCumulative(bin.offsetCdf, rng.uniform());
  const int binIndex = static_cast<int>(&bin - bins_.data());
  const double r = radiusInCell(binIndex, static_cast<int>(cell / A), rng.uniform());
  double phi = (static_cast<double>(cell % A) + rng.uniform()) / static_cast<double>(A) * kPi;
  if (rng.uniform() < 0.5) phi = -phi;
  phi += std::atan2(transmitted.y, transmitted.x);
  path.exitOffsetXCm = r * std::cos(phi);
  path.exitOffsetYCm = r * std::sin(phi);
  path.exitDirection = polarDirection(bin.exitPolarCdf, -1);
  return path;
}

BinStatistics ExitTable::statistics(int k) const {
  const Bin& b = bins_.at(static_cast<std::size_t>(k));
  BinStatistics s;
  s.transmittedCosine = binCosine(k);
  s.rays = b.rays;
  s.subsurface = meanOfScores(b.subsurface, b.subsurfaceSquares, b.rays);
  s.transmitted = meanOfScores(b.transmitted, b.transmittedSquares, b.rays);
  s.eventLimited = meanOfScores(b.eventLimited, b.eventLimitedSquares, b.rays);
  double absorbed = 0;
  for (std::size_t l = 0; l < kLayerCount; ++l) {
    s.absorbedByLayer[l] = meanOfScores(b.absorbed[l], b.absorbedSquaresByLayer[l], b.rays);
    absorbed += b.absorbed[l];
  }
  s.absorbed = meanOfScores(absorbed, b.absorbedSquares, b.rays);
  // The exit-weighted mean radius: a ratio estimate over the effective number of exits.
  const double effectiveExits =
      b.subsurfaceSquares > 0 ? b.subsurface * b.subsurface / b.subsurfaceSquares : 0.0;
  if (effectiveExits > 1) {
    const double mean = b.radiusSumCm / b.subsurface;
    const double variance = std::max(0.0, b.radiusSquaresSumCm2 / b.subsurface - mean * mean);
    s.meanExitRadiusCm = {mean, std::sqrt(variance / (effectiveExits - 1))};
  }
  return s;
}

std::vector<double> ExitTable::radialDistribution(int k) const {
  const Bin& b = bins_.at(static_cast<std::size_t>(k));
  const std::size_t A = static_cast<std::size_t>(settings_.offsetAzimuthBins);
  std::vector<double> radial(b.offsetWeights.size() / A, 0);
  for (std::size_t i = 0; i < b.offsetWeights.size(); ++i) radial[i / A] += b.offsetWeights[i];
  return fractions(radial);
}

std::vector<double> ExitTable::offsetAzimuthDistribution(int k) const {
  const Bin& b = bins_.at(static_cast<std::size_t>(k));
  const std::size_t A = static_cast<std::size_t>(settings_.offsetAzimuthBins);
  std::vector<double> azimuth(A, 0);
  for (std::size_t i = 0; i < b.offsetWeights.size(); ++i) azimuth[i % A] += b.offsetWeights[i];
  return fractions(azimuth);
}

std::vector<double> ExitTable::exitPolarDistribution(int k) const {
  return fractions(bins_.at(static_cast<std::size_t>(k)).exitPolarWeights);
}

}  // namespace hylios::skin
