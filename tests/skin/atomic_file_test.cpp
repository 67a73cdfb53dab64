#include "skin/core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

TEST(AtomicFile, WritesWholeFile) {
  const fs::path path = fs::temp_directory_path() / "hylios_atomic_ok.txt";
  hylios::writeTextAtomically(path, "hello\n");
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "hello");
  fs::remove(path);
}

TEST(AtomicFile, FailedWriteLeavesOldFileAndNoTemporary) {
  const fs::path path = fs::temp_directory_path() / "hylios_atomic_keep.txt";
  hylios::writeTextAtomically(path, "old\n");
  fs::path seenTmp;
  EXPECT_THROW(hylios::writeAtomically(path,
                                       [&](const fs::path& tmp) {
                                         seenTmp = tmp;
                                         std::ofstream(tmp) << "half";
                                         throw std::runtime_error("disk full");
                                       }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(seenTmp));
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "old");
  fs::remove(path);
}
