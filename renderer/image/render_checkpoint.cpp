#include "renderer/image/render_checkpoint.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "renderer/scene/sampler_kind.h"
#include "skin/core/atomic_file.h"
#include "skin/core/content_hash.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[] = "hylios render checkpoint\n";
constexpr std::size_t kMagicSize = sizeof kMagic - 1;
// 2: odd-sample sums and counts (the noise estimate); 3: the pixel sampler's name; 4: the second
// half is the odd blocks of four samples, not the odd samples (pixel_sampler.h), and sample s is
// another point of its half's sequence, so a version-3 film cannot go on
constexpr std::uint32_t kVersion = 4;

/// Appends little-endian values to a byte buffer.
class ByteWriter {
 public:
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    put(bits, 8);
  }
  void bytes(const std::string& text) {
    u64(text.size());
    data_ += text;
  }
  void raw(const char* text, std::size_t size) { data_.append(text, size); }
  std::string& data() { return data_; }

 private:
  void put(std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) data_.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  }
  std::string data_;
};

/// Reads little-endian values from a byte buffer; throws on reading past its end.
class ByteReader {
 public:
  ByteReader(const std::string& data, std::size_t begin, std::size_t end, std::string file)
      : data_(data), at_(begin), end_(end), file_(std::move(file)) {}
  std::uint32_t u32() { return static_cast<std::uint32_t>(get(4)); }
  std::uint64_t u64() { return get(8); }
  double f64() {
    const std::uint64_t bits = get(8);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  std::string bytes() {
    const std::uint64_t size = u64();
    need(size, "a text field");
    std::string text = data_.substr(at_, static_cast<std::size_t>(size));
    at_ += static_cast<std::size_t>(size);
    return text;
  }
  std::size_t left() const { return end_ - at_; }
  /// Throws unless `bytes` bytes remain.
  void need(std::uint64_t bytes, const char* what) const {
    if (bytes > left()) fail(std::string("it ends inside ") + what);
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error("render checkpoint '" + file_ + "' is corrupt: " + why);
  }

 private:
  std::uint64_t get(int size) {
    need(static_cast<std::uint64_t>(size), "a number");
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
      v |= static_cast<std::uint64_t>(static_cast<unsigned char>(data_[at_ + i])) << (8 * i);
    at_ += static_cast<std::size_t>(size);
    return v;
  }
  const std::string& data_;
  std::size_t at_, end_;
  std::string file_;
};

std::string readWholeFile(const fs::path& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read " + std::string(what) + " '" + path.string() + "'");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    throw std::runtime_error("failed reading " + std::string(what) + " '" + path.string() + "'");
  return data;
}

std::string wavelengthList(const std::vector<double>& nm) {
  std::ostringstream text;
  text.precision(17);
  for (std::size_t i = 0; i < nm.size() && i < 4; ++i) text << (i ? ", " : "") << nm[i];
  if (nm.size() > 4) text << ", ... (" << nm.size() << " channels)";
  return "[" + text.str() + "]";
}

}  // namespace

RenderIdentity renderIdentity(const SceneDesc& scene, const std::string& options) {
  RenderIdentity identity;
  const std::string contents =
      scene.file.empty() ? std::string() : readWholeFile(scene.file, "scene file");
  identity.sceneContentHash = skin::fnv1a64(contents.data(), contents.size());
  identity.options = options;
  identity.seed = scene.integrator.seed;
  identity.width = scene.film.width;
  identity.height = scene.film.height;
  identity.samplesPerPixelTarget = scene.film.samplesPerPixel;
  for (const BandDesc& band : scene.film.bands)
    for (const double nm : band.channelWavelengths()) identity.channelWavelengthsNm.push_back(nm);
  identity.sampler = std::string(enumName(scene.integrator.sampler, kSamplerNames));
  return identity;
}

std::vector<std::string> identityDifferences(const RenderIdentity& saved,
                                             const RenderIdentity& current) {
  std::vector<std::string> differences;
  auto compare = [&](bool same, const std::string& what, const std::string& then,
                     const std::string& now) {
    if (!same) differences.push_back(what + ": checkpoint " + then + ", this run " + now);
  };
  compare(saved.sceneContentHash == current.sceneContentHash, "scene file contents",
          "hash " + skin::hex64(saved.sceneContentHash),
          "hash " + skin::hex64(current.sceneContentHash));
  compare(saved.options == current.options, "options", "'" + saved.options + "'",
          "'" + current.options + "'");
  compare(saved.seed == current.seed, "seed", std::to_string(saved.seed),
          std::to_string(current.seed));
  compare(saved.width == current.width && saved.height == current.height, "resolution",
          std::to_string(saved.width) + "x" + std::to_string(saved.height),
          std::to_string(current.width) + "x" + std::to_string(current.height));
  compare(saved.samplesPerPixelTarget == current.samplesPerPixelTarget, "spp target",
          std::to_string(saved.samplesPerPixelTarget),
          std::to_string(current.samplesPerPixelTarget));
  compare(saved.channelWavelengthsNm == current.channelWavelengthsNm, "channel wavelengths (nm)",
          wavelengthList(saved.channelWavelengthsNm), wavelengthList(current.channelWavelengthsNm));
  compare(saved.sampler == current.sampler, "sampler", saved.sampler, current.sampler);
  return differences;
}

fs::path checkpointPathFor(const fs::path& exrPath) {
  fs::path path = exrPath;
  path += ".hylios-state";
  return path;
}

