// Image files, read and written through OpenImageIO without linking it: the library is loaded on
// first use from a module built beside the executable (renderer/image/oiio/, libhylios_image_io).
//
// OpenImageIO's Debian package links about 270 shared libraries (FFmpeg, GDAL, DCMTK, …): loading
// and relocating them cost ≈ 0.16 CPU-s and 0.2 s wall in every process that linked it, including
// the commands and the Python calls that never touch an image. Behind this header only the
// processes that read or write an image pay that, once, when they first do.
//
// Where the module is looked for, in order: beside the file that holds this code (the hylios
// executable, or the Python extension), beside /proc/self/exe, then where the build put it
// (HYLIOS_IMAGE_IO_MODULE). A module that cannot be loaded is a std::runtime_error naming every
// place tried and the loader's message.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace hylios {

/// A file's pixels as float, channels interleaved: pixels[(y·width + x)·channels + c], row 0 at
/// the top; the header's string attributes by name.
struct StoredImage {
  int width = 0, height = 0;
  std::vector<std::string> channelNames;
  std::vector<float> pixels;
  std::vector<std::pair<std::string, std::string>> stringAttributes;

  /// The string attribute `name`, or "" when the file has none.
  std::string attribute(const std::string& name) const;
};

/// A header attribute to write: a string, an int or a float.
struct ImageAttribute {
  std::string name;
  std::variant<std::string, int, float> value;
};

enum class ImageFileFormat {
  Png8,      ///< 8-bit PNG, from ImageToWrite::bytes
  ExrFloat,  ///< OpenEXR, 32-bit float channels from ImageToWrite::pixels, zip compression
};

/// The pixels of an image to write (channels interleaved as in StoredImage): floats for OpenEXR,
/// bytes for PNG.
struct ImageToWrite {
  int width = 0, height = 0;
  const std::vector<std::string>* channelNames = nullptr;
  const float* pixels = nullptr;
  const unsigned char* bytes = nullptr;
};

/// Every channel of subimage 0 of `path` (any format OpenImageIO reads). Throws
/// std::runtime_error naming the file when it cannot be read or has no pixels.
StoredImage readImageFile(const std::filesystem::path& path);
/// The same without throwing for the file: false with OpenImageIO's message in `error`.
bool tryReadImageFile(const std::filesystem::path& path, StoredImage& image, std::string& error);

/// Writes `image` to `path` in `format` (the file name's extension is not consulted, so a
/// temporary name works) with `attributes` in its header. Throws std::runtime_error naming the
/// file (`namedAs` when given: the final name of an atomic write) when it cannot be written.
void writeImageFile(const std::filesystem::path& path, ImageFileFormat format,
                    const ImageToWrite& image, const std::vector<ImageAttribute>& attributes = {},
                    const std::filesystem::path& namedAs = {});

/// The module's text drawing (FreeType through OpenImageIO's render_text): width in pixels of
/// ASCII `text` at `fontSizePx` with the font file `font` ("" for OpenImageIO's default font).
int imageTextWidth(const std::string& text, int fontSizePx, const std::string& font);
/// Draws white ASCII `text` into an RGB float canvas (width × height × 3, row 0 at the top) with
/// its baseline at y; anchor 0 left, 1 centre, 2 right of x. False when nothing could be drawn.
bool drawImageText(float* rgb, int width, int height, int x, int baselineY, const std::string& text,
                   int fontSizePx, const std::string& font, int anchor);

}  // namespace hylios
