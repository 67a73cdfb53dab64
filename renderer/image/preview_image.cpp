#include "renderer/image/preview_image.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "renderer/image/colour_tables.h"
#include "skin/core/atomic_file.h"

namespace hylios {
namespace {

/// The font to hand to render_text: a DejaVu Sans file when one is installed (Debian:
/// fonts-dejavu-core), else "" (OpenImageIO's own search for a default font).
std::string fontName() {
  static const std::string name = [] {
    const char* candidates[] = {
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf", "/usr/local/share/fonts/DejaVuSans.ttf"};
    for (const char* path : candidates) {
      std::error_code error;
      if (std::filesystem::is_regular_file(path, error)) return std::string(path);
    }
    return std::string();
  }();
  return name;
}

void setPixel(OIIO::ImageBuf& image, int x, int y, const std::array<double, 3>& rgb) {
  const float value[3] = {static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
                          static_cast<float>(rgb[2])};
  image.setpixel(x, y, value, 3);
}

}  // namespace

bool textRenderingAvailable() {
  static const bool available = [] {
    OIIO::ImageBuf probe = makeCanvas(64, 32);
    const bool drawn = OIIO::ImageBufAlgo::render_text(probe, 2, 24, "0.5", 16, fontName());
    if (!drawn) return false;
    // Some builds return success without FreeType; require that pixels actually changed.
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(probe);
    return !stats.max.empty() && stats.max[0] > 0.0f;
  }();
  return available;
}

std::string asciiText(const std::string& text) {
  static const std::pair<const char*, const char*> kReplacements[] = {
      {"\u2212", "-"}, {"\u2013", "-"},      {"\u2014", "-"}, {"\u00b7", "|"},
      {"\u00b2", "2"}, {"\u00b3", "3"},      {"\u00b5", "u"}, {"\u00b1", "+/-"},
      {"\u00d7", "x"}, {"\u03bb", "lambda"}, {"\u2192", "->"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (static_cast<unsigned char>(text[i]) < 0x80) {
      out += text[i++];
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : kReplacements) {
      const std::size_t n = std::char_traits<char>::length(from);
      if (text.compare(i, n, from) == 0) {
        out += to;
        i += n;
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    out += '?';  // one '?' per unknown character: skip its continuation bytes
    ++i;
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return out;
}

int fittingFontSize(const std::string& text, int widthPx, int fontSizePx, int minimumPx) {
  if (!textRenderingAvailable() || text.empty()) return fontSizePx;
  const std::string ascii = asciiText(text);
  int size = fontSizePx;
  while (size > minimumPx &&
         OIIO::ImageBufAlgo::text_size(ascii, size, fontName()).width() > widthPx)
    --size;
  return size;
}

bool drawText(OIIO::ImageBuf& canvas, int x, int baselineY, const std::string& utf8Text,
              int fontSizePx, TextAnchor anchor) {
  if (utf8Text.empty()) return true;
  if (!textRenderingAvailable()) return false;
  const std::string text = asciiText(utf8Text);
  const auto alignX = anchor == TextAnchor::Left    ? OIIO::ImageBufAlgo::TextAlignX::Left
                      : anchor == TextAnchor::Right ? OIIO::ImageBufAlgo::TextAlignX::Right
                                                    : OIIO::ImageBufAlgo::TextAlignX::Center;
  const float white[3] = {1.0f, 1.0f, 1.0f};
  return OIIO::ImageBufAlgo::render_text(canvas, x, baselineY, text, fontSizePx, fontName(),
                                         OIIO::cspan<float>(white, 3), alignX,
                                         OIIO::ImageBufAlgo::TextAlignY::Baseline);
}

OIIO::ImageBuf makeCanvas(int width, int height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("preview canvas must have a positive size, got " +
                                std::to_string(width) + "x" + std::to_string(height));
  }
  OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::zero(canvas);
  return canvas;
}

int colourBarStripHeight(int canvasWidth) {
  const int fontSize = std::clamp(canvasWidth / 20, 12, 24);
  const int gap = fontSize / 2, barHeight = fontSize, tickLength = fontSize / 3;
  return gap + barHeight + tickLength + fontSize + fontSize / 2;
}

PseudoColourPanel pseudoColourPanel(const std::vector<double>& values, int width, int height,
                                    double minValue, double maxValue, const std::string& caption) {
  if (values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("pseudoColourPanel: " + std::to_string(values.size()) +
                                " values for a " + std::to_string(width) + "x" +
                                std::to_string(height) + " image");
  }
  if (!(maxValue > minValue) || !std::isfinite(minValue) || !std::isfinite(maxValue)) {
    throw std::invalid_argument("pseudo-colour range [" + std::to_string(minValue) + ", " +
                                std::to_string(maxValue) + "] must be finite and increasing");
  }
  const int canvasWidth = std::max(width, kMinPseudoColourWidth);
  const int fontSize = std::clamp(canvasWidth / 20, 12, 24);
  const int gap = fontSize / 2, barHeight = fontSize, tickLength = fontSize / 3;
  PseudoColourPanel panel;
  panel.image = makeCanvas(canvasWidth, height + colourBarStripHeight(canvasWidth));
  const int offsetX = (canvasWidth - width) / 2;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double v = values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)];
      setPixel(panel.image, offsetX + x, y, colourMap((v - minValue) / (maxValue - minValue)));
    }
  }
  // The bar: colour map from min (left) to max (right), with ticks at both ends and the middle.
  const int margin = std::max(fontSize / 2, 4);
  const int barLeft = margin, barRight = canvasWidth - margin - 1, barTop = height + gap;
  for (int x = barLeft; x <= barRight; ++x) {
    const auto rgb = colourMap(static_cast<double>(x - barLeft) / (barRight - barLeft));
    for (int y = barTop; y < barTop + barHeight; ++y) setPixel(panel.image, x, y, rgb);
  }
  const int ticks[3] = {barLeft, (barLeft + barRight) / 2, barRight};
  for (const int x : ticks) {
    for (int y = barTop + barHeight; y < barTop + barHeight + tickLength; ++y)
      setPixel(panel.image, x, y, {1.0, 1.0, 1.0});
  }
  const int baseline = barTop + barHeight + tickLength + fontSize;
  panel.labelled = drawText(panel.image, barLeft, baseline, formatLabelNumber(minValue), fontSize,
                            TextAnchor::Left) &&
                   drawText(panel.image, barRight + 1, baseline, formatLabelNumber(maxValue),
                            fontSize, TextAnchor::Right) &&
                   drawText(panel.image, (barLeft + barRight) / 2, baseline, caption, fontSize,
                            TextAnchor::Centre);
  return panel;
}

void writePngAtomically(const OIIO::ImageBuf& image, const std::filesystem::path& path) {
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    // The temporary name has no .png extension: name the format explicitly.
    auto out = OIIO::ImageOutput::create("png");
    if (!out) throw std::runtime_error("OpenImageIO has no PNG writer: " + OIIO::geterror());
    const int width = image.spec().width, height = image.spec().height;
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
    std::vector<float> row(static_cast<std::size_t>(width) * image.nchannels());
    for (int y = 0; y < height; ++y) {
      image.get_pixels(OIIO::ROI(0, width, y, y + 1), OIIO::TypeDesc::FLOAT, row.data());
      for (int x = 0; x < width; ++x) {
        for (int c = 0; c < 3; ++c) {
          const float v = row[static_cast<std::size_t>(x) * image.nchannels() +
                              static_cast<std::size_t>(std::min(c, image.nchannels() - 1))];
          if (std::isnan(v))
            throw std::runtime_error("NaN in preview image '" + path.string() + "'");
          pixels[(static_cast<std::size_t>(y) * width + x) * 3 + c] =
              static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
        }
      }
    }
    if (!out->open(tmp.string(), spec)) {
      throw std::runtime_error("cannot write '" + path.string() + "': " + out->geterror());
    }
    const bool written = out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    const bool closed = out->close();
    if (!written || !closed) {
      throw std::runtime_error("cannot write '" + path.string() + "': " + out->geterror());
    }
  });
}

std::string formatLabelNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace hylios
