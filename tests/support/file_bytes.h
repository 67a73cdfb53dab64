// A file's bytes as a string, for tests that compare outputs byte for byte ("" when the file is
// missing).
#pragma once
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hylios::test {

inline std::string readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace hylios::test
