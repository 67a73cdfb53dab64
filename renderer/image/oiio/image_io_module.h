// The table of functions the image-file module (libhylios_image_io, built from this folder and
// linked with OpenImageIO) hands to renderer/image/image_file.cpp, which loads it on first use.
// Both sides are built by the same compiler from this header; kImageIoModuleAbi changes with it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/image/image_file.h"

namespace hylios {

inline constexpr std::uint32_t kImageIoModuleAbi = 1;

/// Each function reports failure through its return value and `error`, never by throwing (an
/// exception would cross the module boundary).
struct ImageIoModule {
  std::uint32_t abi = kImageIoModuleAbi;
  std::uint32_t size = sizeof(ImageIoModule);
  bool (*read)(const std::string& path, StoredImage& image, std::string& error);
  bool (*write)(const std::string& path, ImageFileFormat format, const ImageToWrite& image,
                const std::vector<ImageAttribute>& attributes, std::string& error);
  int (*textWidth)(const std::string& text, int fontSizePx, const std::string& font);
  bool (*drawText)(float* rgb, int width, int height, int x, int baselineY, const std::string& text,
                   int fontSizePx, const std::string& font, int anchor);
};

}  // namespace hylios

/// The module's one exported symbol.
extern "C" const hylios::ImageIoModule* hyliosImageIoModule();
