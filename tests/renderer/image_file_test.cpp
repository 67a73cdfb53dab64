// Image files through the separately loaded OpenImageIO module (renderer/image/image_file.h): an
// OpenEXR and a PNG written and read back (pixels, names, attributes of each type), errors that
// name the file, and the executable's own dependencies (OpenImageIO is not among them).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/image/image_file.h"
#include "tests/support/test_folder.h"

namespace {

namespace fs = std::filesystem;
using hylios::ImageAttribute;
using hylios::ImageFileFormat;
using hylios::ImageToWrite;

class ImageFileTest : public ::testing::Test {
 protected:
  void SetUp() override { folder_ = hylios::test::freshTestFolder("hylios_image_file_"); }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(ImageFileTest, OpenExrKeepsFloatsNamesAndAttributes) {
  // OpenEXR keeps its channels sorted by name (OpenImageIO reads them in that order): sorted here.
  const std::vector<std::string> names{"A", "S0.365,000000nm"};
  const std::vector<float> pixels{1.0f,    0.125f, 0.0f,
                                  3.5e-7f, 1.0f,   12345.5f};  // 3 × 1, 2 channels
  ImageToWrite image;
  image.width = 3;
  image.height = 1;
  image.channelNames = &names;
  image.pixels = pixels.data();
  const fs::path path = folder_ / "a.tmp";  // no extension: the format is named, not guessed
  hylios::writeImageFile(
      path, ImageFileFormat::ExrFloat, image,
      {{"hylios:bands", std::string("uv=365")}, {"hylios:spp", 7}, {"hylios:exposure", 1.5f}});
  const hylios::StoredImage read = hylios::readImageFile(path);
  EXPECT_EQ(read.width, 3);
  EXPECT_EQ(read.height, 1);
  EXPECT_EQ(read.channelNames, names);
  EXPECT_EQ(read.pixels, pixels);  // float channels: bit for bit
  EXPECT_EQ(read.attribute("hylios:bands"), "uv=365");
  EXPECT_EQ(read.attribute("no such attribute"), "");
}

TEST_F(ImageFileTest, PngKeepsBytes) {
  const std::vector<std::string> names{"R", "G", "B"};
  const std::vector<unsigned char> bytes{0, 128, 255, 7, 64, 200};  // 1 × 2 pixels
  ImageToWrite image;
  image.width = 1;
  image.height = 2;
  image.channelNames = &names;
  image.bytes = bytes.data();
  const fs::path path = folder_ / "b.png";
  hylios::writeImageFile(path, ImageFileFormat::Png8, image);
  const hylios::StoredImage read = hylios::readImageFile(path);
  ASSERT_EQ(read.pixels.size(), bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i)
    EXPECT_FLOAT_EQ(read.pixels[i] * 255.0f, static_cast<float>(bytes[i])) << i;
}

TEST_F(ImageFileTest, ErrorsNameTheFile) {
  const fs::path missing = folder_ / "missing.exr";
  try {
    hylios::readImageFile(missing);
    FAIL() << "no error for a missing file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  hylios::StoredImage image;
  std::string error;
  EXPECT_FALSE(hylios::tryReadImageFile(missing, image, error));
  EXPECT_FALSE(error.empty());

  const std::vector<std::string> names{"R", "G", "B"};
  ImageToWrite noBytes;
  noBytes.width = noBytes.height = 1;
  noBytes.channelNames = &names;
  EXPECT_THROW(hylios::writeImageFile(folder_ / "c.png", ImageFileFormat::Png8, noBytes),
               std::invalid_argument);
  const std::vector<unsigned char> bytes{1, 2, 3};
  noBytes.bytes = bytes.data();
  const fs::path inMissingFolder = folder_ / "no_folder" / "c.png";
  try {
    hylios::writeImageFile(inMissingFolder, ImageFileFormat::Png8, noBytes, {},
                           folder_ / "final.png");
    FAIL() << "no error for a file in a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("final.png"), std::string::npos) << e.what();
  }
}

/// `ldd FILE`: the shared libraries the loader maps for it, one per line.
std::string sharedLibrariesOf(const fs::path& file) {
  const std::string command = "ldd '" + file.string() + "' 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get())) out += buffer.data();
  return out;
}

TEST(ImageFileModule, TheExecutableDoesNotLoadOpenImageIOAtStart) {
  const fs::path hylios = fs::path(HYLIOS_BINARY_DIR) / "hylios";
  ASSERT_TRUE(fs::exists(hylios)) << hylios;
  const std::string libraries = sharedLibrariesOf(hylios);
  EXPECT_NE(libraries.find("libembree3"), std::string::npos) << libraries;  // ldd worked
  EXPECT_EQ(libraries.find("OpenImageIO"), std::string::npos) << libraries;
  const fs::path module = fs::path(HYLIOS_BINARY_DIR) / "libhylios_image_io.so";
  ASSERT_TRUE(fs::exists(module)) << module;
  EXPECT_NE(sharedLibrariesOf(module).find("OpenImageIO"), std::string::npos);
}

}  // namespace
