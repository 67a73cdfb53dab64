#include "skin/exit_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include "skin/core/atomic_file.h"
#include "skin/core/constants.h"
#include "skin/core/content_hash.h"

namespace hylios::skin {
namespace {

constexpr char kMagic[8] = {'H', 'Y', 'L', 'X', 'T', 'A', 'B', '1'};
constexpr std::size_t kHeaderBytes = 8 + 4 * 8;
constexpr std::uint64_t kChunkRays = 2048;
constexpr std::size_t kOutcomes =
    3 + 2 * kLayerCount;  // subsurface, transmitted, event limit, absorbed ×2
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

// Little-endian payload writer / bounded reader.
struct Writer {
  std::string bytes;
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<char>(v >> (8 * i)));
  }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
};

struct Reader {
  const std::string& bytes;
  std::size_t at = 0;
  bool ok = true;
  std::uint64_t u64() {
    if (bytes.size() - at < 8) {
      ok = false;
      return 0;
    }
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
      v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
    at += 8;
    return v;
  }
  double f64() {
    const std::uint64_t bits = u64();
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
};

std::uint64_t sum(const std::vector<std::uint64_t>& v) {
  std::uint64_t total = 0;
  for (auto x : v) total += x;
  return total;
}

std::vector<std::uint64_t> cumulative(const std::vector<std::uint64_t>& counts) {
  std::vector<std::uint64_t> cdf(counts.size());
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) cdf[i] = total += counts[i];
  return cdf;
}

/// Index i with probability counts[i]/total (cdf = cumulative counts, total = cdf.back() > 0).
std::size_t pick(const std::vector<std::uint64_t>& cdf, double u) {
  const auto target = static_cast<std::uint64_t>(u * static_cast<double>(cdf.back()));
  return static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin());
}

std::vector<double> fractions(const std::vector<std::uint64_t>& counts) {
  const double total = static_cast<double>(sum(counts));
  std::vector<double> f;
  for (auto c : counts) f.push_back(total > 0 ? static_cast<double>(c) / total : 0.0);
  return f;
}

Estimate binomial(std::uint64_t count, std::uint64_t rays) {
  const double n = static_cast<double>(rays), p = static_cast<double>(count) / n;
  return {p, std::sqrt(std::max(0.0, p - p * p) / (n - 1))};
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
    h.addDouble(m.melanosomesPerComplex).addDouble(m.mu_perCm);
  }
  h.addDouble(o.melanosomeInteriorMuA_perCm).addDouble(o.melaninRefractiveIndex);
  h.addDouble(o.meanScatteringAngleRad).addDouble(o.surfaceAspectRatio);
}

}  // namespace

std::uint64_t ExitTable::key(const SkinOptics& optics, const WalkOptions& walk,
                             const ExitTableSettings& settings) {
  ContentHash h;
  h.addString("hylios exit table").addU64(kExitTableFormatVersion);
  hashOptics(h, optics);
  h.addBool(walk.melanosomes).addBool(walk.rayleigh).addBool(walk.roughSurface);
  h.addU64(static_cast<std::uint64_t>(index(walk.deepestLayer)))
      .addDouble(walk.belowRefractiveIndex);
  h.addBool(walk.tabulatedMelanosomes);
  h.addU64(static_cast<std::uint64_t>(settings.cosineBins))
      .addU64(settings.raysPerBin)
      .addU64(settings.seed);
  h.addU64(static_cast<std::uint64_t>(settings.radialBins))
      .addU64(static_cast<std::uint64_t>(settings.offsetAzimuthBins));
  h.addU64(static_cast<std::uint64_t>(settings.polarBins)).addBool(settings.tabulatedMelanosomes);
  h.addDouble(kMinRadiusCm).addDouble(kMaxRadiusCm);
  return h.value();
}

ExitTable::ExitTable(const SkinWalk& walk, const ExitTableSettings& settings)
    : walk_(walk), settings_(settings), key_(key(walk.optics(), walk.options(), settings)) {
  validateSettings(settings);
}

ExitTable::Bin& ExitTable::newBin() { return bins_.emplace_back(emptyBin()); }

ExitTable::Bin ExitTable::emptyBin() const {
  Bin b;
  b.offsetCounts.assign(
      static_cast<std::size_t>(settings_.radialBins + 2) * settings_.offsetAzimuthBins, 0);
  b.exitPolarCounts.assign(static_cast<std::size_t>(settings_.polarBins), 0);
  b.transmittedPolarCounts.assign(static_cast<std::size_t>(settings_.polarBins), 0);
  return b;
}

