#include "renderer/tracing/exit_table_cache.h"

#include <cstdlib>
#include <iostream>
#include <system_error>

#include "skin/core/content_hash.h"

namespace hylios {

ExitTableCache::ExitTableCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path ExitTableCache::userFolder() {
  auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
  };
  if (const std::string dir = env("HYLIOS_CACHE_DIR"); !dir.empty()) return dir;
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) return std::filesystem::path(xdg) / "hylios";
  if (const std::string home = env("HOME"); !home.empty()) return std::filesystem::path(home) / ".cache" / "hylios";
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
        std::cerr << "warning: exit-table cache folder '" << folder_.string() << "' cannot be created ("
                  << error.message() << "); tables are built in memory only\n";
      });
  });
  return usable_;
}

std::shared_ptr<const skin::ExitTable> ExitTableCache::get(const skin::SkinWalk& walk,
                                                           const skin::ExitTableSettings& settings) {
  const std::uint64_t key = skin::ExitTable::key(walk.optics(), walk.options(), settings);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto found = tables_.find(key); found != tables_.end()) return found->second;
  }
  std::shared_ptr<const skin::ExitTable> table;
  const bool onDisk = folderUsable();
  if (onDisk) {
    const std::filesystem::path file = fileFor(key);
    std::error_code error;
    if (std::filesystem::exists(file, error)) {
      if (auto read = skin::ExitTable::read(file, walk, settings)) {
        table = std::make_shared<const skin::ExitTable>(std::move(*read));
        ++loaded_;
      } else {
        ++rejected_;
      }
    }
  }
  if (!table) {
    table = std::make_shared<const skin::ExitTable>(skin::ExitTable::build(walk, settings));
    ++built_;
    if (onDisk) {
      try {
        table->write(fileFor(key));
      } catch (const std::exception& e) {
        std::call_once(warned_, [&] { std::cerr << "warning: " << e.what() << "; exit tables are kept in memory only\n"; });
      }
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  return tables_.emplace(key, table).first->second;
}

}  // namespace hylios
