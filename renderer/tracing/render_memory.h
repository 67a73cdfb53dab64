// What a render needs in memory, estimated before any work, and what the machine has: a render
// that would not fit is refused with a message instead of failing with std::bad_alloc hours in
// (issue 13, row 8).
#pragma once
#include <cstdint>
#include <optional>

#include "renderer/scene/scene.h"

namespace hylios {

/// Bytes per pixel and film channel: the film's sums and counts (all samples and the second half),
/// the float image written to the EXR, the checkpoint's copy, with some slack.
constexpr std::uint64_t kRenderBytesPerPixelChannel = 48;
/// Bytes per pixel besides the channels: RGB and alpha of the EXR, the previews, the coverage.
constexpr std::uint64_t kRenderBytesPerPixel = 64;

/// The estimate for `scene`'s film (geometry, spectra and exit tables are small beside it).
std::uint64_t estimateRenderBytes(const SceneDesc& scene);
/// The memory this process may still use: $HYLIOS_MEMORY_BUDGET (bytes, if set), else the lowest
/// of MemAvailable (/proc/meminfo) and the cgroup's limit less its usage; nullopt when unknown.
std::optional<std::uint64_t> availableMemoryBytes();
/// Throws std::runtime_error when the estimate exceeds the available memory.
void checkRenderMemory(const SceneDesc& scene);

}  // namespace hylios
