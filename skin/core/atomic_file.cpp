#include "skin/core/atomic_file.h"

#include <atomic>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace hylios {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& tmpPath)>& write) {
  // pid and a per-process counter: threads (or processes) writing the same path never share a
  // temporary file; the last rename wins with a complete file.
  static std::atomic<std::uint64_t> counter{0};
  namespace fs = std::filesystem;
  if (path.empty() || !path.has_filename())
    throw std::runtime_error("cannot write '" + path.string() + "': not a file name");
  std::error_code error;
  // A link is followed: its target is replaced (atomically), the link stays a link.
  fs::path target = path;
  if (fs::is_symlink(fs::symlink_status(path, error))) {
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
    if (error)
      throw std::runtime_error("cannot write '" + path.string() +
                               "': cannot resolve the link: " + error.message());
    target = resolved;
  }
  const fs::file_status status = fs::status(target, error);
  if (fs::is_directory(status))
    throw std::runtime_error("cannot write '" + path.string() + "': it is a folder");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    write(target);  // a character device, FIFO or socket: written in place, never replaced
    return;
  }
  fs::path tmp = target;
  tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::filesystem::rename(tmp, target, error);
  if (error) {
    std::filesystem::remove(tmp, error);
    throw std::runtime_error("cannot write '" + path.string() + "': " + error.message());
  }
}

void writeTextAtomically(const std::filesystem::path& path, const std::string& contents) {
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    out << contents;
    out.close();
    if (!out) throw std::runtime_error("failed writing '" + tmp.string() + "'");
  });
}

}  // namespace hylios
