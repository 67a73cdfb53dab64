// libhylios_image_io: image files and text drawing through OpenImageIO, for
// renderer/image/image_file.cpp (which loads this module on first use; see its header).
#include "renderer/image/oiio/image_io_module.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <variant>

namespace hylios {
namespace {

bool readImage(const std::string& path, StoredImage& image, std::string& error) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    error = OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  image.width = spec.width;
  image.height = spec.height;
  image.channelNames = spec.channelnames;
  image.channelNames.resize(static_cast<std::size_t>(spec.nchannels));
  for (std::size_t c = 0; c < image.channelNames.size(); ++c)
    if (image.channelNames[c].empty()) image.channelNames[c] = "channel" + std::to_string(c);
  image.stringAttributes.clear();
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING)
      image.stringAttributes.emplace_back(p.name().string(), p.get_string());
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    error = "the image has no pixels or no channels";
    return false;
  }
  image.pixels.resize(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                      static_cast<std::size_t>(spec.nchannels));
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    error = input->geterror();
    return false;
  }
  input->close();
  return true;
}

bool writeImage(const std::string& path, ImageFileFormat format, const ImageToWrite& image,
                const std::vector<ImageAttribute>& attributes, std::string& error) {
  const bool png = format == ImageFileFormat::Png8;
  auto out = OIIO::ImageOutput::create(png ? "png" : "openexr");
  if (!out) {
    error = std::string("OpenImageIO has no ") + (png ? "PNG" : "OpenEXR") +
            " writer: " + OIIO::geterror();
    return false;
  }
  const int channels = static_cast<int>(image.channelNames->size());
  OIIO::ImageSpec spec(image.width, image.height, channels,
                       png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.channelnames = *image.channelNames;
  if (!png) spec.attribute("compression", "zip");
  for (const ImageAttribute& a : attributes) {
    if (const auto* text = std::get_if<std::string>(&a.value)) spec.attribute(a.name, *text);
    if (const auto* integer = std::get_if<int>(&a.value)) spec.attribute(a.name, *integer);
    if (const auto* real = std::get_if<float>(&a.value)) spec.attribute(a.name, *real);
  }
  if (!out->open(path, spec)) {
    error = out->geterror();
    return false;
  }
  const bool written = png ? out->write_image(OIIO::TypeDesc::UINT8, image.bytes)
                           : out->write_image(OIIO::TypeDesc::FLOAT, image.pixels);
  const bool closed = out->close();
  if (!written || !closed) {
    error = out->geterror();
    return false;
  }
  return true;
}

int textWidth(const std::string& text, int fontSizePx, const std::string& font) {
  return OIIO::ImageBufAlgo::text_size(text, fontSizePx, font).width();
}

bool drawText(float* rgb, int width, int height, int x, int baselineY, const std::string& text,
              int fontSizePx, const std::string& font, int anchor) {
  // The caller's buffer, wrapped: render_text draws into it directly.
  OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT), rgb);
  const auto alignX = anchor == 0   ? OIIO::ImageBufAlgo::TextAlignX::Left
                      : anchor == 2 ? OIIO::ImageBufAlgo::TextAlignX::Right
                                    : OIIO::ImageBufAlgo::TextAlignX::Center;
  const float white[3] = {1.0f, 1.0f, 1.0f};
  return OIIO::ImageBufAlgo::render_text(canvas, x, baselineY, text, fontSizePx, font,
                                         OIIO::cspan<float>(white, 3), alignX,
                                         OIIO::ImageBufAlgo::TextAlignY::Baseline);
}

const ImageIoModule kModule{
    kImageIoModuleAbi, sizeof(ImageIoModule), readImage, writeImage, textWidth, drawText};

}  // namespace
}  // namespace hylios

extern "C" __attribute__((visibility("default"))) const hylios::ImageIoModule*
hyliosImageIoModule() {
  return &hylios::kModule;
}
