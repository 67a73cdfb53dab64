// The user's cache of HyLIoS exit tables (skin/exit_table.h) on disk, shared by `hylios render`,
// `figure` and `spectrum` in the `table` skin mode.
//
// Folder: $HYLIOS_CACHE_DIR, else $XDG_CACHE_HOME/hylios, else $HOME/.cache/hylios, created when
// needed. A table lives in "<folder>/exit-<key in 16 hex digits>.hxt"; get() reads it, verifies
// it (magic, version, key, size, checksum, consistent counts) and otherwise builds the table and
// writes it atomically, so a truncated, corrupt, stale or foreign file is rebuilt. When the folder
// cannot be created or written, tables are built in memory and one warning is printed.
// A bundle's tables (ExitTable::buildBundle, built together from spectral walks) are one file per
// member; getBundle loads them when every member is intact and otherwise builds the bundle again,
// its lock taken on the first member's file.
// Thread-safe: tables for different keys are built in parallel; tables already obtained are
// kept in memory for the life of the cache object. Across processes (and cache objects) a table
// is built once: its builder holds an exclusive lock (flock) on "<table file>.lock" while it looks
// for, builds and writes the table, so a second render sharing the cache waits and then reads it.
#pragma once
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "skin/exit_table.h"
#include "skin/skin_walk.h"

namespace hylios {

class ExitTableCache {
 public:
  /// `folder` empty: memory only (nothing read or written).
  explicit ExitTableCache(std::filesystem::path folder);

  /// The folder from the environment (see above); empty when neither HYLIOS_CACHE_DIR,
  /// XDG_CACHE_HOME nor HOME is set.
  static std::filesystem::path userFolder();
  /// The process-wide cache in userFolder(), made on first use.
  static ExitTableCache& shared();

  /// The table of `walk` with `settings`: from memory, from disk, or built (and written).
  std::shared_ptr<const skin::ExitTable> get(const skin::SkinWalk& walk,
                                             const skin::ExitTableSettings& settings);
  /// The tables of a bundle's walks built from one set of spectral walks (ExitTable::buildBundle),
  /// in the bundle's order: from memory or disk when every member is there, otherwise all built.
  std::vector<std::shared_ptr<const skin::ExitTable>> getBundle(
      const std::vector<const skin::SkinWalk*>& bundle, const skin::ExitTableSettings& settings);

  const std::filesystem::path& folder() const { return folder_; }
  std::filesystem::path fileFor(std::uint64_t key) const;
  std::size_t loaded() const { return loaded_; }      ///< tables read from disk
  std::size_t built() const { return built_; }        ///< tables built by walks
  std::size_t rejected() const { return rejected_; }  ///< files found but invalid (then rebuilt)

  /// Exit tables being built in this process now (async-signal-safe to read: a lock-free atomic),
  /// so that an interrupt handler can say that it finishes the table first.
  static int buildsInProgress();
  /// Counts one build in progress while alive.
  class BuildInProgress {
   public:
    BuildInProgress();
    ~BuildInProgress();
    BuildInProgress(const BuildInProgress&) = delete;
    BuildInProgress& operator=(const BuildInProgress&) = delete;
  };

 private:
  using ReadMember = std::function<std::optional<skin::ExitTable>(std::size_t member,
                                                                  const std::filesystem::path&)>;
  using BuildAll = std::function<std::vector<skin::ExitTable>()>;
  /// The tables of `keys`: from memory, else from disk, else all of them from build().
  std::vector<std::shared_ptr<const skin::ExitTable>> obtain(const std::vector<std::uint64_t>& keys,
                                                             const ReadMember& read,
                                                             const BuildAll& build);
  void writeQuietly(const skin::ExitTable& table, const std::filesystem::path& file);
  bool folderUsable();

  std::filesystem::path folder_;
  std::mutex mutex_;
  std::map<std::uint64_t, std::shared_ptr<const skin::ExitTable>> tables_;
  std::set<std::uint64_t>
      claimed_;  ///< keys whose file lock a thread of this object holds or awaits
  std::atomic<std::size_t> loaded_{0}, built_{0}, rejected_{0};
  std::once_flag folderChecked_, warned_;
  bool usable_ = false;
};

}  // namespace hylios