void writeRenderCheckpoint(const fs::path& path, const RenderIdentity& identity, const Film& film) {
  ByteWriter out;
  out.raw(kMagic, kMagicSize);
  out.u32(kVersion);
  out.u64(identity.sceneContentHash);
  out.bytes(identity.options);
  out.u64(identity.seed);
  out.u32(static_cast<std::uint32_t>(identity.width));
  out.u32(static_cast<std::uint32_t>(identity.height));
  out.u32(static_cast<std::uint32_t>(identity.samplesPerPixelTarget));
  out.u64(identity.channelWavelengthsNm.size());
  for (const double nm : identity.channelWavelengthsNm) out.f64(nm);
  out.bytes(identity.sampler);
  out.u32(static_cast<std::uint32_t>(film.samplesPerPixelDone()));
  out.u64(film.sums().size());
  out.data().reserve(out.data().size() + film.sums().size() * 24 + 8);
  for (const double sum : film.sums()) out.f64(sum);
  for (const std::uint32_t count : film.counts()) out.u32(count);
  for (const double sum : film.secondHalfSums()) out.f64(sum);
  for (const std::uint32_t count : film.secondHalfCounts()) out.u32(count);
  out.u64(skin::fnv1a64(out.data().data(), out.data().size()));
  writeAtomically(path, [&](const fs::path& tmp) {
    std::ofstream file(tmp, std::ios::binary);
    if (!file) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    file.write(out.data().data(), static_cast<std::streamsize>(out.data().size()));
    file.close();
    if (!file) throw std::runtime_error("failed writing '" + tmp.string() + "'");
  });
}

RenderCheckpoint readRenderCheckpoint(const fs::path& path) {
  if (!fs::exists(path))
    throw std::runtime_error("no render checkpoint '" + path.string() +
                             "' to resume from (it is written when a render is interrupted, and "
                             "removed when one completes)");
  const std::string data = readWholeFile(path, "render checkpoint");
  if (data.size() < kMagicSize || data.compare(0, kMagicSize, kMagic, kMagicSize) != 0)
    throw std::runtime_error("'" + path.string() + "' is not a hylios render checkpoint");
  ByteReader in(data, kMagicSize, data.size(), path.string());
  const std::uint32_t version = in.u32();
  if (version != kVersion)
    throw std::runtime_error("render checkpoint '" + path.string() + "' has format version " +
                             std::to_string(version) + "; this hylios reads version " +
                             std::to_string(kVersion));
  if (in.left() < 8) in.fail("it is truncated (no checksum)");
  const std::size_t bodyEnd = data.size() - 8;
  ByteReader checksum(data, bodyEnd, data.size(), path.string());
  if (checksum.u64() != skin::fnv1a64(data.data(), bodyEnd))
    in.fail("its checksum does not match its contents (truncated or damaged)");
  ByteReader body(data, kMagicSize + 4, bodyEnd, path.string());
  RenderCheckpoint checkpoint;
  RenderIdentity& id = checkpoint.identity;
  id.sceneContentHash = body.u64();
  id.options = body.bytes();
  id.seed = body.u64();
  id.width = static_cast<int>(body.u32());
  id.height = static_cast<int>(body.u32());
  id.samplesPerPixelTarget = static_cast<int>(body.u32());
  const std::uint64_t channels = body.u64();
  body.need(channels * 8, "the channel wavelengths");
  for (std::uint64_t c = 0; c < channels; ++c) id.channelWavelengthsNm.push_back(body.f64());
  id.sampler = body.bytes();
  checkpoint.samplesPerPixelDone = static_cast<int>(body.u32());
  const std::uint64_t slots = body.u64();
  if (id.width <= 0 || id.height <= 0 || id.samplesPerPixelTarget <= 0 ||
      slots !=
          static_cast<std::uint64_t>(id.width) * static_cast<std::uint64_t>(id.height) * channels)
    body.fail("its resolution, channel count and film size disagree");
  if (checkpoint.samplesPerPixelDone < 0 ||
      checkpoint.samplesPerPixelDone > id.samplesPerPixelTarget)
    body.fail("it claims " + std::to_string(checkpoint.samplesPerPixelDone) +
              " samples per pixel of " + std::to_string(id.samplesPerPixelTarget));
  if (body.left() != slots * 24) body.fail("its film data has the wrong size");
  auto readSums = [&](std::vector<double>& out) {
    out.reserve(static_cast<std::size_t>(slots));
    for (std::uint64_t s = 0; s < slots; ++s) out.push_back(body.f64());
  };
  auto readCounts = [&](std::vector<std::uint32_t>& out) {
    out.reserve(static_cast<std::size_t>(slots));
    for (std::uint64_t s = 0; s < slots; ++s) out.push_back(body.u32());
  };
  readSums(checkpoint.sums);
  readCounts(checkpoint.counts);
  readSums(checkpoint.secondHalfSums);
  readCounts(checkpoint.secondHalfCounts);
  return checkpoint;
}

RenderCheckpoint readMatchingCheckpoint(const fs::path& path, const RenderIdentity& current) {
  RenderCheckpoint checkpoint = readRenderCheckpoint(path);
  const std::vector<std::string> differences = identityDifferences(checkpoint.identity, current);
  if (!differences.empty()) {
    std::string text =
        "render checkpoint '" + path.string() + "' belongs to another render; it differs in:";
    for (const std::string& d : differences) text += "\n  " + d;
    text +=
        "\n(resume with the scene file and options of the interrupted run, or render without "
        "--resume)";
    throw std::runtime_error(text);
  }
  return checkpoint;
}

}  // namespace hylios
