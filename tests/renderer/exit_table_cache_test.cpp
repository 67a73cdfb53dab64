// ExitTableCache (renderer/tracing/exit_table_cache.h): folder choice from the environment, load
// instead of build on a second get, damaged or foreign files rebuilt, memory-only operation when
// the folder cannot be made.
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdlib.h>
#include <thread>
#include <vector>

#include "renderer/scene/data_paths.h"
#include "renderer/tracing/exit_table_cache.h"
#include "skin/skin_optics.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

using namespace hylios;

namespace {

std::filesystem::path freshFolder(const std::string& name) {
  const auto dir = std::filesystem::path(HYLIOS_BINARY_DIR) / "exit_table_cache_test" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

skin::SkinOptics s1Optics(double wavelengthNm) {
  static const skin::SpectralDatabase db = skin::SpectralDatabase::load(spectraDir());
  static const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  return skin::computeSkinOptics(specimen, db, wavelengthNm);
}

skin::ExitTableSettings small() {
  skin::ExitTableSettings s;
  s.cosineBins = 2;
  s.raysPerBin = 400;
  return s;
}

std::string bytesOf(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void put(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST(ExitTableCache, FolderFromTheEnvironment) {
  const char* saved[3] = {getenv("HYLIOS_CACHE_DIR"), getenv("XDG_CACHE_HOME"), getenv("HOME")};
  const std::string keep[3] = {saved[0] ? saved[0] : "", saved[1] ? saved[1] : "",
                               saved[2] ? saved[2] : ""};
  setenv("HYLIOS_CACHE_DIR", "/tmp/a", 1);
  setenv("XDG_CACHE_HOME", "/tmp/b", 1);
  setenv("HOME", "/tmp/c", 1);
  EXPECT_EQ(ExitTableCache::userFolder(), std::filesystem::path("/tmp/a"));
  unsetenv("HYLIOS_CACHE_DIR");
  EXPECT_EQ(ExitTableCache::userFolder(), std::filesystem::path("/tmp/b/hylios"));
  setenv("XDG_CACHE_HOME", "", 1);
  EXPECT_EQ(ExitTableCache::userFolder(), std::filesystem::path("/tmp/c/.cache/hylios"));
  unsetenv("XDG_CACHE_HOME");
  unsetenv("HOME");
  EXPECT_TRUE(ExitTableCache::userFolder().empty());
  const char* names[3] = {"HYLIOS_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  for (int i = 0; i < 3; ++i)
    if (saved[i]) setenv(names[i], keep[i].c_str(), 1);
}

TEST(ExitTableCache, SecondGetLoadsInsteadOfBuilding) {
  const auto folder = freshFolder("load");
  const skin::SkinWalk walk(s1Optics(500));
  std::shared_ptr<const skin::ExitTable> built, loaded;
  {
    ExitTableCache cache(folder);
    built = cache.get(walk, small());
    EXPECT_EQ(cache.built(), 1u);
    EXPECT_EQ(cache.loaded(), 0u);
    EXPECT_EQ(cache.get(walk, small()), built);  // in memory: neither read nor built again
    EXPECT_EQ(cache.built(), 1u);
    EXPECT_TRUE(std::filesystem::exists(cache.fileFor(built->key())));
  }
  ExitTableCache again(folder);
  loaded = again.get(walk, small());
  EXPECT_EQ(again.loaded(), 1u);
  EXPECT_EQ(again.built(), 0u);
  skin::Rng a(1), b(1);
  for (int i = 0; i < 500; ++i) {
    const skin::SkinPath x = built->sample({0, 0, 1}, a), y = loaded->sample({0, 0, 1}, b);
    ASSERT_EQ(x.end, y.end);
    ASSERT_EQ(x.exitOffsetYCm, y.exitOffsetYCm);
  }
  // One coefficient changed: another key, another file, built.
  skin::SkinOptics changed = walk.optics();
  changed.layers[5].muATotal_perCm *= 1.01;
  const auto other = again.get(skin::SkinWalk(changed), small());
  EXPECT_NE(other->key(), loaded->key());
  EXPECT_EQ(again.built(), 1u);
}

TEST(ExitTableCache, ABundleIsBuiltOnceAndLoadedWhole) {
  const auto folder = freshFolder("bundle");
  const std::vector<skin::SkinWalk> walks{skin::SkinWalk(s1Optics(500)),
                                          skin::SkinWalk(s1Optics(510))};
  const std::vector<const skin::SkinWalk*> bundle{&walks[0], &walks[1]};
  std::vector<std::shared_ptr<const skin::ExitTable>> built;
  {
    ExitTableCache cache(folder);
    built = cache.getBundle(bundle, small());
    ASSERT_EQ(built.size(), 2u);
    EXPECT_EQ(cache.built(), 2u);  // both members from one set of walks
    EXPECT_EQ(built[1]->bundleSize(), 2u);
    EXPECT_EQ(cache.getBundle(bundle, small())[1], built[1]);  // in memory
    EXPECT_EQ(cache.built(), 2u);
  }
  {
    ExitTableCache again(folder);
    const auto loaded = again.getBundle(bundle, small());
    EXPECT_EQ(again.loaded(), 2u);
    EXPECT_EQ(again.built(), 0u);
    EXPECT_EQ(loaded[0]->key(), built[0]->key());
  }
  // One member's file lost: the bundle is built again, whole.
  std::filesystem::remove(ExitTableCache(folder).fileFor(built[1]->key()));
  ExitTableCache third(folder);
  third.getBundle(bundle, small());
  EXPECT_EQ(third.built(), 2u);
  EXPECT_EQ(bytesOf(third.fileFor(built[1]->key())).size(),
            bytesOf(third.fileFor(built[0]->key())).size());
}

TEST(ExitTableCache, DamagedOrForeignFilesAreRebuilt) {
  const auto folder = freshFolder("damaged");
  const skin::SkinWalk walk(s1Optics(500)), otherWalk(s1Optics(600));
  std::filesystem::path file, otherFile;
  {
    ExitTableCache cache(folder);
    file = cache.fileFor(cache.get(walk, small())->key());
    otherFile = cache.fileFor(cache.get(otherWalk, small())->key());
  }
  const std::string good = bytesOf(file);
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 1);
  const std::string cases[3] = {good.substr(0, good.size() - 9), flipped, bytesOf(otherFile)};
  const char* names[3] = {"truncated", "bit flip", "another key's table"};
  for (int i = 0; i < 3; ++i) {
    put(file, cases[i]);
    ExitTableCache cache(folder);
    const auto table = cache.get(walk, small());
    EXPECT_EQ(cache.rejected(), 1u) << names[i];
    EXPECT_EQ(cache.built(), 1u) << names[i];
    EXPECT_EQ(cache.loaded(), 0u) << names[i];
    EXPECT_EQ(bytesOf(file), good) << names[i] << ": the rebuilt table is written back";
  }
}

TEST(ExitTableCache, UnusableFolderBuildsInMemory) {
  const auto base = freshFolder("blocked");
  std::filesystem::create_directories(base);
  put(base / "file", "not a folder");
  ExitTableCache cache(base / "file" / "cache");
  testing::internal::CaptureStderr();
  const auto table = cache.get(skin::SkinWalk(s1Optics(500)), small());
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(table, nullptr);
  EXPECT_EQ(cache.built(), 1u);
  EXPECT_NE(warning.find("cannot be created"), std::string::npos) << warning;
}

// Issue 13: two renders sharing a cache (two cache objects on one folder, as two processes)
// asking for the same table at once build it once; the other waits for it and reads it.
TEST(ExitTableCache, ConcurrentRequestsForOneTableBuildItOnce) {
  const auto folder = freshFolder("concurrent");
  const skin::SkinWalk walk(s1Optics(520));
  skin::ExitTableSettings settings = small();
  settings.raysPerBin = 4000;  // long enough for the two requests to overlap
  ExitTableCache first(folder), second(folder);
  std::atomic<int> ready{0};
  auto request = [&](ExitTableCache& cache) {
    ++ready;
    while (ready.load() < 2) std::this_thread::yield();
    cache.get(walk, settings);
  };
  std::thread a(request, std::ref(first)), b(request, std::ref(second));
  a.join();
  b.join();
  EXPECT_EQ(first.built() + second.built(), 1u);
  EXPECT_EQ(first.loaded() + second.loaded(), 1u);
}
