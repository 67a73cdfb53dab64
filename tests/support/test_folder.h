// A folder of its own for the running GoogleTest test: temp/<prefix><pid>_<test name>, emptied
// when made, so tests run in parallel (CTest runs each test as its own process) never share one.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace hylios::test {

/// temp/<prefix><pid>_<name of the running test>, removed if it exists and made again, empty.
inline std::filesystem::path freshTestFolder(const std::string& prefix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       (prefix + std::to_string(::getpid()) + "_" + info->name());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace hylios::test
