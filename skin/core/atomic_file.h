// Output files are written whole or not at all: write to "<path>.tmp-<pid>-<n>" then rename.
// Used for every file the project writes (CSVs, images, checkpoints, exit-table caches).
#pragma once
#include <filesystem>
#include <functional>
#include <string>

namespace hylios {

/// Calls write(tmpPath) and renames tmpPath onto `path` if it returns without throwing; otherwise
/// removes tmpPath and rethrows. Throws std::runtime_error if the rename fails.
/// A symbolic link `path` is followed: its target is replaced atomically and the link kept. An
/// existing `path` that is not a regular file (a character device such as /dev/null, a FIFO) is
/// written in place: write(path) is called and nothing is renamed. A folder is refused.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& tmpPath)>& write);
/// Convenience: writes `contents` as a text file atomically.
void writeTextAtomically(const std::filesystem::path& path, const std::string& contents);

}  // namespace hylios
