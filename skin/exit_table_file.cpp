// The file format of exit tables (skin/exit_table.h): writing, and reading with every check.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "skin/core/atomic_file.h"
#include "skin/core/content_hash.h"
#include "skin/exit_table.h"

namespace hylios::skin {
namespace {

constexpr char kMagic[8] = {'H', 'Y', 'L', 'X', 'T', 'A', 'B', '1'};
constexpr std::size_t kHeaderBytes = 8 + 4 * 8;
constexpr std::size_t kSettingsFields = 8;  // the seven settings and the bundle size
/// Relative rounding allowed between a histogram's sum and its outcome's weight (both sums of the
/// same path weights, added in different orders).
constexpr double kSumTolerance = 1e-9;

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

double sum(const std::vector<double>& v) {
  double total = 0;
  for (double x : v) total += x;
  return total;
}

bool sameSum(double a, double b) {
  return std::fabs(a - b) <= kSumTolerance * std::max({1.0, std::fabs(a), std::fabs(b)});
}

}  // namespace

/// Every stored double of a bin, in file order (for writing and reading alike).
template <class BinType, class Visit>
void visitStoredWeights(BinType& b, Visit&& visit) {
  visit(b.subsurface);
  visit(b.transmitted);
  visit(b.eventLimited);
  for (auto& x : b.absorbed) visit(x);
  for (auto& x : b.absorbedInMelanosome) visit(x);
  visit(b.subsurfaceSquares);
  visit(b.transmittedSquares);
  visit(b.eventLimitedSquares);
  visit(b.absorbedSquares);
  for (auto& x : b.absorbedSquaresByLayer) visit(x);
  for (auto& x : b.offsetWeights) visit(x);
  for (auto& x : b.exitPolarWeights) visit(x);
  for (auto& x : b.transmittedPolarWeights) visit(x);
  visit(b.largestRadiusCm);
  visit(b.radiusSumCm);
  visit(b.radiusSquaresSumCm2);
}

static std::size_t expectedPayloadBytes(const ExitTableSettings& s) {
  const std::size_t perBin = 1 + 3 + 2 * kLayerCount + 4 + kLayerCount +
                             static_cast<std::size_t>(s.radialBins + 2) * s.offsetAzimuthBins +
                             2 * static_cast<std::size_t>(s.polarBins) + 3;
  return 8 * (kSettingsFields + static_cast<std::size_t>(s.cosineBins) * perBin);
}

std::string ExitTable::serializePayload() const {
  Writer w;
  w.u64(static_cast<std::uint64_t>(settings_.cosineBins));
  w.u64(settings_.raysPerBin);
  w.u64(settings_.seed);
  w.u64(static_cast<std::uint64_t>(settings_.radialBins));
  w.u64(static_cast<std::uint64_t>(settings_.offsetAzimuthBins));
  w.u64(static_cast<std::uint64_t>(settings_.polarBins));
  w.u64(settings_.tabulatedMelanosomes ? 1 : 0);
  w.u64(bundleSize_);
  for (const Bin& b : bins_) {
    w.u64(b.rays);
    visitStoredWeights(b, [&](double x) { w.f64(x); });
  }
  return std::move(w.bytes);
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
  if (r.u64() != bundleSize_) return fail("built for another bundle size");
  bins_.clear();
  for (int k = 0; k < s.cosineBins; ++k) {
    Bin& b = newBin();
    b.rays = r.u64();
    bool finite = true;
    visitStoredWeights(b, [&](double& x) {
      x = r.f64();
      finite = finite && std::isfinite(x) && x >= 0;
    });
    if (!r.ok) return fail("payload ends early");
    const bool raysFit =
        s.raysByUse ? b.rays >= 2 && b.rays <= s.raysPerBin : b.rays == s.raysPerBin;
    if (!raysFit) return fail("bin ray count differs");
    if (!finite) return fail("a weight is not finite and non-negative");
    double ends = b.subsurface + b.transmitted + b.eventLimited;
    for (std::size_t l = 0; l < kLayerCount; ++l) {
      if (b.absorbedInMelanosome[l] > b.absorbed[l] * (1 + kSumTolerance))
        return fail("absorption weights inconsistent");
      ends += b.absorbed[l];
    }
    if (!(ends > 0)) return fail("a bin has no weight");
    // Analog walks: every ray is counted once (counts are exact in doubles up to 2^53).
    if (bundleSize_ == 1 && ends != static_cast<double>(b.rays))
      return fail("outcome counts do not add up");
    if (!sameSum(sum(b.offsetWeights), b.subsurface) ||
        !sameSum(sum(b.exitPolarWeights), b.subsurface) ||
        !sameSum(sum(b.transmittedPolarWeights), b.transmitted))
      return fail("histograms do not add up");
    const std::size_t overflow = static_cast<std::size_t>(s.radialBins + 1) * s.offsetAzimuthBins;
    for (std::size_t a = 0; a < static_cast<std::size_t>(s.offsetAzimuthBins); ++a)
      if (b.offsetWeights[overflow + a] > 0 && !(b.largestRadiusCm >= kMaxRadiusCm))
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
  try {
    return readWithKey(
        path, ExitTable(walk, settings, key(walk.optics(), walk.options(), settings), 1), whyNot);
  } catch (const std::exception& e) {
    if (whyNot) *whyNot = e.what();
    return std::nullopt;
  }
}

std::optional<ExitTable> ExitTable::readBundleMember(const std::filesystem::path& path,
                                                     const std::vector<const SkinWalk*>& bundle,
                                                     std::size_t member,
                                                     const ExitTableSettings& settings,
                                                     std::string* whyNot) {
  try {
    return readWithKey(
        path,
        ExitTable(*bundle.at(member), settings, bundleKey(bundle, member, settings), bundle.size()),
        whyNot);
  } catch (const std::exception& e) {
    if (whyNot) *whyNot = e.what();
    return std::nullopt;
  }
}

std::optional<ExitTable> ExitTable::readWithKey(const std::filesystem::path& path, ExitTable table,
                                                std::string* whyNot) {
  auto fail = [&](const std::string& why) -> std::optional<ExitTable> {
    if (whyNot) *whyNot = why;
    return std::nullopt;
  };
  const std::size_t payloadBytes = expectedPayloadBytes(table.settings_);
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open '" + path.string() + "'");
  std::string header(kHeaderBytes, '\0');
  if (!in.read(header.data(), static_cast<std::streamsize>(header.size())))
    return fail("header truncated");
  if (std::memcmp(header.data(), kMagic, 8) != 0) return fail("not an exit table (magic)");
  const std::string fields = header.substr(8);
  Reader h{fields};
  const std::uint64_t version = h.u64(), fileKey = h.u64(), size = h.u64(), checksum = h.u64();
  if (version != kExitTableFormatVersion) return fail("format version " + std::to_string(version));
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
}

}  // namespace hylios::skin