void ExitTable::Bin::merge(const Bin& o) {
  rays += o.rays;
  subsurface += o.subsurface;
  transmitted += o.transmitted;
  eventLimited += o.eventLimited;
  for (std::size_t l = 0; l < kLayerCount; ++l) {
    absorbed[l] += o.absorbed[l];
    absorbedInMelanosome[l] += o.absorbedInMelanosome[l];
  }
  for (std::size_t i = 0; i < offsetCounts.size(); ++i) offsetCounts[i] += o.offsetCounts[i];
  for (std::size_t i = 0; i < exitPolarCounts.size(); ++i)
    exitPolarCounts[i] += o.exitPolarCounts[i];
  for (std::size_t i = 0; i < transmittedPolarCounts.size(); ++i)
    transmittedPolarCounts[i] += o.transmittedPolarCounts[i];
  largestRadiusCm = std::max(largestRadiusCm, o.largestRadiusCm);
  radiusSumCm += o.radiusSumCm;
  radiusSquaresSumCm2 += o.radiusSquaresSumCm2;
}

int ExitTable::radialCell(double radiusCm) const {
  if (radiusCm < kMinRadiusCm) return 0;
  if (radiusCm >= kMaxRadiusCm) return settings_.radialBins + 1;
  const double x = std::log(radiusCm / kMinRadiusCm) / std::log(kMaxRadiusCm / kMinRadiusCm) *
                   settings_.radialBins;
  return 1 + std::clamp(static_cast<int>(x), 0,
                        settings_.radialBins - 1);  // rounding at the edges only
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

/// Polar bin of a cosine in [0, 1] (uniform bins; cosine 1 goes to the last).
static std::size_t polarBin(double cosine, int bins) {
  return static_cast<std::size_t>(std::clamp(static_cast<int>(cosine * bins), 0, bins - 1));
}

void ExitTable::tally(Bin& bin, const SkinPath& path) const {
  ++bin.rays;
  switch (path.end) {
    case PathEnd::SubsurfaceReflection: {
      ++bin.subsurface;
      const double r = std::hypot(path.exitOffsetXCm, path.exitOffsetYCm);
      // Entry direction has azimuth 0 (x axis): the offset's azimuth from it, folded to [0, π].
      const double phi =
          r > 0 ? std::atan2(std::fabs(path.exitOffsetYCm), path.exitOffsetXCm) : 0.0;
      const int a = std::clamp(static_cast<int>(phi / kPi * settings_.offsetAzimuthBins), 0,
                               settings_.offsetAzimuthBins - 1);
      bin.offsetCounts[static_cast<std::size_t>(radialCell(r)) * settings_.offsetAzimuthBins + a]++;
      bin.exitPolarCounts[polarBin(-path.exitDirection.z, settings_.polarBins)]++;
      bin.largestRadiusCm = std::max(bin.largestRadiusCm, r);
      bin.radiusSumCm += r;
      bin.radiusSquaresSumCm2 += r * r;
      break;
    }
    case PathEnd::Transmitted:
      ++bin.transmitted;
      bin.transmittedPolarCounts[polarBin(path.exitDirection.z, settings_.polarBins)]++;
      break;
    case PathEnd::Absorbed:
      ++bin.absorbed[index(path.layer)];
      if (path.absorbedInMelanosome) ++bin.absorbedInMelanosome[index(path.layer)];
      break;
    case PathEnd::EventLimit:
    case PathEnd::SurfaceReflection:  // traceEntered never reflects at the surface; count it as
                                      // limit
      ++bin.eventLimited;
      break;
  }
}

ExitTable ExitTable::build(const SkinWalk& walk, const ExitTableSettings& settings) {
  ExitTable table(walk, settings);
  WalkOptions buildOptions = walk.options();
  buildOptions.tabulatedMelanosomes =
      buildOptions.tabulatedMelanosomes || settings.tabulatedMelanosomes;
  const SkinWalk buildWalk(walk.optics(), buildOptions);
  const std::size_t bins = static_cast<std::size_t>(settings.cosineBins);
  const std::uint64_t chunks = (settings.raysPerBin + kChunkRays - 1) / kChunkRays;
  std::vector<Bin> partials(bins * chunks, table.emptyBin());  // per-chunk partial bins
  tbb::parallel_for(std::size_t{0}, bins * chunks, [&](std::size_t task) {
    const std::size_t k = task / chunks;
    const std::uint64_t first = (task % chunks) * kChunkRays;
    const std::uint64_t last = std::min(first + kChunkRays, settings.raysPerBin);
    const double mu = table.binCosine(static_cast<int>(k));
    const Vec3 direction{std::sqrt(1 - mu * mu), 0, mu};
    Bin& partial = partials[task];
    for (std::uint64_t i = first; i < last; ++i) {
      Rng rng(settings.seed, k, i);
      table.tally(partial, buildWalk.traceEntered(direction, rng));
    }
  });
  for (std::size_t k = 0; k < bins; ++k) {
    Bin& b = table.newBin();
    for (std::uint64_t c = 0; c < chunks; ++c) b.merge(partials[k * chunks + c]);
  }
  table.prepareSampling();
  return table;
}

void ExitTable::prepareSampling() {
  for (Bin& b : bins_) {
    std::vector<std::uint64_t> outcomes(kOutcomes, 0);
    outcomes[0] = b.subsurface;
    outcomes[1] = b.transmitted;
    outcomes[2] = b.eventLimited;
    for (std::size_t l = 0; l < kLayerCount; ++l) {
      outcomes[kOutcomeAbsorbed + l] = b.absorbed[l] - b.absorbedInMelanosome[l];
      outcomes[kOutcomeMelanosome + l] = b.absorbedInMelanosome[l];
    }
    b.outcomeCdf = cumulative(outcomes);
    b.offsetCdf = cumulative(b.offsetCounts);
    b.exitPolarCdf = cumulative(b.exitPolarCounts);
    b.transmittedPolarCdf = cumulative(b.transmittedPolarCounts);
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
  const int bins = settings_.cosineBins;
  const double x = std::clamp(transmitted.z, 0.0, 1.0) * bins - 1;  // centres at (k + 1)/K
  int k = 0;
  const double u = rng.uniform();
  if (x >= bins - 1) {
    k = bins - 1;
  } else if (x > 0) {
    k = static_cast<int>(x);
    if (u < x - k) ++k;  // linear interpolation between the centres k and k + 1
  }
  return sampleBin(bins_[static_cast<std::size_t>(k)], transmitted, rng);
}

SkinPath ExitTable::sampleBin(const Bin& bin, const Vec3& transmitted, Rng& rng) const {
  SkinPath path;
  path.events = 1;
  const std::size_t outcome = pick(bin.outcomeCdf, rng.uniform());
  auto polarDirection = [&](const std::vector<std::uint64_t>& cdf, double zSign) {
    const double cosine =
        (static_cast<double>(pick(cdf, rng.uniform())) + rng.uniform()) / settings_.polarBins;
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
  const std::size_t cell = pick(bin.offsetCdf, rng.uniform());
  const int radial = static_cast<int>(cell / A);
  const double v = rng.uniform();
  double r;
  const int binIndex = static_cast<int>(&bin - bins_.data());
  const double lo = radialCellLowerCm(radial), hi = radialCellUpperCm(binIndex, radial);
  if (radial == 0)
    r = hi * std::sqrt(v);  // uniform in area
  else if (radial > settings_.radialBins)
    r = lo + v * (hi - lo);  // overflow: uniform
  else
    r = lo * std::pow(hi / lo, v);  // log-uniform
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
  s.subsurface = binomial(b.subsurface, b.rays);
  s.transmitted = binomial(b.transmitted, b.rays);
  s.eventLimited = binomial(b.eventLimited, b.rays);
  std::uint64_t absorbed = 0;
  for (std::size_t l = 0; l < kLayerCount; ++l) {
    s.absorbedByLayer[l] = binomial(b.absorbed[l], b.rays);
    absorbed += b.absorbed[l];
  }
  s.absorbed = binomial(absorbed, b.rays);
  if (b.subsurface > 1) {
    const double n = static_cast<double>(b.subsurface), mean = b.radiusSumCm / n;
    const double variance = std::max(0.0, b.radiusSquaresSumCm2 / n - mean * mean);
    s.meanExitRadiusCm = {mean, std::sqrt(variance / (n - 1))};
  }
  return s;
}

std::vector<double> ExitTable::radialDistribution(int k) const {
  const Bin& b = bins_.at(static_cast<std::size_t>(k));
  const std::size_t A = static_cast<std::size_t>(settings_.offsetAzimuthBins);
  std::vector<std::uint64_t> radial(b.offsetCounts.size() / A, 0);
  for (std::size_t i = 0; i < b.offsetCounts.size(); ++i) radial[i / A] += b.offsetCounts[i];
  return fractions(radial);
}

std::vector<double> ExitTable::offsetAzimuthDistribution(int k) const {
  const Bin& b = bins_.at(static_cast<std::size_t>(k));
  const std::size_t A = static_cast<std::size_t>(settings_.offsetAzimuthBins);
  std::vector<std::uint64_t> azimuth(A, 0);
  for (std::size_t i = 0; i < b.offsetCounts.size(); ++i) azimuth[i % A] += b.offsetCounts[i];
  return fractions(azimuth);
}

std::vector<double> ExitTable::exitPolarDistribution(int k) const {
  return fractions(bins_.at(static_cast<std::size_t>(k)).exitPolarCounts);
}

// ---- serialization ----

std::string ExitTable::serializePayload() const {
  Writer w;
  w.u64(static_cast<std::uint64_t>(settings_.cosineBins));
  w.u64(settings_.raysPerBin);
  w.u64(settings_.seed);
  w.u64(static_cast<std::uint64_t>(settings_.radialBins));
  w.u64(static_cast<std::uint64_t>(settings_.offsetAzimuthBins));
  w.u64(static_cast<std::uint64_t>(settings_.polarBins));
  w.u64(settings_.tabulatedMelanosomes ? 1 : 0);
  for (const Bin& b : bins_) {
    w.u64(b.rays);
    w.u64(b.subsurface);
    w.u64(b.transmitted);
    w.u64(b.eventLimited);
    for (auto c : b.absorbed) w.u64(c);
    for (auto c : b.absorbedInMelanosome) w.u64(c);
    for (auto c : b.offsetCounts) w.u64(c);
    for (auto c : b.exitPolarCounts) w.u64(c);
    for (auto c : b.transmittedPolarCounts) w.u64(c);
    w.f64(b.largestRadiusCm);
    w.f64(b.radiusSumCm);
    w.f64(b.radiusSquaresSumCm2);
  }
  return std::move(w.bytes);
}

static std::size_t expectedPayloadBytes(const ExitTableSettings& s) {
  const std::size_t perBin = 4 + 2 * kLayerCount +
                             static_cast<std::size_t>(s.radialBins + 2) * s.offsetAzimuthBins +
                             2 * static_cast<std::size_t>(s.polarBins) + 3;
  return 8 * (7 + static_cast<std::size_t>(s.cosineBins) * perBin);
}

bool ExitTable::parsePayload(const std::string& payload, std::string* whyNot) {
  auto fail = [&](const std::string& why) {
    if (whyNot) *whyNot = why;
    return false;
  };
  Reader r{payload};
  const ExitTableSettings& s = settings_;
  if (r.u64() != static_cast<std::uint64_t>(s.cosineBins) || r.u64() != s.raysPerBin ||
      r.u64() != s.seed || r.u64() != static_cast<std::uint64_t>(s.radialBins) ||
      r.u64() != static_cast<std::uint64_t>(s.offsetAzimuthBins) ||
      r.u64() != static_cast<std::uint64_t>(s.polarBins) ||
      r.u64() != (s.tabulatedMelanosomes ? 1u : 0u))
    return fail("settings differ from the requested ones");
  bins_.clear();
  for (int k = 0; k < s.cosineBins; ++k) {
    Bin& b = newBin();
    b.rays = r.u64();
    b.subsurface = r.u64();
    b.transmitted = r.u64();
    b.eventLimited = r.u64();
    for (auto& c : b.absorbed) c = r.u64();
    for (auto& c : b.absorbedInMelanosome) c = r.u64();
    for (auto& c : b.offsetCounts) c = r.u64();
    for (auto& c : b.exitPolarCounts) c = r.u64();
    for (auto& c : b.transmittedPolarCounts) c = r.u64();
    b.largestRadiusCm = r.f64();
    b.radiusSumCm = r.f64();
    b.radiusSquaresSumCm2 = r.f64();
    if (!r.ok) return fail("payload ends early");
    // Consistency (sums are bounded by rays ≤ 2^32 per bin, so no overflow below).
    if (b.rays != s.raysPerBin) return fail("bin ray count differs");
    std::uint64_t ends = b.subsurface + b.transmitted + b.eventLimited;
    for (std::size_t l = 0; l < kLayerCount; ++l) {
      if (b.absorbed[l] > b.rays || b.absorbedInMelanosome[l] > b.absorbed[l])
        return fail("absorption counts inconsistent");
      ends += b.absorbed[l];
    }
    if (b.subsurface > b.rays || b.transmitted > b.rays || ends != b.rays)
      return fail("outcome counts do not add up");
    for (const auto* v : {&b.offsetCounts, &b.exitPolarCounts, &b.transmittedPolarCounts})
      for (auto c : *v)
        if (c > b.rays) return fail("histogram count exceeds the rays");
    if (sum(b.offsetCounts) != b.subsurface || sum(b.exitPolarCounts) != b.subsurface ||
        sum(b.transmittedPolarCounts) != b.transmitted)
      return fail("histograms do not add up");
    if (!(std::isfinite(b.largestRadiusCm) && b.largestRadiusCm >= 0 &&
          std::isfinite(b.radiusSumCm) && b.radiusSumCm >= 0 &&
          std::isfinite(b.radiusSquaresSumCm2) && b.radiusSquaresSumCm2 >= 0))
      return fail("radius sums are not finite and non-negative");
    for (std::size_t a = 0; a < static_cast<std::size_t>(s.offsetAzimuthBins); ++a)
      if (b.offsetCounts[static_cast<std::size_t>(s.radialBins + 1) * s.offsetAzimuthBins + a] >
              0 &&
          !(b.largestRadiusCm >= kMaxRadiusCm))
        return fail("overflow radii without a largest radius");
  }
  if (r.at != payload.size()) return fail("payload has trailing bytes");
  prepareSampling();
  return true;
}

void ExitTable::write(const std::filesystem::path& path) const {
  const std::string payload = serializePayload();
  Writer header;
  header.bytes.assign(kMagic, kMagic + 8);
  header.u64(kExitTableFormatVersion);
  header.u64(key_);
  header.u64(payload.size());
  header.u64(fnv1a64(payload.data(), payload.size()));
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(header.bytes.data(), static_cast<std::streamsize>(header.bytes.size()));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    out.close();
    if (!out) throw std::runtime_error("exit table: cannot write '" + tmp.string() + "'");
  });
}

std::optional<ExitTable> ExitTable::read(const std::filesystem::path& path, const SkinWalk& walk,
                                         const ExitTableSettings& settings, std::string* whyNot) {
  auto fail = [&](const std::string& why) -> std::optional<ExitTable> {
    if (whyNot) *whyNot = why;
    return std::nullopt;
  };
  try {
    ExitTable table(walk, settings);
    const std::size_t payloadBytes = expectedPayloadBytes(settings);
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail("cannot open '" + path.string() + "'");
    std::string header(kHeaderBytes, '\0');
    if (!in.read(header.data(), static_cast<std::streamsize>(header.size())))
      return fail("header truncated");
    if (std::memcmp(header.data(), kMagic, 8) != 0) return fail("not an exit table (magic)");
    const std::string fields = header.substr(8);
    Reader h{fields};
    const std::uint64_t version = h.u64(), fileKey = h.u64(), size = h.u64(), checksum = h.u64();
    if (version != kExitTableFormatVersion)
      return fail("format version " + std::to_string(version));
    if (fileKey != table.key_)
      return fail("key " + hex64(fileKey) + " differs from " + hex64(table.key_));
    if (size != payloadBytes)
      return fail("payload size " + std::to_string(size) + " differs from the expected " +
                  std::to_string(payloadBytes));
    std::string payload(payloadBytes, '\0');
    if (!in.read(payload.data(), static_cast<std::streamsize>(payload.size())))
      return fail("payload truncated");
    if (in.peek() != std::char_traits<char>::eof()) return fail("trailing bytes after the payload");
    if (fnv1a64(payload.data(), payload.size()) != checksum) return fail("checksum mismatch");
    if (!table.parsePayload(payload, whyNot)) return std::nullopt;
    return table;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

}  // namespace hylios::skin
