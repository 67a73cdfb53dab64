#include "renderer/tracing/render_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace hylios {
namespace {

std::optional<std::uint64_t> readNumber(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;  // missing, or "max" (no limit)
  return std::stoull(text);
}

std::optional<std::uint64_t> memAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  std::uint64_t value = 0;
  while (in >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024;
  return std::nullopt;
}

}  // namespace

std::uint64_t estimateRenderBytes(const SceneDesc& scene) {
  std::uint64_t channels = 0;
  for (const BandDesc& band : scene.film.bands) channels += band.channelWavelengths().size();
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(scene.film.width) * static_cast<std::uint64_t>(scene.film.height);
  return pixels * (channels * kRenderBytesPerPixelChannel + kRenderBytesPerPixel);
}

std::optional<std::uint64_t> availableMemoryBytes() {
  if (const char* budget = std::getenv("HYLIOS_MEMORY_BUDGET"); budget && *budget) {
    const std::string text = budget;
    if (text.find_first_not_of("0123456789") != std::string::npos)
      throw std::runtime_error("HYLIOS_MEMORY_BUDGET='" + text + "': expected a number of bytes");
    return std::stoull(text);
  }
  std::optional<std::uint64_t> available = memAvailable();
  // cgroup v2, then v1
  std::optional<std::uint64_t> limit = readNumber("/sys/fs/cgroup/memory.max");
  std::optional<std::uint64_t> usage = readNumber("/sys/fs/cgroup/memory.current");
  if (!limit) {
    limit = readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes");
    usage = readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes");
  }
  if (limit && *limit < (std::uint64_t{1} << 60)) {
    const std::uint64_t left = usage && *usage < *limit ? *limit - *usage : (usage ? 0 : *limit);
    available = available ? std::min(*available, left) : left;
  }
  return available;
}

void checkRenderMemory(const SceneDesc& scene) {
  const std::uint64_t need = estimateRenderBytes(scene);
  const std::optional<std::uint64_t> have = availableMemoryBytes();
  if (!have || need <= *have) return;
  std::uint64_t channels = 0;
  for (const BandDesc& band : scene.film.bands) channels += band.channelWavelengths().size();
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  throw std::runtime_error(
      fmt::format("{}: a {}x{} film with {} channels needs about {:.1f} GiB, but only {:.1f} GiB "
                  "of memory is available{}; "
                  "lower --resolution or the number of channels",
                  scene.file.string(), scene.film.width, scene.film.height, channels,
                  static_cast<double>(need) / kGiB, static_cast<double>(*have) / kGiB,
                  std::getenv("HYLIOS_MEMORY_BUDGET") ? " ($HYLIOS_MEMORY_BUDGET)" : ""));
}

}  // namespace hylios
