// Render checkpoints: the exact state of a stopped render (app/interrupt_signal.h), saved
// beside its OpenEXR as "<out>.hylios-state" so that `hylios render --resume` can continue it to
// the very image an uninterrupted render gives.
//
// File layout (version 3; integers and doubles little-endian, doubles as IEEE-754 binary64 bits):
//   magic      25 bytes "hylios render checkpoint\n"
//   version    u32 = 3
//   identity   u64 scene content hash; u64 n + n bytes options; u64 seed; u32 width; u32 height;
//              u32 spp target; u64 channel count C + C × f64 channel wavelengths (nm);
//              u64 n + n bytes the pixel sampler's name (version 3)
//   state      u32 spp done; u64 slot count S (= width·height·C) + S × f64 radiance sums
//              + S × u32 sample counts (Film::sums()/counts() order), then the same for the
//              second half's samples alone (Film::secondHalfSums()/secondHalfCounts(); version
//              2; version 4: the half of pixel_sampler.h's inSecondFilmHalf)
//   checksum   u64 FNV-1a 64 (skin/core/content_hash.h) of every byte before it
// The state is the film's own (double sums and counts), not the EXR's float means, so the sums
// continue bit-identically.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/scene/scene.h"

namespace hylios {

/// Everything a checkpoint must agree with to be continued.
struct RenderIdentity {
  std::uint64_t sceneContentHash =
      0;  ///< FNV-1a 64 of the scene file's bytes (files it refers to are not hashed)
  std::string
      options;  ///< the image-affecting command-line options, canonical (app/render_command.cpp)
  std::uint64_t seed = 0;
  int width = 0, height = 0;
  int samplesPerPixelTarget = 0;  ///< the channel stratification depends on it
  std::vector<double> channelWavelengthsNm;
  /// The sampler the samples were drawn with ("sobol", "independent"; renderer/scene/
  /// sampler_kind.h), recorded whether it came from the scene, an option or the default.
  std::string sampler;
};

/// The identity of rendering `scene` (settings already applied): hashes the bytes of scene.file
/// (throws std::runtime_error when it cannot be read; an empty path hashes no bytes).
RenderIdentity renderIdentity(const SceneDesc& scene, const std::string& options);

/// What differs between a checkpoint's identity and this run's, one phrase each (e.g.
/// "seed: checkpoint 1, this run 2"); empty when they agree.
std::vector<std::string> identityDifferences(const RenderIdentity& saved,
                                             const RenderIdentity& current);

struct RenderCheckpoint {
  RenderIdentity identity;
  int samplesPerPixelDone = 0;
  std::vector<double> sums;
  std::vector<std::uint32_t> counts;
  std::vector<double> secondHalfSums;
  std::vector<std::uint32_t> secondHalfCounts;
};

/// "<exrPath>.hylios-state".
std::filesystem::path checkpointPathFor(const std::filesystem::path& exrPath);

/// Writes the film's state atomically (skin/core/atomic_file.h).
void writeRenderCheckpoint(const std::filesystem::path& path, const RenderIdentity& identity,
                           const Film& film);

/// Reads a checkpoint; throws std::runtime_error naming the file and what is wrong (missing,
/// not a checkpoint, another version, truncated, checksum mismatch, inconsistent sizes).
RenderCheckpoint readRenderCheckpoint(const std::filesystem::path& path);

/// readRenderCheckpoint, then throws std::runtime_error listing every identity difference.
RenderCheckpoint readMatchingCheckpoint(const std::filesystem::path& path,
                                        const RenderIdentity& current);

}  // namespace hylios
