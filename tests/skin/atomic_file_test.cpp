#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fcntl.h>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#include "skin/core/atomic_file.h"
#include "tests/support/file_bytes.h"

namespace fs = std::filesystem;

TEST(AtomicFile, WritesWholeFile) {
  const fs::path path = fs::temp_directory_path() / "hylios_atomic_ok.txt";
  hylios::writeTextAtomically(path, "hello\n");
  EXPECT_EQ(hylios::test::readBytes(path), "hello\n");
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
  EXPECT_EQ(hylios::test::readBytes(path), "old\n");
  fs::remove(path);
}

// Issue 13 row 5: a symbolic link is followed (its target replaced, the link kept), and a file
// that is not a regular file (here a FIFO, like /dev/null a character device) is written in place
// instead of being replaced by a regular file.
TEST(AtomicFile, FollowsASymlinkAndReplacesItsTarget) {
  const fs::path folder = fs::temp_directory_path() / "hylios_atomic_link";
  fs::remove_all(folder);
  fs::create_directories(folder / "real");
  const fs::path target = folder / "real" / "data.txt", link = folder / "link.txt";
  hylios::writeTextAtomically(target, "old\n");
  fs::create_symlink(target, link);
  hylios::writeTextAtomically(link, "new\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(hylios::test::readBytes(target), "new\n");
  fs::remove_all(folder);
}

TEST(AtomicFile, WritesAFifoInPlace) {
  const fs::path fifo = fs::temp_directory_path() / "hylios_atomic_fifo";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  std::string received;
  std::thread drain([&] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    char buffer[64];
    while (std::chrono::steady_clock::now() < deadline) {
      const ssize_t n = ::read(reader, buffer, sizeof buffer);
      if (n > 0) received.append(buffer, static_cast<std::size_t>(n));
      if (n == 0 && !received.empty()) break;  // the writer closed after writing
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  hylios::writeTextAtomically(fifo, "through\n");
  drain.join();
  ::close(reader);
  EXPECT_EQ(received, "through\n");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  fs::remove(fifo);
}

TEST(AtomicFile, RefusesAFolder) {
  const fs::path folder = fs::temp_directory_path() / "hylios_atomic_folder";
  fs::create_directories(folder);
  EXPECT_THROW(hylios::writeTextAtomically(folder, "x"), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(folder));
  fs::remove_all(folder);
}
