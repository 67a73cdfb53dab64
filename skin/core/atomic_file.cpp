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
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
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
