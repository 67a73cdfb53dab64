#include "renderer/tracing/exit_table_cache.h"

#include <sys/file.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <iostream>
#include <optional>
#include <system_error>
#include <unistd.h>

#include "skin/core/content_hash.h"

namespace hylios {

namespace {

std::atomic<int> buildsNow{0};
static_assert(std::atomic<int>::is_always_lock_free, "read by signal handlers");

/// An exclusive flock on `path` (created if missing) for the life of the object; no lock (and no
/// error) when the file cannot be opened, so that a read-only cache still works.
class FileLock {
 public:
  explicit FileLock(const std::filesystem::path& path)
      : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) return;
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {}
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

int ExitTableCache::buildsInProgress() { return buildsNow.load(std::memory_order_relaxed); }
ExitTableCache::BuildInProgress::BuildInProgress() { buildsNow.fetch_add(1); }
ExitTableCache::BuildInProgress::~BuildInProgress() { buildsNow.fetch_sub(1); }

ExitTableCache::ExitTableCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path ExitTableCache::userFolder() {
  auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
  };
  if (const std::string dir = env("HYLIOS_CACHE_DIR"); !dir.empty()) return dir;
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty())
    return std::filesystem::path(xdg) / "hylios";
  if (const std::string home = env("HOME"); !home.empty())
    return std::filesystem::path(home) / ".cache" / "hylios";
  return {};
}

ExitTableCache& ExitTableCache::shared() {
  static ExitTableCache cache(userFolder());
  return cache;
}

std::filesystem::path ExitTableCache::fileFor(std::uint64_t key) const {
  return folder_ / ("exit-" + skin::hex64(key) + ".hxt");
}

bool ExitTableCache::folderUsable() {
  std::call_once(folderChecked_, [this] {
    if (folder_.empty()) return;
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    usable_ = !error && std::filesystem::is_directory(folder_, error);
    if (!usable_)
      std::call_once(warned_, [&] {
        std::cerr << "warning: exit-table cache folder '" << folder_.string()
                  << "' cannot be created (" << error.message()
                  << "); tables are built in memory only\n";
      });
  });
  return usable_;
}

std::shared_ptr<const skin::ExitTable> ExitTableCache::get(
    const skin::SkinWalk& walk, const skin::ExitTableSettings& settings) {
  const std::uint64_t key = skin::ExitTable::key(walk.optics(), walk.options(), settings);
  return obtain(
      {key},
      [&](std::size_t, const std::filesystem::path& file) {
        return skin::ExitTable::read(file, walk, settings);
      },
      [&] { return std::vector<skin::ExitTable>{skin::ExitTable::build(walk, settings)}; })[0];
}

std::vector<std::shared_ptr<const skin::ExitTable>> ExitTableCache::getBundle(
    const std::vector<const skin::SkinWalk*>& bundle, const skin::ExitTableSettings& settings) {
  std::vector<std::uint64_t> keys;
  for (std::size_t m = 0; m < bundle.size(); ++m)
    keys.push_back(skin::ExitTable::bundleKey(bundle, m, settings));
  return obtain(
      keys,
      [&](std::size_t member, const std::filesystem::path& file) {
        return skin::ExitTable::readBundleMember(file, bundle, member, settings);
      },
      [&] { return skin::ExitTable::buildBundle(bundle, settings); });
}

std::vector<std::shared_ptr<const skin::ExitTable>> ExitTableCache::obtain(
    const std::vector<std::uint64_t>& keys, const ReadMember& read, const BuildAll& build) {
  std::vector<std::shared_ptr<const skin::ExitTable>> tables(keys.size());
  auto fromMemory = [&] {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t m = 0; m < keys.size(); ++m)
      if (auto found = tables_.find(keys[m]); found != tables_.end()) tables[m] = found->second;
    return std::all_of(tables.begin(), tables.end(), [](const auto& t) { return t != nullptr; });
  };
  if (fromMemory()) return tables;
  const bool onDisk = folderUsable();
  // One builder per table (or bundle: its first key) across processes: the first request of a key
  // in this process takes the file lock (waiting for another process that builds it). A second
  // request of the same key in this process does not wait (it may run nested on the first one's
  // own thread, inside the build's parallel loop, and would deadlock) but builds the table itself.
  std::optional<FileLock> claim;
  bool claimedHere = false;
  bool complete = false;
  if (onDisk) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      claimedHere = claimed_.insert(keys[0]).second;
    }
    std::filesystem::path lockFile = fileFor(keys[0]);
    lockFile += ".lock";
    if (claimedHere) claim.emplace(lockFile);
    complete = true;
    for (std::size_t m = 0; m < keys.size(); ++m) {
      if (tables[m]) continue;
      const std::filesystem::path file = fileFor(keys[m]);
      std::error_code error;
      std::optional<skin::ExitTable> found;
      if (std::filesystem::exists(file, error)) {
        found = read(m, file);
        if (!found) ++rejected_;
      }
      if (found) {
        tables[m] = std::make_shared<const skin::ExitTable>(std::move(*found));
        ++loaded_;
      } else {
        complete = false;
      }
    }
  }
  if (!complete) {
    const BuildInProgress building;
    std::vector<skin::ExitTable> built = build();
    for (std::size_t m = 0; m < keys.size(); ++m) {
      tables[m] = std::make_shared<const skin::ExitTable>(std::move(built[m]));
      ++built_;
      if (onDisk) writeQuietly(*tables[m], fileFor(keys[m]));
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (claimedHere) claimed_.erase(keys[0]);
  for (std::size_t m = 0; m < keys.size(); ++m)
    tables[m] = tables_.emplace(keys[m], tables[m]).first->second;
  return tables;
}

void ExitTableCache::writeQuietly(const skin::ExitTable& table, const std::filesystem::path& file) {
  try {
    table.write(file);
  } catch (const std::exception& e) {
    std::call_once(warned_, [&] {
      std::cerr << "warning: " << e.what() << "; exit tables are kept in memory only\n";
    });
  }
}

}  // namespace hylios
